// `semslam convert kitti-tracking` (issue 11; docs/datasets.md, "KITTI tracking"): the frame conventions, the
// matching and the truth kinds on hand-made frames, the σ(r) covariance, byte-stable output, and bad input, on a
// small cut (the first frames) of sequence 0000 written to a temporary folder from ../shared/data (skipped where
// it is absent; nothing is copied into the repository).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "io/ConverterTesting.h"
#include "semslam/core/InputError.h"
#include "semslam/io/convert/KittiDetectionNoise.h"
#include "semslam/io/convert/KittiFrames.h"
#include "semslam/io/convert/KittiTrackingConverter.h"
#include "semslam/io/convert/KittiTrackingTruth.h"
#include "support/RunCommand.h"
#include "support/TestData.h"

using namespace semslam;
using semslam::test::TempDir;

namespace {

constexpr const char* kFolder = "kitti-tracking";
constexpr int kCutFrames = 120;

std::vector<std::string> lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

int frameOf(const std::string& line) { return std::stoi(line.substr(0, line.find_first_of(" ,"))); }

/// Writes the first kCutFrames frames of sequence 0000 into `dir`/cut, laid out as the dataset is; `edit` may change
/// the lines of a file (by its path relative to the folder) before they are written.
std::string writeCut(const std::filesystem::path& data, const TempDir& dir,
                     const std::map<std::string, std::function<void(std::vector<std::string>&)>>& edit = {}) {
  const std::filesystem::path cut = dir.path("cut");
  for (const std::string relative :
       {"label_02/0000.txt", "orbslam3_stereo_poses/0000.txt", "pointrcnn_detections/Car/0000.txt",
        "pointrcnn_detections/Pedestrian/0000.txt", "pointrcnn_detections/Cyclist/0000.txt"}) {
    std::vector<std::string> kept;
    const std::vector<std::string> all = lines(data / relative);
    for (std::size_t i = 0; i < all.size(); ++i) {
      const bool poses = relative.rfind("orbslam3", 0) == 0;
      if (poses ? i < static_cast<std::size_t>(kCutFrames) : frameOf(all[i]) < kCutFrames) kept.push_back(all[i]);
    }
    if (const auto e = edit.find(relative); e != edit.end()) e->second(kept);
    std::filesystem::create_directories((cut / relative).parent_path());
    std::ofstream out(cut / relative);
    for (const std::string& line : kept) out << line << "\n";
  }
  return cut.string();
}

ConvertOptions sequenceZero() {
  ConvertOptions options;
  options.kitti.sequence = 0;
  return options;
}

KittiLabel label(int frame, int track, KittiLabelType type, const Point3& camera) {
  KittiLabel l;
  l.frame = frame;
  l.track = track;
  l.type = type;
  l.box = {0.0, 0.0, 10.0, 10.0};
  l.bottomCentre = camera;
  return l;
}

KittiDetection detection(int frame, KittiClass c, const Point3& camera, std::array<double, 4> box = {500, 100, 510,
                                                                                                      110}) {
  KittiDetection d;
  d.frame = frame;
  d.detectedClass = c;
  d.bottomCentre = camera;
  d.box = box;
  d.score = 5.0;
  return d;
}

}  // namespace

TEST(KittiFrames, CameraToBodyRotationAndConjugatedPoses) {
  // Camera x right, y down, z forward → body x forward, y left, z up.
  EXPECT_TRUE(kittiBodyPoint(Point3(1.0, 2.0, 3.0)).isApprox(Point3(3.0, -1.0, -2.0), 0.0));
  EXPECT_NEAR(kittiCameraToBody().rotation().matrix().determinant(), 1.0, 1e-15);
  // A camera that moved 2 m forward (camera z) and turned left (about camera −y) moved 2 m along body x, turning
  // about body +z.
  const SE3 camera(SO3::fromAxisAngle(Vector3(0.0, -1.0, 0.0), 0.3), Point3(0.0, 0.0, 2.0));
  const SE3 body = kittiBodyPose(camera);
  EXPECT_TRUE(body.translation().isApprox(Point3(2.0, 0.0, 0.0), 1e-15));
  EXPECT_TRUE(body.rotation().matrix().isApprox(SO3::fromAxisAngle(Vector3::UnitZ(), 0.3).matrix(), 1e-15));
  // A point's world position is the same through the body pose and through the camera pose (rotated by S).
  const Point3 p(-4.5, 1.8, 13.4);
  EXPECT_TRUE(body.transformFrom(kittiBodyPoint(p)).isApprox(kittiBodyPoint(camera.transformFrom(p)), 1e-14));
}

