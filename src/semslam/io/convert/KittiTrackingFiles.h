#pragma once
// The three files of one KITTI tracking sequence as ../shared/data/kitti-tracking lays them out (its SOURCE.txt),
// read and checked; the converter (KittiTrackingConverter.h) turns them into a measurement log.
//
//   label_02/NNNN.txt                    whitespace separated, 17 fields:
//       frame track_id type truncated occluded alpha x1 y1 x2 y2 h w l X Y Z rotation_y
//       type ∈ {Car, Van, Truck, Pedestrian, Person_sitting, Cyclist, Tram, Misc, DontCare}; (X, Y, Z) the 3D box's
//       bottom centre in the rectified left colour camera frame (x right, y down, z forward), metres; track_id ≥ 0,
//       or −1 for DontCare (whose 3D fields are −1000 / −10: only its image box (x1, y1, x2, y2) is used).
//   pointrcnn_detections/{Car,Pedestrian,Cyclist}/NNNN.txt   comma separated, 15 numbers:
//       frame, type (1 Pedestrian, 2 Car, 3 Cyclist), x1, y1, x2, y2, score, h, w, l, x, y, z, rot_y, alpha
//       (x, y, z) the same bottom-centre point in the same camera frame; score PointRCNN's unnormalised confidence.
//   orbslam3_stereo_poses/NNNN.txt       KITTI pose format (io/KittiFormat.h): frame k's camera-to-world pose, world
//       = the first camera frame; one line per frame, as many as the sequence has frames.
//
// Checks (each an InputError naming the file, the line and the problem, never a crash): a row with the wrong
// number of fields (a truncated line), a field that is not a number, a frame that is not an integer ≥ 0, a frame
// smaller than the previous row's (rows are in frame order), an unknown label type, a detection whose type column
// differs from its folder's class, a score or position that is not finite, and a frame (of a label or a detection)
// for which the pose file has no line ("frame 153 has no pose: orbslam3_stereo_poses/0000.txt has 150 lines"),
// a detection at the camera or farther than kMaxKittiCoordinate, and more than kMaxKittiRowsPerFrame rows of one
// file in one frame (the ground-truth matching allocates a
// detections × labels matrix per frame: 10^5 rows of one frame would have asked for 80 GB).

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "semslam/geometry/SE3.h"

namespace semslam {

/// The detector's classes, in the order of the log's class indices: 0 Car, 1 Pedestrian, 2 Cyclist.
enum class KittiClass { Car = 0, Pedestrian = 1, Cyclist = 2 };
inline constexpr int kKittiClasses = 3;
/// "Car", "Pedestrian", "Cyclist": the detection folders' names.
const std::array<std::string, kKittiClasses>& kittiClassNames();

/// A label's type as KITTI writes it.
enum class KittiLabelType { Car, Van, Truck, Pedestrian, PersonSitting, Cyclist, Tram, Misc, DontCare };
inline constexpr int kKittiLabelTypes = 9;
/// The largest coordinate of a detection's position (a log's limit, docs/measurement-log.md).
inline constexpr double kMaxKittiCoordinate = 1e7;
/// The most rows one file may hold for one frame (KITTI's frames have fewer than 100 objects).
inline constexpr std::size_t kMaxKittiRowsPerFrame = 1000;

struct KittiLabel {
  std::size_t line = 0;  ///< in the label file, for messages
  int frame = 0;
  int track = -1;  ///< ≥ 0, −1 for DontCare
  KittiLabelType type = KittiLabelType::DontCare;
  std::array<double, 4> box{};  ///< image box x1, y1, x2, y2 (pixels)
  Point3 bottomCentre = Point3::Zero();  ///< camera frame (x right, y down, z forward), metres
};

struct KittiDetection {
  std::size_t line = 0;  ///< in its detection file
  int frame = 0;
  KittiClass detectedClass = KittiClass::Car;
  std::array<double, 4> box{};  ///< image box x1, y1, x2, y2 (pixels)
  double score = 0.0;
  Point3 bottomCentre = Point3::Zero();  ///< camera frame, metres
};

struct KittiSequence {
  std::string labelPath, posePath;
  std::array<std::string, kKittiClasses> detectionPaths;
  std::vector<SE3> cameraToWorld;  ///< one per frame: the ORB-SLAM3 estimate, rotation projected to SO(3)
  std::vector<std::size_t> poseLines;  ///< one per frame: its line in the pose file
  std::vector<KittiLabel> labels;           ///< in file order (frames non-decreasing)
  std::vector<KittiDetection> detections;   ///< Car, then Pedestrian, then Cyclist file, each in file order
};

/// "0004" for 4.
std::string kittiSequenceName(int sequence);

/// Reads sequence `sequence` (0..9999) of the dataset folder `folder`; throws InputError as described above.
KittiSequence readKittiSequence(const std::string& folder, int sequence);

/// The label type's name as KITTI writes it ("Person_sitting").
std::string kittiLabelTypeName(KittiLabelType type);

}  // namespace semslam
