#include "semslam/io/convert/KittiTrackingTruth.h"

#include <algorithm>
#include <limits>

#include "semslam/io/convert/KittiFrames.h"
#include "semslam/models/MeasurementLog.h"
#include "semslam/solve/HungarianAssignment.h"

namespace semslam {

namespace {

enum class Group { Vehicles, Persons, None };

Group groupOfLabel(KittiLabelType type) {
  switch (type) {
    case KittiLabelType::Car:
    case KittiLabelType::Van:
    case KittiLabelType::Truck:
    case KittiLabelType::Tram:
    case KittiLabelType::Misc: return Group::Vehicles;
    case KittiLabelType::Pedestrian:
    case KittiLabelType::PersonSitting:
    case KittiLabelType::Cyclist: return Group::Persons;
    case KittiLabelType::DontCare: return Group::None;
  }
  return Group::None;
}

Group groupOfDetection(KittiClass c) { return c == KittiClass::Car ? Group::Vehicles : Group::Persons; }

bool insideBox(const std::array<double, 4>& box, double x, double y) {
  return x >= box[0] && x <= box[2] && y >= box[1] && y <= box[3];
}

/// The truth of a detection matched to `label` of `track`.
KittiDetectionTruth matchedTruth(const KittiDetection& detection, std::size_t labelIndex, const KittiLabel& label,
                                 const KittiTrack& track) {
  KittiDetectionTruth truth;
  truth.label = labelIndex;
  truth.track = label.track;
  const bool otherVehicle = detection.detectedClass == KittiClass::Car && label.type != KittiLabelType::Car;
  if (otherVehicle) {
    truth.kind = KittiTruthKind::OtherVehicle;
  } else if (track.motion > kKittiMovingMotion) {
    truth.kind = KittiTruthKind::Moving;
  } else if (track.motion > kKittiStaticMotion) {
    truth.kind = KittiTruthKind::SlowTrack;
  } else {
    truth.kind = KittiTruthKind::Landmark;
  }
  truth.truthId = truth.kind == KittiTruthKind::Landmark ? label.track
                  : truth.kind == KittiTruthKind::Moving ? kNotALandmark
                                                         : kUnknownTruth;
  return truth;
}

}  // namespace

std::string kittiTruthKindName(KittiTruthKind kind) {
  switch (kind) {
    case KittiTruthKind::Landmark: return "landmark";
    case KittiTruthKind::Moving: return "moving";
    case KittiTruthKind::FalsePositive: return "false-positive";
    case KittiTruthKind::SlowTrack: return "slow-track";
    case KittiTruthKind::OtherVehicle: return "other-vehicle";
    case KittiTruthKind::NearLabel: return "near-label";
    case KittiTruthKind::DontCare: return "dont-care";
    case KittiTruthKind::Unlabelled: return "unlabelled";
  }
  return "?";
}

std::optional<int> kittiClassOfLabel(KittiLabelType type) {
  switch (type) {
    case KittiLabelType::Car: return static_cast<int>(KittiClass::Car);
    case KittiLabelType::Pedestrian:
    case KittiLabelType::PersonSitting: return static_cast<int>(KittiClass::Pedestrian);
    case KittiLabelType::Cyclist: return static_cast<int>(KittiClass::Cyclist);
    default: return std::nullopt;
  }
}

KittiLabelConfusion kittiLabelConfusion(const std::vector<KittiDetection>& detections,
                                        const std::vector<KittiDetectionTruth>& truth,
                                        const std::vector<KittiLabel>& labels) {
  KittiLabelConfusion counts{};
  for (std::size_t i = 0; i < detections.size(); ++i) {
    const std::size_t row = truth.at(i).label ? static_cast<std::size_t>(labels.at(*truth[i].label).type)
                                              : static_cast<std::size_t>(kKittiLabelTypes);
    ++counts[row][static_cast<std::size_t>(detections[i].detectedClass)];
  }
  return counts;
}

std::map<int, KittiTrack> kittiTracks(const std::vector<KittiLabel>& labels, const std::vector<SE3>& bodyPoses) {
  std::map<int, std::vector<Point3>> positions;
  std::map<int, KittiTrack> tracks;
  for (const KittiLabel& label : labels) {
    if (label.track < 0) continue;
    const SE3& pose = bodyPoses.at(static_cast<std::size_t>(label.frame));
    positions[label.track].push_back(pose.transformFrom(kittiBodyPoint(label.bottomCentre)));
    tracks.emplace(label.track, KittiTrack{label.type, 0.0, Point3::Zero(), 0, label.line});
  }
  for (auto& [id, track] : tracks) {
    const std::vector<Point3>& p = positions[id];
    track.labels = p.size();
    Point3 sum = Point3::Zero();
    for (const Point3& x : p) sum += x;
    track.meanPosition = sum / static_cast<double>(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      for (std::size_t j = i + 1; j < p.size(); ++j) track.motion = std::max(track.motion, (p[i] - p[j]).norm());
    }
  }
  return tracks;
}

std::vector<KittiDetectionTruth> kittiDetectionTruth(const std::vector<KittiDetection>& detections,
                                                     const std::vector<KittiLabel>& labels,
                                                     const std::map<int, KittiTrack>& tracks) {
  std::vector<KittiDetectionTruth> truth(detections.size());
  // Indices by (frame, group), in file order.
  std::map<std::pair<int, Group>, std::vector<std::size_t>> detectionsOf, labelsOf;
  std::map<int, std::vector<std::size_t>> dontCareOf;
  for (std::size_t i = 0; i < detections.size(); ++i) {
    detectionsOf[{detections[i].frame, groupOfDetection(detections[i].detectedClass)}].push_back(i);
  }
  for (std::size_t j = 0; j < labels.size(); ++j) {
    const Group group = groupOfLabel(labels[j].type);
    if (group == Group::None) {
      dontCareOf[labels[j].frame].push_back(j);
    } else {
      labelsOf[{labels[j].frame, group}].push_back(j);
    }
  }
  for (const auto& [key, rows] : detectionsOf) {
    const auto found = labelsOf.find(key);
    const std::vector<std::size_t> none;
    const std::vector<std::size_t>& columns = found == labelsOf.end() ? none : found->second;
    Matrix weights = Matrix::Zero(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(columns.size()));
    Matrix distance = weights;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      for (std::size_t c = 0; c < columns.size(); ++c) {
        const double d = (detections[rows[r]].bottomCentre - labels[columns[c]].bottomCentre).norm();
        distance(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = d;
        weights(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = std::max(0.0, kKittiMatchGate - d);
      }
    }
    const Assignment assignment = maximumWeightAssignment(weights);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const KittiDetection& detection = detections[rows[r]];
      const int c = assignment.rowToColumn.empty() ? -1 : assignment.rowToColumn[r];
      if (c >= 0 && distance(static_cast<Eigen::Index>(r), c) < kKittiMatchGate) {
        const std::size_t j = columns[static_cast<std::size_t>(c)];
        truth[rows[r]] = matchedTruth(detection, j, labels[j], tracks.at(labels[j].track));
        continue;
      }
      KittiDetectionTruth& t = truth[rows[r]];
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t col = 0; col < columns.size(); ++col) {
        nearest = std::min(nearest, distance(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(col)));
      }
      const double cx = 0.5 * (detection.box[0] + detection.box[2]), cy = 0.5 * (detection.box[1] + detection.box[3]);
      bool inDontCare = false;
      if (const auto dc = dontCareOf.find(detection.frame); dc != dontCareOf.end()) {
        for (std::size_t j : dc->second) inDontCare = inDontCare || insideBox(labels[j].box, cx, cy);
      }
      if (nearest <= kKittiNearbyLabel) {
        t.kind = KittiTruthKind::NearLabel;
      } else if (inDontCare) {
        t.kind = KittiTruthKind::DontCare;
      } else if (detection.bottomCentre.norm() > kKittiLabelledRange) {
        t.kind = KittiTruthKind::Unlabelled;
      } else {
        t.kind = KittiTruthKind::FalsePositive;
      }
      t.truthId = t.kind == KittiTruthKind::FalsePositive ? kNotALandmark : kUnknownTruth;
    }
  }
  return truth;
}

}  // namespace semslam
