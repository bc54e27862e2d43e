#include "semslam/eval/MeasurementResiduals.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "semslam/core/ChiSquare.h"
#include "semslam/models/RangeBearingElevationSensor3.h"
#include "semslam/models/RangeBearingSensor2.h"
#include "semslam/models/RelativePositionSensor2.h"
#include "semslam/models/RelativePositionSensor3.h"

namespace semslam {

namespace {

std::vector<std::string> detectionComponents(const LogHeader& header) {
  switch (header.sensor.kind) {
    case SensorKind::RangeBearing:
      return {"range", "bearing"};
    case SensorKind::RangeBearingElevation:
      return {"range", "bearing", "elevation"};
    case SensorKind::RelativePosition:
      return header.dimension == 3 ? std::vector<std::string>{"x", "y", "z"} : std::vector<std::string>{"x", "y"};
    case SensorKind::RelativePose:
      return {};
  }
  return {};
}

std::vector<std::string> odometryComponents(int dimension) {
  if (dimension == 3) return {"x", "y", "z", "rx", "ry", "rz"};
  return {"x", "y", "theta"};
}

double median(std::vector<double> values) {
  const std::size_t n = values.size();
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(n / 2), values.end());
  const double upper = values[n / 2];
  if (n % 2 == 1) return upper;
  const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(n / 2));
  return 0.5 * (lower + upper);
}

ComponentResidualStatistics summarise(const std::string& name, const std::vector<double>& residual,
                                      const std::vector<double>& variance) {
  ComponentResidualStatistics s;
  s.name = name;
  s.count = residual.size();
  if (s.count == 0) return s;
  const double n = static_cast<double>(s.count);
  double sum = 0.0, sumVariance = 0.0, sumNormalized = 0.0;
  std::vector<double> normalized(s.count);
  for (std::size_t i = 0; i < s.count; ++i) {
    sum += residual[i];
    sumVariance += variance[i];
    normalized[i] = variance[i] > 0.0 ? residual[i] / std::sqrt(variance[i]) : 0.0;
    sumNormalized += normalized[i];
  }
  s.mean = sum / n;
  const double meanNormalized = sumNormalized / n;
  double squares = 0.0, squaresNormalized = 0.0;
  for (std::size_t i = 0; i < s.count; ++i) {
    squares += (residual[i] - s.mean) * (residual[i] - s.mean);
    squaresNormalized += (normalized[i] - meanNormalized) * (normalized[i] - meanNormalized);
  }
  s.std = std::sqrt(squares / n);
  s.normalizedStd = std::sqrt(squaresNormalized / n);
  s.statedStd = std::sqrt(sumVariance / n);
  s.median = median(residual);
  std::vector<double> deviations(s.count);
  for (std::size_t i = 0; i < s.count; ++i) deviations[i] = std::abs(residual[i] - s.median);
  std::size_t inside = 0;
  for (std::size_t i = 0; i < s.count; ++i) inside += deviations[i] <= 1.96 * std::sqrt(variance[i]);
  s.within95 = static_cast<double>(inside) / n;
  s.robustStd = 1.4826 * median(std::move(deviations));
  return s;
}

// measured − predicted for one detection, or an empty vector when it is not evaluated.
Vector detectionResidual(const LogHeader& header, const Pose& pose, const LandmarkState& landmark,
                         const Detection& detection) {
  const SensorSpec& sensor = header.sensor;
  if (sensor.kind == SensorKind::RangeBearing) {
    const auto* robot = std::get_if<SE2>(&pose);
    const auto* point = std::get_if<Point2>(&landmark);
    const auto* mount = std::get_if<SE2>(&sensor.bodyToSensor);
    if (!robot || !point || !mount) return {};
    const RangeBearingSensor2 model(*mount);
    return RangeBearingSensor2::difference(detection.geometry, model.predict(*robot, *point));
  }
  if (sensor.kind == SensorKind::RangeBearingElevation) {
    const auto* robot = std::get_if<SE3>(&pose);
    const auto* point = std::get_if<Point3>(&landmark);
    const auto* mount = std::get_if<SE3>(&sensor.bodyToSensor);
    if (!robot || !point || !mount) return {};
    const RangeBearingElevationSensor3 model(*mount);
    return RangeBearingElevationSensor3::difference(detection.geometry, model.predict(*robot, *point));
  }
  if (sensor.kind == SensorKind::RelativePosition) {
    if (const auto* robot = std::get_if<SE2>(&pose)) {
      const auto* point = std::get_if<Point2>(&landmark);
      const auto* mount = std::get_if<SE2>(&sensor.bodyToSensor);
      if (!point || !mount) return {};
      return Vector(detection.geometry - RelativePositionSensor2(*mount).predict(*robot, *point));
    }
    const auto* robot = std::get_if<SE3>(&pose);
    const auto* point = std::get_if<Point3>(&landmark);
    const auto* mount = std::get_if<SE3>(&sensor.bodyToSensor);
    if (!robot || !point || !mount) return {};
    return Vector(detection.geometry - RelativePositionSensor3(*mount).predict(*robot, *point));
  }
  return {};
}

