#include "semslam/io/convert/KittiTrackingFiles.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "semslam/core/InputError.h"
#include "semslam/core/InputFile.h"
#include "semslam/core/InputExcerpt.h"
#include "semslam/io/KittiFormat.h"
#include "semslam/io/NumericTable.h"
#include "semslam/io/NumericTable.h"
#include "semslam/io/convert/ConversionCommon.h"

namespace semslam {

namespace {

constexpr std::size_t kLabelFields = 17;
constexpr std::size_t kDetectionFields = 15;

KittiLabelType parseLabelType(const std::string& path, std::size_t line, const std::string& text) {
  static const std::array<std::pair<const char*, KittiLabelType>, 9> kTypes = {{
      {"Car", KittiLabelType::Car},
      {"Van", KittiLabelType::Van},
      {"Truck", KittiLabelType::Truck},
      {"Pedestrian", KittiLabelType::Pedestrian},
      {"Person_sitting", KittiLabelType::PersonSitting},
      {"Cyclist", KittiLabelType::Cyclist},
      {"Tram", KittiLabelType::Tram},
      {"Misc", KittiLabelType::Misc},
      {"DontCare", KittiLabelType::DontCare},
  }};
  for (const auto& [name, type] : kTypes) {
    if (text == name) return type;
  }
  throw InputError(path, line,
                   "unknown label type " + inputExcerpt(text) +
                       " (expected Car, Van, Truck, Pedestrian, Person_sitting, Cyclist, Tram, Misc or DontCare)");
}

double parseNumber(const std::string& path, std::size_t line, const std::string& text, const char* name) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw InputError(path, line, std::string(name) + ": " + inputExcerpt(text) + " is not a finite number");
  }
  return value;
}

/// A frame number: an integer ≥ 0 that is not smaller than the previous row's, and that has a pose.
int frameField(const std::string& path, std::size_t line, double value, int previous, std::size_t poses,
               const std::string& posePath) {
  if (value != std::floor(value) || value < 0.0 || value > 1e7) {
    std::ostringstream problem;
    problem << "frame " << value << " is not an integer >= 0";
    throw InputError(path, line, problem.str());
  }
  const int frame = static_cast<int>(value);
  if (frame < previous) {
    throw InputError(path, line,
                     "frame " + std::to_string(frame) + " after frame " + std::to_string(previous) +
                         " (rows must be in frame order)");
  }
  if (static_cast<std::size_t>(frame) >= poses) {
    throw InputError(path, line,
                     "frame " + std::to_string(frame) + " has no pose: " + posePath + " has " + std::to_string(poses) +
                         " lines (one per frame)");
  }
  return frame;
}

/// Counts the rows of one file per frame (rows come in frame order) and refuses the row past kMaxKittiRowsPerFrame.
class RowsPerFrame {
 public:
  void count(const std::string& path, std::size_t line, int frame) {
    rows_ = frame == frame_ ? rows_ + 1 : 1;
    frame_ = frame;
    if (rows_ > kMaxKittiRowsPerFrame) {
      throw InputError(path, line,
                       "more than " + std::to_string(kMaxKittiRowsPerFrame) + " rows for frame " +
                           std::to_string(frame) + " (the most accepted in one frame)");
    }
  }

 private:
  int frame_ = -1;
  std::size_t rows_ = 0;
};

std::vector<KittiLabel> readLabels(const std::string& path, std::size_t poses, const std::string& posePath) {
  std::ifstream in = openInputFile(path);
  std::vector<KittiLabel> labels;
  std::string text;
  std::size_t line = 0;
  int previous = 0;
  RowsPerFrame rowsPerFrame;
  static const char* const kNames[kLabelFields] = {"frame", "track_id", "type",  "truncated", "occluded", "alpha",
                                                   "x1",    "y1",       "x2",    "y2",        "h",        "w",
                                                   "l",     "X",        "Y",     "Z",         "rotation_y"};
  while (readBoundedLine(in, text, path, line + 1)) {
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::istringstream fields(text);
    std::vector<std::string> field;
    for (std::string f; fields >> f;) field.push_back(f);
    if (field.empty() || field[0][0] == '#') continue;
    if (field.size() != kLabelFields) {
      throw InputError(path, line,
                       "expected 17 fields (frame track_id type truncated occluded alpha x1 y1 x2 y2 h w l X Y Z "
                       "rotation_y), found " +
                           std::to_string(field.size()));
    }
    std::array<double, kLabelFields> value{};
    for (std::size_t i = 0; i < kLabelFields; ++i) {
      if (i != 2) value[i] = parseNumber(path, line, field[i], kNames[i]);
    }
    KittiLabel label;
    label.line = line;
    label.frame = frameField(path, line, value[0], previous, poses, posePath);
    rowsPerFrame.count(path, line, label.frame);
    previous = label.frame;
    label.type = parseLabelType(path, line, field[2]);
    if (value[1] != std::floor(value[1]) || value[1] < -1.0 || value[1] > 1e9) {
      throw InputError(path, line, "track_id " + field[1] + " is not an integer >= -1");
    }
    label.track = static_cast<int>(value[1]);
    if ((label.track < 0) != (label.type == KittiLabelType::DontCare)) {
      throw InputError(path, line, "track_id " + field[1] + " with type " + field[2] +
                                       " (DontCare regions, and only they, have track_id -1)");
    }
    label.box = {value[6], value[7], value[8], value[9]};
    label.bottomCentre = Point3(value[13], value[14], value[15]);
    labels.push_back(label);
  }
  if (labels.empty()) throw InputError(path, 0, "no labels");
  return labels;
}

