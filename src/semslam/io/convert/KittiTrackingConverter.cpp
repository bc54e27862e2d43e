#include "semslam/io/convert/KittiTrackingConverter.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <sstream>

#include "semslam/core/InputError.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/io/convert/ConversionCommon.h"
#include "semslam/io/convert/KittiDetectionNoise.h"
#include "semslam/io/convert/KittiFrames.h"
#include "semslam/io/convert/KittiTrackingFiles.h"
#include "semslam/io/convert/KittiTrackingTruth.h"
#include "semslam/models/Sampling.h"

namespace semslam {

namespace {

using ConfusionCounts = std::array<std::array<std::size_t, kKittiClasses>, kKittiClasses>;

std::string number(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

void validateKittiOptions(const KittiTrackingOptions& o) {
  if (o.sequence < 0) throw InputError("kitti-tracking needs --sequence N (0..9999)");
  for (std::size_t c = 0; c < o.scoreThresholds.size(); ++c) {
    if (o.scoreThresholds[c] && !std::isfinite(*o.scoreThresholds[c])) {
      throw InputError("--score-threshold-" + kittiClassNames()[c] + " must be finite");
    }
  }
  if (o.odometryNoiseScale) {
    if (o.odometry != KittiTrackingOptions::Odometry::Noisy) {
      throw InputError("--odom-noise-scale applies to --odometry noisy only");
    }
    if (!std::isfinite(*o.odometryNoiseScale) || *o.odometryNoiseScale < 0.0) {
      throw InputError("--odom-noise-scale must be a finite number >= 0, got " + number(*o.odometryNoiseScale));
    }
  }
  if (!std::isfinite(o.maxRange) || o.maxRange < 0.0) {
    throw InputError("--max-range must be a finite number of metres >= 0, got " + number(o.maxRange));
  }
}

/// A 3x3 table of non-negative integer counts, rows the true class, columns the detected class.
ConfusionCounts readConfusionCounts(const std::string& path) {
  const std::vector<NumericRow> rows = readDatasetTable(path, kKittiClasses, "Car Pedestrian Cyclist counts");
  if (rows.size() != kKittiClasses) {
    throw InputError(path, rows.back().line,
                     "expected 3 rows (true Car, Pedestrian, Cyclist), found " + std::to_string(rows.size()));
  }
  ConfusionCounts counts{};
  for (std::size_t r = 0; r < kKittiClasses; ++r) {
    for (std::size_t c = 0; c < kKittiClasses; ++c) {
      counts[r][c] = static_cast<std::size_t>(integerField(path, rows[r], c, "count", 0, 1 << 30));
    }
  }
  return counts;
}

/// p = (off-diagonal + 1) / (total + 3).
double misclassificationOf(const ConfusionCounts& counts) {
  std::size_t total = 0, off = 0;
  for (std::size_t r = 0; r < kKittiClasses; ++r) {
    for (std::size_t c = 0; c < kKittiClasses; ++c) {
      total += counts[r][c];
      if (r != c) off += counts[r][c];
    }
  }
  return static_cast<double>(off + 1) / static_cast<double>(total + kKittiClasses);
}

std::string fullCountsText(const KittiLabelConfusion& counts) {
  std::string text = "confusion of detector class against label type (rows label, columns detected Car "
                     "Pedestrian Cyclist):";
  for (int r = 0; r <= kKittiLabelTypes; ++r) {
    if (r < kKittiLabelTypes && static_cast<KittiLabelType>(r) == KittiLabelType::DontCare) continue;
    text += (r == 0 ? " " : "; ") +
            (r < kKittiLabelTypes ? kittiLabelTypeName(static_cast<KittiLabelType>(r)) : std::string("unmatched")) +
            ":";
    for (const std::size_t count : counts[static_cast<std::size_t>(r)]) text += " " + std::to_string(count);
  }
  return text;
}

std::string countsText(const ConfusionCounts& counts) {
  std::string text;
  for (std::size_t r = 0; r < kKittiClasses; ++r) {
    text += (r == 0 ? "" : "; ") + kittiClassNames()[r] + ":";
    for (std::size_t c = 0; c < kKittiClasses; ++c) text += " " + std::to_string(counts[r][c]);
  }
  return text;
}

/// The residual of a matched detection, e = p_det − p_label in body axes, split along the label's viewing ray u
/// (radial), across it horizontally (h = normalise(z × u), "left") and across it vertically (v = u × h).
std::array<double, 3> rayResidual(const Point3& detectionBody, const Point3& labelBody) {
  const Vector3 e = detectionBody - labelBody;
  const Vector3 u = labelBody.normalized();
  const Vector3 h = Vector3::UnitZ().cross(u).normalized();
  const Vector3 v = u.cross(h);
  return {e.dot(u), e.dot(h), e.dot(v)};
}

void writeMatches(const std::string& path, int sequence, const std::vector<KittiDetection>& detections,
                  const std::vector<KittiDetectionTruth>& truth, const std::vector<KittiLabel>& labels,
                  const std::map<int, KittiTrack>& tracks) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out << "sequence,frame,class,score,range,kind,label_type,track,track_motion,radial,lateral,vertical\n";
    char line[512];
    for (std::size_t i = 0; i < detections.size(); ++i) {
      const KittiDetection& d = detections[i];
      const KittiDetectionTruth& t = truth[i];
      const Point3 p = kittiBodyPoint(d.bottomCentre);
      std::string labelType, track, motion, radial, lateral, vertical;
      if (t.label) {
        const KittiLabel& label = labels[*t.label];
        labelType = kittiLabelTypeName(label.type);
        track = std::to_string(label.track);
        motion = number(tracks.at(label.track).motion);
        const std::array<double, 3> r = rayResidual(p, kittiBodyPoint(label.bottomCentre));
        radial = number(r[0]);
        lateral = number(r[1]);
        vertical = number(r[2]);
      }
      std::snprintf(line, sizeof line, "%d,%d,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", sequence, d.frame,
                    kittiClassNames()[static_cast<std::size_t>(d.detectedClass)].c_str(), number(d.score).c_str(),
                    number(p.norm()).c_str(), kittiTruthKindName(t.kind).c_str(), labelType.c_str(), track.c_str(),
                    motion.c_str(), radial.c_str(), lateral.c_str(), vertical.c_str());
      out << line;
    }
  });
}

}  // namespace