TEST(KittiDetectionNoise, CovarianceIsAlignedToTheViewingRay) {
  const Vector3 p(6.0, 8.0, 0.0);  // r = 10
  const Matrix3 s = kittiDetectionCovariance(p);
  const double radial = kKittiRadialSigma.a + 10.0 * kKittiRadialSigma.b;
  const double lateral = kKittiLateralSigma.a + 10.0 * kKittiLateralSigma.b;
  const Vector3 u = p / 10.0, h(-0.8, 0.6, 0.0), v = Vector3::UnitZ();
  EXPECT_NEAR(u.dot(s * u), radial * radial, 1e-15);
  EXPECT_NEAR(h.dot(s * h), lateral * lateral, 1e-15);
  EXPECT_NEAR(v.dot(s * v), lateral * lateral, 1e-15);
  EXPECT_NEAR(u.dot(s * h), 0.0, 1e-15);
  EXPECT_EQ(s, s.transpose());
  // σ grows linearly with range.
  EXPECT_NEAR(std::sqrt(u.dot(kittiDetectionCovariance(6.0 * p) * u)), kKittiRadialSigma.at(60.0), 1e-15);
  EXPECT_THROW(kittiDetectionCovariance(Vector3::Zero()), std::invalid_argument);
}

TEST(KittiTrackingTruth, MatchingAndTruthKindsOnHandMadeFrames) {
  // Identity reference poses: world = camera frame rotated to body axes. Camera (x right, y down, z forward).
  const std::vector<SE3> poses(3, SE3());
  std::vector<KittiLabel> labels = {
      label(0, 1, KittiLabelType::Car, Point3(-3.0, 1.7, 10.0)),  // parked: the same position in frames 0-2
      label(1, 1, KittiLabelType::Car, Point3(-3.0, 1.7, 10.2)),
      label(2, 1, KittiLabelType::Car, Point3(-3.0, 1.7, 10.1)),
      label(0, 2, KittiLabelType::Car, Point3(3.0, 1.7, 12.0)),  // drives 8 m
      label(2, 2, KittiLabelType::Car, Point3(3.0, 1.7, 20.0)),
      label(0, 3, KittiLabelType::Car, Point3(0.0, 1.7, 25.0)),  // creeps 3 m
      label(2, 3, KittiLabelType::Car, Point3(0.0, 1.7, 28.0)),
      label(0, 4, KittiLabelType::Van, Point3(-3.0, 1.7, 18.0)),
      label(0, 5, KittiLabelType::Cyclist, Point3(1.5, 1.7, 6.0)),  // a parked bicycle
      label(1, 5, KittiLabelType::Cyclist, Point3(1.5, 1.7, 6.0)),
      label(0, -1, KittiLabelType::DontCare, Point3(-1000, -1000, -1000)),
  };
  labels.back().box = {800.0, 100.0, 900.0, 200.0};
  const std::vector<KittiDetection> detections = {
      detection(0, KittiClass::Car, Point3(-3.1, 1.7, 10.3)),   // 0: track 1 → landmark 1
      detection(0, KittiClass::Car, Point3(2.9, 1.7, 12.2)),    // 1: track 2 moves 8 m → not-a-landmark
      detection(0, KittiClass::Car, Point3(0.2, 1.7, 25.1)),    // 2: track 3 moves 3 m → unknown
      detection(0, KittiClass::Car, Point3(-3.0, 1.7, 17.5)),   // 3: on the Van → unknown
      detection(0, KittiClass::Pedestrian, Point3(1.4, 1.7, 6.1)),  // 4: a Pedestrian detection of the bicycle
      detection(0, KittiClass::Car, Point3(-3.0, 1.7, 11.8)),   // 5: second box near track 1, 1.8 m from it but
                                                                //    the label went to 0 → near-label, unknown
      detection(0, KittiClass::Car, Point3(10.0, 1.7, 15.0)),   // 6: nothing near → false positive
      detection(0, KittiClass::Car, Point3(-10.0, 1.7, 45.0)),  // 7: unlabelled range → unknown
      detection(0, KittiClass::Car, Point3(9.0, 1.7, 30.0), {820, 120, 840, 140}),  // 8: in the DontCare box
      detection(1, KittiClass::Cyclist, Point3(1.5, 1.7, 6.0)),  // 9: the bicycle again, right class
  };
  const std::map<int, KittiTrack> tracks = kittiTracks(labels, poses);
  EXPECT_NEAR(tracks.at(1).motion, 0.2, 1e-12);
  EXPECT_NEAR(tracks.at(2).motion, 8.0, 1e-12);
  EXPECT_NEAR(tracks.at(3).motion, 3.0, 1e-12);
  EXPECT_TRUE(tracks.at(1).meanPosition.isApprox(kittiBodyPoint(Point3(-3.0, 1.7, 10.1)), 1e-12));

  const std::vector<KittiDetectionTruth> t = kittiDetectionTruth(detections, labels, tracks);
  const std::vector<std::pair<KittiTruthKind, int>> expected = {
      {KittiTruthKind::Landmark, 1},           {KittiTruthKind::Moving, kNotALandmark},
      {KittiTruthKind::SlowTrack, kUnknownTruth}, {KittiTruthKind::OtherVehicle, kUnknownTruth},
      {KittiTruthKind::Landmark, 5},           {KittiTruthKind::NearLabel, kUnknownTruth},
      {KittiTruthKind::FalsePositive, kNotALandmark}, {KittiTruthKind::Unlabelled, kUnknownTruth},
      {KittiTruthKind::DontCare, kUnknownTruth},  {KittiTruthKind::Landmark, 5},
  };
  ASSERT_EQ(t.size(), expected.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_EQ(kittiTruthKindName(t[i].kind), kittiTruthKindName(expected[i].first)) << "detection " << i;
    EXPECT_EQ(t[i].truthId, expected[i].second) << "detection " << i;
  }
  // The confusion of detector class against label type: Car detections on the Car (0, 1, 2) and Van (3) rows, the
  // Pedestrian detection of the cyclist and the Cyclist one on the Cyclist row, four unmatched Car detections.
  const KittiLabelConfusion confusion = kittiLabelConfusion(detections, t, labels);
  const auto row = [&](KittiLabelType type) { return confusion[static_cast<std::size_t>(type)]; };
  using Row = std::array<std::size_t, kKittiClasses>;
  EXPECT_EQ(row(KittiLabelType::Car), (Row{3, 0, 0}));
  EXPECT_EQ(row(KittiLabelType::Van), (Row{1, 0, 0}));
  EXPECT_EQ(row(KittiLabelType::Cyclist), (Row{0, 1, 1}));
  EXPECT_EQ(row(KittiLabelType::DontCare), (Row{0, 0, 0}));
  EXPECT_EQ(confusion[kKittiLabelTypes], (Row{4, 0, 0}));
  std::size_t total = 0;
  for (const Row& r : confusion) total += r[0] + r[1] + r[2];
  EXPECT_EQ(total, detections.size());
}