Vector odometryResidual(const Pose& previous, const Pose& current, const Odometry& odometry) {
  if (const auto* a = std::get_if<SE2>(&previous)) {
    const auto* b = std::get_if<SE2>(&current);
    const auto* z = std::get_if<SE2>(&odometry.increment);
    if (!b || !z) return {};
    return SE2::Log(z->between(a->between(*b)));
  }
  const auto* a = std::get_if<SE3>(&previous);
  const auto* b = std::get_if<SE3>(&current);
  const auto* z = std::get_if<SE3>(&odometry.increment);
  if (!a || !b || !z) return {};
  return SE3::Log(z->between(a->between(*b)));
}

// The NEES of the composed `odometry` (consecutive steps, oldest first) against the true relative pose `relative`
// of the window's ends (header comment: first-order covariance, r = Log(Z⁻¹ · relative)); nullopt where an
// increment is not of the relative pose's group or its covariance not of the group's dimension.
template <class Group>
std::optional<double> composedOdometryNees(const std::vector<const Odometry*>& odometry, const Group& relative) {
  Group composed;
  Matrix covariance = Matrix::Zero(Group::kDim, Group::kDim);
  for (const Odometry* step : odometry) {
    const auto* increment = std::get_if<Group>(&step->increment);
    if (!increment || step->covariance.rows() != Group::kDim || step->covariance.cols() != Group::kDim) {
      return std::nullopt;
    }
    const Matrix adjoint = increment->inverse().adjoint();  // Ad(Z_i⁻¹)
    covariance = adjoint * covariance * adjoint.transpose() + step->covariance;
    composed = composed.compose(*increment);
  }
  const Vector residual = Group::Log(composed.between(relative));
  return residual.dot(covariance.ldlt().solve(residual));
}

}  // namespace

ResidualAccumulator::ResidualAccumulator(const LogHeader& header) : header_(header) {
  detection_.resize(detectionComponents(header).size());
  odometry_.resize(odometryComponents(header.dimension).size());
}

void ResidualAccumulator::add(const TimeStep& step) {
  for (const Detection& detection : step.detections) {
    if (!scoredTruth(detection.truthId)) {  // no truth, or "unknown"
      ++counts_.detectionsUnknownTruth;
      continue;
    }
    if (*detection.truthId == kNotALandmark) {
      ++counts_.detectionsClutter;
      continue;
    }
    const auto landmark = std::find_if(header_.landmarkTruth.begin(), header_.landmarkTruth.end(),
                                       [&](const LandmarkTruth& t) { return t.id == *detection.truthId; });
    if (landmark == header_.landmarkTruth.end()) {
      ++counts_.detectionsUnknownTruth;
      continue;
    }
    if (!step.truePose) {
      ++counts_.detectionsWithoutTruePose;
      continue;
    }
    Vector residual;
    try {
      residual = detectionResidual(header_, *step.truePose, landmark->state, detection);
    } catch (const std::domain_error&) {
      ++counts_.detectionsUndefined;
      continue;
    }
    if (residual.size() == 0 || static_cast<std::size_t>(residual.size()) != detection_.size() ||
        detection.covariance.rows() != residual.size()) {
      ++counts_.detectionsSkipped;
      continue;
    }
    ++counts_.detectionsEvaluated;
    for (Eigen::Index i = 0; i < residual.size(); ++i) {
      detection_[static_cast<std::size_t>(i)].residual.push_back(residual(i));
      detection_[static_cast<std::size_t>(i)].variance.push_back(detection.covariance(i, i));
    }
  }
  if (!first_ && step.odometry) {
    if (previousTruePose_ && step.truePose) {
      const Vector residual = odometryResidual(*previousTruePose_, *step.truePose, *step.odometry);
      if (static_cast<std::size_t>(residual.size()) == odometry_.size()) {
        ++counts_.odometryEvaluated;
        for (Eigen::Index i = 0; i < residual.size(); ++i) {
          odometry_[static_cast<std::size_t>(i)].residual.push_back(residual(i));
          odometry_[static_cast<std::size_t>(i)].variance.push_back(step.odometry->covariance(i, i));
        }
      }
    } else {
      ++counts_.odometryWithoutTruePoses;
    }
  }
  first_ = false;
  previousTruePose_ = step.truePose;
  window_.push_back({step.odometry, step.truePose});
  if (window_.size() > static_cast<std::size_t>(kOdometryWindowSteps.back()) + 1) window_.pop_front();
  addWindows();
}