MeasurementLog convertKittiTracking(const std::string& folder, const ConvertOptions& options, ConversionStats* stats) {
  validateConvertOptions(options, 3);
  const KittiTrackingOptions& kitti = options.kitti;
  validateKittiOptions(kitti);
  const KittiSequence sequence = readKittiSequence(folder, kitti.sequence);
  const std::size_t frames = sequence.cameraToWorld.size();

  std::vector<SE3> bodyPoses;
  bodyPoses.reserve(frames);
  for (const SE3& pose : sequence.cameraToWorld) bodyPoses.push_back(kittiBodyPose(pose));

  // Detections kept: score threshold per class, then the range limit.
  std::array<double, kKittiClasses> thresholds{};
  for (std::size_t c = 0; c < kKittiClasses; ++c) {
    thresholds[c] = kitti.scoreThresholds[c].value_or(kKittiDefaultScoreThresholds[c]);
  }
  std::vector<KittiDetection> kept;
  std::size_t belowThreshold = 0, beyondRange = 0;
  for (const KittiDetection& d : sequence.detections) {
    if (d.score < thresholds[static_cast<std::size_t>(d.detectedClass)]) {
      ++belowThreshold;
    } else if (kitti.maxRange > 0.0 && d.bottomCentre.norm() > kitti.maxRange) {
      ++beyondRange;
    } else if (d.bottomCentre.norm() <= 0.0) {
      throw InputError(sequence.detectionPaths[static_cast<std::size_t>(d.detectedClass)], d.line,
                       "a detection at the camera's origin has no viewing ray");
    } else {
      kept.push_back(d);
    }
  }

  const std::map<int, KittiTrack> tracks = kittiTracks(sequence.labels, bodyPoses);
  const std::vector<KittiDetectionTruth> truth = kittiDetectionTruth(kept, sequence.labels, tracks);
  if (!kitti.matchesOut.empty()) {
    writeMatches(kitti.matchesOut, kitti.sequence, kept, truth, sequence.labels, tracks);
  }

  // Confusion counts of the matched detections whose label is one of the detector's classes.
  ConfusionCounts ownCounts{};
  std::array<std::size_t, kKittiTruthKinds> kindCounts{};
  for (std::size_t i = 0; i < kept.size(); ++i) {
    ++kindCounts[static_cast<std::size_t>(truth[i].kind)];
    if (!truth[i].label) continue;
    if (const std::optional<int> c = kittiClassOfLabel(sequence.labels[*truth[i].label].type)) {
      ++ownCounts[static_cast<std::size_t>(*c)][static_cast<std::size_t>(kept[i].detectedClass)];
    }
  }
  const KittiLabelConfusion fullCounts = kittiLabelConfusion(kept, truth, sequence.labels);
  const bool heldOut = !kitti.confusionFile.empty();
  const ConfusionCounts modelCounts = heldOut ? readConfusionCounts(kitti.confusionFile) : ownCounts;
  const double misclassification = misclassificationOf(modelCounts);

  MeasurementLog raw;
  LogSources sources;
  sources.dataset = folder;
  LogHeader& header = raw.header;
  header.dimension = 3;
  header.classes = kKittiClasses;
  header.semantic = SemanticKind::Label;
  header.classifier.kind = ClassifierModelSpec::Kind::Categorical;
  header.classifier.misclassification = misclassification;
  header.sensor.kind = SensorKind::RelativePosition;
  header.sensor.bodyToSensor = SE3();
  header.sensor.maxRange = kitti.maxRange;
  header.sensor.fieldOfView = kKittiFieldOfView;

  // Steps: one per frame, with the reference pose and ORB-SLAM3's increment.
  Matrix orbCovariance = Matrix::Zero(6, 6);
  for (int i = 0; i < 6; ++i) orbCovariance(i, i) = kKittiOrbSlamSigmas[static_cast<std::size_t>(i)] *
                                                    kKittiOrbSlamSigmas[static_cast<std::size_t>(i)];
  const bool noisy = kitti.odometry == KittiTrackingOptions::Odometry::Noisy;
  const double scale = kitti.odometryNoiseScale.value_or(1.0);
  std::mt19937 rng(options.seed);
  raw.steps.resize(frames);
  sources.steps.resize(frames);
  for (std::size_t k = 0; k < frames; ++k) {
    TimeStep& step = raw.steps[k];
    step.time = kKittiFramePeriod * static_cast<double>(k);
    step.truePose = bodyPoses[k];
    // The frame's pose makes its true pose and, with the previous frame's, its odometry.
    const SourceLine poseRow{sequence.posePath, sequence.poseLines.at(k), 0};
    sources.steps[k].step = sources.steps[k].truePose = sources.steps[k].odometry = poseRow;
    if (k == 0) continue;
    SE3 increment = bodyPoses[k - 1].inverse().compose(bodyPoses[k]);
    Matrix covariance = orbCovariance;
    if (noisy) {
      const Vector delta = sampleGaussian(Vector::Zero(6), scale * scale * orbCovariance, rng);
      increment = increment.compose(SE3::Exp(Vector6(delta)));
      covariance = (1.0 + scale * scale) * orbCovariance;
    }
    step.odometry = Odometry{increment, covariance};
  }

  std::set<int> landmarkTracks;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const KittiDetection& d = kept[i];
    Detection detection;
    const Point3 p = kittiBodyPoint(d.bottomCentre);
    detection.geometry = Vector3(p);
    detection.covariance = kittiDetectionCovariance(p);
    detection.label = static_cast<int>(d.detectedClass);
    detection.truthId = truth[i].truthId;
    if (truth[i].kind == KittiTruthKind::Moving) detection.clutterSource = truth[i].track;
    if (truth[i].kind == KittiTruthKind::Landmark) landmarkTracks.insert(truth[i].track);
    raw.steps[static_cast<std::size_t>(d.frame)].detections.push_back(std::move(detection));
    sources.steps[static_cast<std::size_t>(d.frame)].detections.push_back(
        SourceLine{sequence.detectionPaths[static_cast<std::size_t>(d.detectedClass)], d.line, 0});
  }
  for (int id : landmarkTracks) {
    const KittiTrack& track = tracks.at(id);
    header.landmarkTruth.push_back(LandmarkTruth{id, kittiClassOfLabel(track.type).value_or(-1), track.meanPosition});
    sources.landmarks.push_back(SourceLine{sequence.labelPath, track.firstLine, 0});
  }

  // Notes: the counts per truth kind and the confusion counts.
  std::ostringstream kinds;
  kinds << "truth kinds:";
  for (int k = 0; k < kKittiTruthKinds; ++k) {
    kinds << (k == 0 ? " " : ", ") << kittiTruthKindName(static_cast<KittiTruthKind>(k)) << " "
          << kindCounts[static_cast<std::size_t>(k)];
  }
  const std::string confusion = "confusion counts (rows true, columns detected Car Pedestrian Cyclist) " +
                                countsText(ownCounts) + "; misclassification " + number(misclassification) +
                                (heldOut ? " from " + kitti.confusionFile : " from this sequence");

  std::ostringstream source;
  source << "KITTI tracking sequence " << kittiSequenceName(kitti.sequence) << " (" << folder
         << "), semslam convert kitti-tracking: PointRCNN detections with score >= " << number(thresholds[0])
         << " (Car), " << number(thresholds[1]) << " (Pedestrian), " << number(thresholds[2]) << " (Cyclist)";
  if (kitti.maxRange > 0.0) source << " within " << number(kitti.maxRange) << " m";
  source << " (" << belowThreshold << " below threshold, " << beyondRange << " beyond range dropped)"
         << "; bottom centre in body axes (x forward, y left, z up), sigma_radial = " << number(kKittiRadialSigma.a)
         << " + " << number(kKittiRadialSigma.b) << " r, sigma_lateral = " << number(kKittiLateralSigma.a) << " + "
         << number(kKittiLateralSigma.b) << " r; labels = the detector's class (0 Car, 1 Pedestrian, 2 Cyclist); "
         << kinds.str() << "; " << confusion << "; odometry "
         << (noisy ? "ORB-SLAM3 plus noise at scale " + number(scale) + " (seed " + std::to_string(options.seed) + ")"
                   : std::string("ORB-SLAM3"))
         << "; true_pose = the ORB-SLAM3 stereo trajectory, an estimate, not ground truth";
  header.source = source.str();

  MeasurementLog log = finishConversion(std::move(raw), std::move(sources), options, stats);
  if (stats != nullptr) {
    stats->notes.push_back(kinds.str() + " (before keyframing)");
    stats->notes.push_back(confusion);
    stats->notes.push_back(fullCountsText(fullCounts));
  }
  return log;
}

}  // namespace semslam