TEST(KittiTrackingTruth, TheMatchingIsTheBestAssignmentNotGreedy) {
  // Two labels 1.6 m apart and two detections: detection 0 is nearest to label A (0.5 m) but also 1.1 m from B;
  // detection 1 is 0.6 m from A and 2.2 m from B. Greedy nearest-first gives 0→A and leaves 1 unmatched (B is
  // beyond the 2 m gate); the assignment gives 0→B, 1→A, both matched.
  const std::vector<SE3> poses(1, SE3());
  const std::vector<KittiLabel> labels = {label(0, 7, KittiLabelType::Car, Point3(0.0, 1.7, 10.0)),
                                          label(0, 8, KittiLabelType::Car, Point3(1.6, 1.7, 10.0))};
  const std::vector<KittiDetection> detections = {detection(0, KittiClass::Car, Point3(0.5, 1.7, 10.0)),
                                                  detection(0, KittiClass::Car, Point3(-0.6, 1.7, 10.0))};
  const std::vector<KittiDetectionTruth> t = kittiDetectionTruth(detections, labels, kittiTracks(labels, poses));
  EXPECT_EQ(t[0].truthId, 8);
  EXPECT_EQ(t[1].truthId, 7);
}

TEST(KittiTrackingConverter, DetectionsAndLabelsMeetInTheWorldThroughTheReferencePose) {
  SEMSLAM_REQUIRE_DATA(data, kFolder);
  TempDir dir;
  const std::string cut = writeCut(data, dir);
  ConversionStats stats;
  const MeasurementLog log = convertKittiTracking(cut, sequenceZero(), &stats);
  ASSERT_EQ(log.steps.size(), static_cast<std::size_t>(kCutFrames));
  EXPECT_EQ(log.header.dimension, 3);
  EXPECT_EQ(log.header.classes, 3);
  EXPECT_EQ(log.header.semantic, SemanticKind::Label);
  ASSERT_FALSE(log.header.landmarkTruth.empty());
  std::map<int, Point3> landmark;
  for (const LandmarkTruth& t : log.header.landmarkTruth) landmark[t.id] = std::get<Point3>(t.state);
  // Every landmark detection, through its step's reference pose, lands within the match gate of its track's mean
  // world position (the label's world positions, through the same poses); typically within a few decimetres.
  std::size_t checked = 0;
  double worst = 0.0;
  for (const TimeStep& step : log.steps) {
    const SE3& pose = std::get<SE3>(*step.truePose);
    for (const Detection& d : step.detections) {
      if (!d.truthId || *d.truthId < 0) continue;
      const Point3 world = pose.transformFrom(Point3(d.geometry));
      worst = std::max(worst, (world - landmark.at(*d.truthId)).norm());
      ++checked;
    }
  }
  EXPECT_GT(checked, 10u);  // 18 in the first 120 frames
  EXPECT_LT(worst, kKittiMatchGate);
  // The first reference pose is ORB-SLAM3's identity; odometry composes to the reference poses.
  EXPECT_TRUE(std::get<SE3>(*log.steps.front().truePose).equals(SE3(), 1e-8));
  SE3 dead = std::get<SE3>(*log.steps.front().truePose);
  for (std::size_t k = 1; k < log.steps.size(); ++k) dead = dead.compose(std::get<SE3>(log.steps[k].odometry->increment));
  EXPECT_TRUE(dead.equals(std::get<SE3>(*log.steps.back().truePose), 1e-9));
  ASSERT_EQ(stats.notes.size(), 3u);  // the truth kinds, the 3x3 confusion counts, the full confusion
  EXPECT_NE(stats.notes[2].find("confusion of detector class against label type"), std::string::npos);
  EXPECT_NE(stats.notes[2].find("; unmatched: "), std::string::npos);
  EXPECT_EQ(stats.notes[2].find("DontCare"), std::string::npos);
}

