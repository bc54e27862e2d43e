#include "semslam/study/LogPerturbation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "semslam/models/Sampling.h"

namespace semslam {

namespace {

int poseDimension(const Pose& pose) { return std::holds_alternative<SE2>(pose) ? 2 : 3; }

}  // namespace

Matrix addedOdometryCovariance(int dimension, double scale, double dt, const OdometryNoiseBaseline& baseline) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("odometry noise: dimension must be 2 or 3");
  const double sx = scale * baseline.sigmaX, sy = scale * baseline.sigmaY, st = scale * baseline.sigmaTheta;
  Vector variances;
  if (dimension == 2) {
    variances = Vector3(sx * sx, sy * sy, st * st);
  } else {
    variances.resize(6);
    variances << sx * sx, sy * sy, sx * sx, st * st, st * st, st * st;
  }
  return Matrix((variances * dt).asDiagonal());
}

std::vector<double> stepDurations(const MeasurementLog& log) {
  std::vector<double> durations(log.steps.size(), 0.0);
  bool allEqual = true;
  for (std::size_t k = 1; k < log.steps.size(); ++k) allEqual = allEqual && log.steps[k].time == log.steps[0].time;
  for (std::size_t k = 1; k < log.steps.size(); ++k) {
    const double dt = allEqual ? 1.0 : log.steps[k].time - log.steps[k - 1].time;
    if (!(dt > 0.0) || !std::isfinite(dt)) {
      throw std::invalid_argument("odometry noise: step " + std::to_string(k) +
                                  ": times must increase (or all be equal: 1 s per step)");
    }
    durations[k] = dt;
  }
  return durations;
}

MeasurementLog addOdometryNoise(const MeasurementLog& log, double scale, std::mt19937& rng,
                                const OdometryNoiseBaseline& baseline) {
  if (!(scale >= 0.0) || !std::isfinite(scale)) {
    throw std::invalid_argument("odometry noise: the scale must be finite and >= 0");
  }
  MeasurementLog out = log;
  const std::vector<double> durations = stepDurations(log);
  for (std::size_t k = 0; k < out.steps.size(); ++k) {
    if (!out.steps[k].odometry) continue;
    Odometry& odometry = *out.steps[k].odometry;
    const int dimension = poseDimension(odometry.increment);
    const int d = dimension == 2 ? 3 : 6;
    if (odometry.covariance.rows() != d || odometry.covariance.cols() != d) {
      throw std::invalid_argument("odometry noise: step " + std::to_string(k) + ": covariance is not " +
                                  std::to_string(d) + "x" + std::to_string(d));
    }
    Vector n(d);
    for (int i = 0; i < d; ++i) n(i) = standardNormal(rng);
    if (scale == 0.0) continue;  // bit-identical
    const Matrix q = addedOdometryCovariance(dimension, scale, durations[k], baseline);
    const Vector delta = q.diagonal().cwiseSqrt().cwiseProduct(n);
    if (dimension == 2) {
      odometry.increment = std::get<SE2>(odometry.increment).retract(Vector3(delta));
    } else {
      odometry.increment = std::get<SE3>(odometry.increment).retract(Vector6(delta));
    }
    odometry.covariance += q;
  }
  return out;
}

int trueLandmarkClass(const LogHeader& header, int landmarkId) {
  if (header.classes < 1) throw std::invalid_argument("labels: the log has no classes");
  for (const LandmarkTruth& truth : header.landmarkTruth) {
    if (truth.id == landmarkId && truth.classIndex >= 0) return truth.classIndex;
  }
  if (landmarkId < 0) throw std::invalid_argument("labels: a landmark id must be >= 0");
  return landmarkId % header.classes;
}

MeasurementLog redrawLabels(const MeasurementLog& log, double misclassification, std::mt19937& rng) {
  const double p = misclassification;
  if (!(p >= 0.0 && p < 1.0)) throw std::invalid_argument("labels: the misclassification rate must be in [0, 1)");
  const int classes = log.header.classes;
  if (classes < 2) throw std::invalid_argument("labels: redrawing labels needs at least two classes");
  MeasurementLog out = log;
  out.header.semantic = SemanticKind::Label;
  out.header.classifier = ClassifierModelSpec{};
  out.header.classifier.kind = ClassifierModelSpec::Kind::Categorical;
  out.header.classifier.misclassification = p;
  for (std::size_t k = 0; k < out.steps.size(); ++k) {
    for (Detection& detection : out.steps[k].detections) {
      if (!scoredTruth(detection.truthId)) {
        throw std::invalid_argument("labels: step " + std::to_string(k) +
                                    ": a detection without a truth id or with truth \"unknown\" (the true class "
                                    "is unknown)");
      }
      const double u1 = uniform01(rng), u2 = uniform01(rng);
      int label;
      if (*detection.truthId == kNotALandmark) {
        label = std::min(classes - 1, static_cast<int>(u2 * classes));
      } else {
        const int c = trueLandmarkClass(out.header, *detection.truthId);
        if (u1 >= p) {
          label = c;
        } else {
          const int other = std::min(classes - 2, static_cast<int>(u2 * (classes - 1)));
          label = other < c ? other : other + 1;  // the other-th class that is not c
        }
      }
      detection.label = label;
      detection.classVector.reset();
    }
  }
  return out;
}

std::mt19937 perturbationStream(std::uint64_t seed, std::uint32_t stream) {
  std::seed_seq words{static_cast<std::uint32_t>(seed & 0xffffffffu), static_cast<std::uint32_t>(seed >> 32), stream,
                      static_cast<std::uint32_t>(0x5714d7)};
  return std::mt19937(words);
}

MeasurementLog perturbLog(const MeasurementLog& log, const LogPerturbation& perturbation, std::uint64_t seed) {
  if (perturbation.maxSteps < 0) throw std::invalid_argument("perturbation: maxSteps must be >= 0");
  MeasurementLog truncated;
  const MeasurementLog* source = &log;
  if (perturbation.maxSteps > 0 && static_cast<std::size_t>(perturbation.maxSteps) < log.steps.size()) {
    truncated.header = log.header;
    truncated.steps.assign(log.steps.begin(), log.steps.begin() + perturbation.maxSteps);
    source = &truncated;
  }
  std::mt19937 noise = perturbationStream(seed, 1), labels = perturbationStream(seed, 2);
  const MeasurementLog noisy = addOdometryNoise(*source, perturbation.odometryNoiseScale, noise, perturbation.baseline);
  if (!(perturbation.modelMisclassificationFloor >= 0.0 && perturbation.modelMisclassificationFloor < 1.0)) {
    throw std::invalid_argument("perturbation: the model misclassification floor must be in [0, 1)");
  }
  MeasurementLog out = redrawLabels(noisy, perturbation.misclassification, labels);
  out.header.classifier.misclassification =
      std::max(perturbation.misclassification, perturbation.modelMisclassificationFloor);
  return out;
}

}  // namespace semslam