void ResidualAccumulator::addWindows() {
  const WindowEntry& last = window_.back();
  if (!last.truePose) return;
  const int dimension = header_.dimension == 3 ? SE3::kDim : SE2::kDim;
  const double quantile = chiSquareQuantile(0.95, dimension);
  for (std::size_t w = 0; w < kOdometryWindowSteps.size(); ++w) {
    const std::size_t n = static_cast<std::size_t>(kOdometryWindowSteps[w]);
    if (window_.size() < n + 1) continue;
    const WindowEntry& start = window_[window_.size() - 1 - n];
    if (!start.truePose) continue;
    std::vector<const Odometry*> odometry;
    for (std::size_t i = window_.size() - n; i < window_.size(); ++i) {
      if (!window_[i].odometry) break;
      odometry.push_back(&*window_[i].odometry);
    }
    if (odometry.size() != n) continue;  // a step without odometry inside the window
    std::optional<double> nees;
    if (const auto* a = std::get_if<SE2>(&*start.truePose)) {
      if (const auto* b = std::get_if<SE2>(&*last.truePose)) nees = composedOdometryNees(odometry, a->between(*b));
    } else if (const auto* a3 = std::get_if<SE3>(&*start.truePose)) {
      if (const auto* b3 = std::get_if<SE3>(&*last.truePose)) nees = composedOdometryNees(odometry, a3->between(*b3));
    }
    if (!nees) continue;
    WindowSums& sums = windowSums_[w];
    ++sums.windows;
    sums.nees += *nees;
    sums.inside += *nees <= quantile;
  }
}

LogResidualStatistics ResidualAccumulator::statistics() const {
  LogResidualStatistics result = counts_;
  const std::vector<std::string> detectionNames = detectionComponents(header_);
  const std::vector<std::string> odometryNames = odometryComponents(header_.dimension);
  for (std::size_t i = 0; i < detection_.size(); ++i) {
    result.detection.push_back(summarise(detectionNames[i], detection_[i].residual, detection_[i].variance));
  }
  for (std::size_t i = 0; i < odometry_.size(); ++i) {
    result.odometry.push_back(summarise(odometryNames[i], odometry_[i].residual, odometry_[i].variance));
  }
  for (std::size_t w = 0; w < kOdometryWindowSteps.size(); ++w) {
    OdometryWindowStatistics window;
    window.steps = kOdometryWindowSteps[w];
    window.dimension = header_.dimension == 3 ? SE3::kDim : SE2::kDim;
    window.windows = windowSums_[w].windows;
    if (window.windows > 0) {
      window.meanNees = windowSums_[w].nees / static_cast<double>(window.windows);
      window.withinQuantile = static_cast<double>(windowSums_[w].inside) / static_cast<double>(window.windows);
    }
    result.odometryWindows.push_back(window);
  }
  return result;
}

LogResidualStatistics computeResidualStatistics(const MeasurementLog& log) {
  ResidualAccumulator accumulator(log.header);
  for (const TimeStep& step : log.steps) accumulator.add(step);
  return accumulator.statistics();
}

std::string formatResidualStatistics(const LogResidualStatistics& statistics) {
  std::string text;
  char line[256];
  auto table = [&](const char* title, const std::vector<ComponentResidualStatistics>& components) {
    std::snprintf(line, sizeof line, "%-10s %-10s %8s %11s %11s %11s %11s %11s %9s %9s\n", title, "component", "count",
                  "mean", "std", "robust std", "stated std", "std/stated", "norm. std", "in 1.96σ");
    text += line;
    for (const ComponentResidualStatistics& c : components) {
      const double ratio = c.statedStd > 0.0 ? c.std / c.statedStd : 0.0;
      std::snprintf(line, sizeof line, "%-10s %-10s %8zu %11.4g %11.4g %11.4g %11.4g %11.3f %9.3f %9.3f\n", "",
                    c.name.c_str(), c.count, c.mean, c.std, c.robustStd, c.statedStd, ratio, c.normalizedStd,
                    c.within95);
      text += line;
    }
  };
  std::snprintf(line, sizeof line,
                "detections: %zu evaluated; not evaluated: %zu clutter, %zu unknown truth, %zu without a true pose, "
                "%zu unsupported, %zu undefined\n",
                statistics.detectionsEvaluated, statistics.detectionsClutter, statistics.detectionsUnknownTruth,
                statistics.detectionsWithoutTruePose, statistics.detectionsSkipped, statistics.detectionsUndefined);
  text += line;
  if (!statistics.detection.empty()) table("detection", statistics.detection);
  std::snprintf(line, sizeof line, "odometry: %zu evaluated; %zu without true poses at both ends\n",
                statistics.odometryEvaluated, statistics.odometryWithoutTruePoses);
  text += line;
  table("odometry", statistics.odometry);
  if (!statistics.odometryWindows.empty()) {
    const int dimension = statistics.odometryWindows.front().dimension;
    std::snprintf(line, sizeof line,
                  "odometry over windows of n steps (composed; every start step, so windows overlap; white noise as "
                  "stated gives a mean NEES of %d and 0.95 inside the chi2 95 %% quantile):\n",
                  dimension);
    text += line;
    std::snprintf(line, sizeof line, "%-10s %-10s %8s %11s %11s\n", "odometry", "n steps", "windows", "mean NEES",
                  "inside 95%");
    text += line;
    for (const OdometryWindowStatistics& w : statistics.odometryWindows) {
      std::snprintf(line, sizeof line, "%-10s %-10d %8zu %11.3f %11.3f\n", "", w.steps, w.windows, w.meanNees,
                    w.withinQuantile);
      text += line;
    }
  }
  return text;
}

}  // namespace semslam