TEST(KittiTrackingConverter, SameArgumentsSameBytesAndSeededNoise) {
  SEMSLAM_REQUIRE_DATA(data, kFolder);
  TempDir dir;
  const std::string cut = writeCut(data, dir);
  ConvertOptions options = sequenceZero();
  const std::string a = test::writeAndReadBack(convertKittiTracking(cut, options), dir, "a.jsonl");
  const std::string b = test::writeAndReadBack(convertKittiTracking(cut, options), dir, "b.jsonl");
  EXPECT_TRUE(a == b);
  options.kitti.odometry = KittiTrackingOptions::Odometry::Noisy;
  options.kitti.odometryNoiseScale = 5.0;
  options.seed = 3;
  options.keyframePeriod = 1.0;
  MeasurementLog noisy;
  const std::string c = test::writeAndReadBack(convertKittiTracking(cut, options), dir, "c.jsonl", &noisy);
  EXPECT_TRUE(c == test::writeAndReadBack(convertKittiTracking(cut, options), dir, "d.jsonl"));
  options.seed = 4;
  EXPECT_FALSE(c == test::writeAndReadBack(convertKittiTracking(cut, options), dir, "e.jsonl"));
  EXPECT_EQ(noisy.steps.size(), 12u);  // 120 frames at 10 Hz, one keyframe per second
  // The stated covariance of a noisy one-frame increment is (1 + K²) Σ_orb, composed over the keyframe's frames.
  EXPECT_GT(noisy.steps[1].odometry->covariance(0, 0), 26.0 * 9.0 * kKittiOrbSlamSigmas[0] * kKittiOrbSlamSigmas[0]);
}