void readDetections(const std::string& path, KittiClass detectedClass, std::size_t poses, const std::string& posePath,
                    std::vector<KittiDetection>& detections) {
  // Detection type codes of the files: 1 Pedestrian, 2 Car, 3 Cyclist.
  const int expectedType = detectedClass == KittiClass::Car ? 2 : detectedClass == KittiClass::Pedestrian ? 1 : 3;
  int previous = 0;
  RowsPerFrame rowsPerFrame;
  for (const NumericRow& row : readNumericTable(path, Separator::Comma)) {
    if (row.values.size() != kDetectionFields) {
      throw InputError(path, row.line,
                       "expected 15 comma-separated numbers (frame, type, x1, y1, x2, y2, score, h, w, l, x, y, z, "
                       "rot_y, alpha), found " +
                           std::to_string(row.values.size()));
    }
    KittiDetection detection;
    detection.line = row.line;
    detection.frame = frameField(path, row.line, row.values[0], previous, poses, posePath);
    rowsPerFrame.count(path, row.line, detection.frame);
    previous = detection.frame;
    const int type = integerField(path, row, 1, "type", 1, 3);
    if (type != expectedType) {
      throw InputError(path, row.line,
                       "type " + std::to_string(type) + " in the " +
                           kittiClassNames()[static_cast<std::size_t>(detectedClass)] + " file (expected " +
                           std::to_string(expectedType) + ")");
    }
    detection.detectedClass = detectedClass;
    detection.box = {row.values[2], row.values[3], row.values[4], row.values[5]};
    detection.score = row.values[6];
    detection.bottomCentre = Point3(row.values[10], row.values[11], row.values[12]);
    // Its covariance grows with its direction and range from the camera (KittiDetectionNoise.h): none at the
    // camera, and a log's coordinates are at most 1e7 (docs/measurement-log.md, "Limits").
    if (detection.bottomCentre.cwiseAbs().maxCoeff() > kMaxKittiCoordinate) {
      throw InputError(path, row.line, "the position (x, y, z) is too large: at most 1e7 m in magnitude");
    }
    if (detection.bottomCentre.norm() == 0.0) {
      throw InputError(path, row.line, "the position (x, y, z) is at the camera (0, 0, 0): a detection has a direction");
    }
    detections.push_back(detection);
  }
}

}  // namespace

const std::array<std::string, kKittiClasses>& kittiClassNames() {
  static const std::array<std::string, kKittiClasses> names = {"Car", "Pedestrian", "Cyclist"};
  return names;
}

std::string kittiLabelTypeName(KittiLabelType type) {
  switch (type) {
    case KittiLabelType::Car: return "Car";
    case KittiLabelType::Van: return "Van";
    case KittiLabelType::Truck: return "Truck";
    case KittiLabelType::Pedestrian: return "Pedestrian";
    case KittiLabelType::PersonSitting: return "Person_sitting";
    case KittiLabelType::Cyclist: return "Cyclist";
    case KittiLabelType::Tram: return "Tram";
    case KittiLabelType::Misc: return "Misc";
    case KittiLabelType::DontCare: return "DontCare";
  }
  return "?";
}

std::string kittiSequenceName(int sequence) {
  char name[16];
  std::snprintf(name, sizeof name, "%04d", sequence);
  return name;
}

KittiSequence readKittiSequence(const std::string& folder, int sequence) {
  if (sequence < 0 || sequence > 9999) {
    throw InputError("--sequence must be a KITTI tracking sequence number 0..9999, got " + std::to_string(sequence));
  }
  const std::string name = kittiSequenceName(sequence) + ".txt";
  KittiSequence s;
  s.posePath = datasetFile(folder, "orbslam3_stereo_poses/" + name);
  s.labelPath = datasetFile(folder, "label_02/" + name);
  for (int c = 0; c < kKittiClasses; ++c) {
    s.detectionPaths[static_cast<std::size_t>(c)] =
        datasetFile(folder, "pointrcnn_detections/" + kittiClassNames()[static_cast<std::size_t>(c)] + "/" + name);
  }
  const Trajectory poses = readKittiTrajectory(s.posePath);
  s.cameraToWorld.reserve(poses.size());
  for (const SE3& pose : poses.poses()) {
    // KITTI prints the rotation with 9 digits: project it onto SO(3) so that composing and inverting agree.
    s.cameraToWorld.emplace_back(SO3::nearest(pose.rotation().matrix()), pose.translation());
  }
  // The trajectory reader reads the same data rows (io/TrajectoryTable.cpp), one pose each.
  for (const NumericRow& row : readNumericTable(s.posePath, Separator::Whitespace)) s.poseLines.push_back(row.line);
  s.labels = readLabels(s.labelPath, s.cameraToWorld.size(), s.posePath);
  for (int c = 0; c < kKittiClasses; ++c) {
    readDetections(s.detectionPaths[static_cast<std::size_t>(c)], static_cast<KittiClass>(c), s.cameraToWorld.size(),
                   s.posePath, s.detections);
  }
  return s;
}

}  // namespace semslam
