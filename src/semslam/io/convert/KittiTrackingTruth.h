#pragma once
// Ground truth of KITTI tracking detections: which labelled object, if any, produced each detection, and whether
// that object is a landmark (issue 11, "truth"; docs/datasets.md, "KITTI tracking", Truth).
//
// Tracks. A label's world position is its bottom centre through the frame's reference pose (KittiFrames.h:
// p_w = T_wb,k · R_bc · p_c). A track's motion is the largest distance between two of its world positions (the
// diameter of the set), so a parked car seen for 700 m of path scores the drift of the reference trajectory plus
// the labels' noise, and a car that drives off scores its path. Its landmark position is the mean of its world
// positions.
//
// Class groups. Matching is within a group, so a detection is never explained by an object of another kind:
//   vehicles: Car detections     ↔ Car, Van, Truck, Tram, Misc labels;
//   persons:  Pedestrian and Cyclist detections ↔ Pedestrian, Person_sitting, Cyclist labels
//             (a Pedestrian detection of a cyclist is a real detection with a wrong class: the confusion model's job).
//
// Matching, per frame and group: the maximum-weight assignment (solve/HungarianAssignment.h) of detections to
// labels with weight max(0, g − d), d the 3D distance of the bottom centres in the camera frame and g =
// kKittiMatchGate; assigned pairs with d ≥ g are dropped. The weights depend only on the file order of the rows, so
// the matching is deterministic.
//
// Truth kinds, in this order of precedence:
//   matched, Car detection on a Van/Truck/Tram/Misc label           → unknown  (OtherVehicle)
//   matched, track motion > kKittiMovingMotion (5 m)                → not-a-landmark, clutter source = track id (Moving)
//   matched, track motion > kKittiStaticMotion (1.5 m)              → unknown  (SlowTrack)
//   matched, otherwise                                              → the track id (Landmark)
//   unmatched, a label of its group within kKittiNearbyLabel (3 m)  → unknown  (NearLabel: a second detection of
//                                                                      one object, or its label went to another)
//   unmatched, its image box centre inside a DontCare box           → unknown  (DontCare)
//   unmatched, range > kKittiLabelledRange (40 m)                   → unknown  (Unlabelled: KITTI labels stop)
//   unmatched, otherwise                                            → not-a-landmark (FalsePositive)

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "semslam/io/convert/KittiTrackingFiles.h"

namespace semslam {

inline constexpr double kKittiMatchGate = 2.0;       ///< metres: largest detection-label distance of a match
inline constexpr double kKittiNearbyLabel = 3.0;     ///< metres: "a label nearby" of an unmatched detection
inline constexpr double kKittiStaticMotion = 1.5;    ///< metres: a track within this is a landmark
inline constexpr double kKittiMovingMotion = 5.0;    ///< metres: a track beyond this is a moving object
inline constexpr double kKittiLabelledRange = 40.0;  ///< metres: beyond it an unmatched detection may be unlabelled

enum class KittiTruthKind { Landmark, Moving, FalsePositive, SlowTrack, OtherVehicle, NearLabel, DontCare, Unlabelled };
inline constexpr int kKittiTruthKinds = 8;
/// "landmark", "moving", "false-positive", "slow-track", "other-vehicle", "near-label", "dont-care", "unlabelled".
std::string kittiTruthKindName(KittiTruthKind kind);

struct KittiTrack {
  KittiLabelType type = KittiLabelType::Car;  ///< of its first label
  double motion = 0.0;                         ///< metres, the diameter of its world positions
  Point3 meanPosition = Point3::Zero();        ///< world (body-convention) frame
  std::size_t labels = 0;
  std::size_t firstLine = 0;                   ///< in the label file, of its first label
};

struct KittiDetectionTruth {
  KittiTruthKind kind = KittiTruthKind::FalsePositive;
  std::optional<std::size_t> label;  ///< index into the sequence's labels, when matched
  int track = -1;                    ///< the matched label's track, when matched
  /// The log's truth: a track id, kNotALandmark or kUnknownTruth (models/MeasurementLog.h).
  int truthId = -1;
};

/// Every track of the labels, by track id, with its motion and mean position through `bodyPoses` (T_wb,k).
std::map<int, KittiTrack> kittiTracks(const std::vector<KittiLabel>& labels, const std::vector<SE3>& bodyPoses);

/// The truth of each of `detections` (all of one sequence, any order), as above.
std::vector<KittiDetectionTruth> kittiDetectionTruth(const std::vector<KittiDetection>& detections,
                                                     const std::vector<KittiLabel>& labels,
                                                     const std::map<int, KittiTrack>& tracks);

/// The confusion of detector class against label type (docs/datasets.md, "Detector class against label type"):
/// [r][c] counts the detections of class c (KittiClass) matched to a label of type r (KittiLabelType order; the
/// DontCare row stays 0, since DontCare boxes are never matched), and row kKittiLabelTypes those matched to no label
/// (false positives, near-label, dont-care and unlabelled kinds). Matching is within a class group, so a Car
/// detection counts on a vehicle row or the last, a Pedestrian or Cyclist one on a person row or the last.
using KittiLabelConfusion = std::array<std::array<std::size_t, kKittiClasses>, kKittiLabelTypes + 1>;
KittiLabelConfusion kittiLabelConfusion(const std::vector<KittiDetection>& detections,
                                        const std::vector<KittiDetectionTruth>& truth,
                                        const std::vector<KittiLabel>& labels);

/// The class index of a label type that is one of the detector's classes (Person_sitting is a Pedestrian), or
/// std::nullopt (Van, Truck, Tram, Misc, DontCare).
std::optional<int> kittiClassOfLabel(KittiLabelType type);

}  // namespace semslam