TEST(KittiTrackingConverter, BadInputNamesFileAndLineAndExitsTwo) {
  SEMSLAM_REQUIRE_DATA(data, kFolder);
  struct Case {
    const char* name;
    std::string file;
    std::function<void(std::vector<std::string>&)> edit;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"truncated detection line", "pointrcnn_detections/Car/0000.txt",
       [](std::vector<std::string>& l) { l[2] = l[2].substr(0, l[2].size() / 2); },
       "pointrcnn_detections/Car/0000.txt:3: expected 15 comma-separated numbers"},
      {"frame out of order", "label_02/0000.txt", [](std::vector<std::string>& l) { l[20] = "0" + l[20].substr(l[20].find(' ')); },
       "label_02/0000.txt:21: frame 0 after frame"},
      {"pose file shorter than the labels", "orbslam3_stereo_poses/0000.txt",
       [](std::vector<std::string>& l) { l.resize(20); }, "has no pose: "},
      {"unknown label type", "label_02/0000.txt",
       [](std::vector<std::string>& l) { l[4].replace(l[4].find("Pedestrian"), 10, "Bus"); },
       "label_02/0000.txt:5: unknown label type 'Bus'"},
      // The matching allocates detections x labels per frame: rows of one frame are bounded (issue 16).
      {"too many rows in one frame", "pointrcnn_detections/Car/0000.txt",
       [](std::vector<std::string>& l) { l.insert(l.end(), 1001, l.back()); }, "rows for frame 119"},
  };
  for (const Case& c : cases) {
    TempDir dir;
    const std::string cut = writeCut(data, dir, {{c.file, c.edit}});
    const auto run = test::runSemslam("convert kitti-tracking " + cut + " --sequence 0 --out " + dir.path("x.jsonl"));
    EXPECT_EQ(run.exitCode, 2) << c.name << ": " << run.output;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << c.name << ": " << run.output;
    EXPECT_THROW(convertKittiTracking(cut, sequenceZero()), InputError) << c.name;
  }
  // Options.
  TempDir dir;
  const std::string cut = writeCut(data, dir);
  for (const std::string& arguments :
       {std::string("--out ") + dir.path("x.jsonl"),  // no --sequence
        "--sequence 0 --odom-noise-scale 2 --out " + dir.path("x.jsonl"),  // noise scale without noisy odometry
        "--sequence 0 --classes 3 --out " + dir.path("x.jsonl"),           // the detector's labels are kept
        "--sequence 7 --out " + dir.path("x.jsonl")}) {                    // not in the folder
    const auto run = test::runSemslam("convert kitti-tracking " + cut + " " + arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
  }
}
