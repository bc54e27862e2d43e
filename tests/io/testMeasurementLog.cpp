// Measurement log files: write -> read round trips (2D and 3D, every sensor and semantic kind, priors and ground
// truth), byte-identical re-writing, the streaming reader, the writer's own validation, and the specification's
// example.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>

#include "IoTesting.h"
#include "semslam/io/MeasurementLogFile.h"

namespace semslam {
namespace {

using test::readText;
using test::TempDir;

// ---- building logs ----

Matrix spd(int n, std::mt19937& rng, double scale = 0.01) {
  std::normal_distribution<double> normal;
  Matrix a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a(i, j) = normal(rng);
  const Matrix m = scale * (a * a.transpose() + Matrix::Identity(n, n));
  return 0.5 * (m + m.transpose());  // exactly symmetric
}

SE3 randomSE3(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  const Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return SE3(SO3::fromQuaternion(q), Point3(normal(rng), normal(rng), normal(rng)));
}

SE2 randomSE2(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  return SE2(normal(rng), normal(rng), angle(rng));
}

Vector simplex(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> uniform(0.01, 1.0);
  Vector v(n);
  for (int i = 0; i < n; ++i) v(i) = uniform(rng);
  return v / v.sum();
}

Vector scores(int n, std::mt19937& rng) {
  std::normal_distribution<double> normal(0.3, 0.5);  // leaves the simplex: negative entries, sums != 1
  Vector v(n);
  for (int i = 0; i < n; ++i) v(i) = normal(rng);
  return v;
}

/// A 2D log with a range-bearing sensor, every kind of ground truth and priors, and the given semantics.
MeasurementLog makeLog2(SemanticKind semantic, unsigned seed = 7) {
  std::mt19937 rng(seed);
  MeasurementLog log;
  LogHeader& h = log.header;
  h.dimension = 2;
  h.classes = 3;
  h.semantic = semantic;
  if (semantic == SemanticKind::Label || semantic == SemanticKind::Probabilities) {
    h.classifier.kind = ClassifierModelSpec::Kind::Categorical;
    h.classifier.misclassification = 0.1;
  } else if (semantic == SemanticKind::Scores) {
    h.classifier.kind = ClassifierModelSpec::Kind::ViewpointGaussian;
    h.classifier.alpha = 0.25;
    h.classifier.sharpness = 15.0;
    h.classifier.table = "models/classifier table.csv";
  }
  h.sensor.kind = SensorKind::RangeBearing;
  h.sensor.bodyToSensor = SE2(0.1, -0.02, 0.3);
  h.sensor.maxRange = 12.5;
  h.sensor.fieldOfView = std::numbers::pi / 1.5;
  h.initialPose = PosePrior{SE2(0.5, -1.0 / 3.0, 0.25), spd(3, rng, 1e-4)};
  h.landmarkPriors.push_back(LandmarkPrior{4, Point2(2.0, 1.0 / 7.0), spd(2, rng)});
  h.landmarkPriors.push_back(LandmarkPrior{9, Point2(-0.0, 1e-300), spd(2, rng, 1e6)});
  h.landmarkTruth.push_back(LandmarkTruth{4, 2, Point2(2.0, 0.1 + 0.2)});
  h.landmarkTruth.push_back(LandmarkTruth{9, -1, Point2(6.02214076e6, -1.5)});
  h.landmarkTruth.push_back(LandmarkTruth{0, 0, Point2(0.0, 0.0)});
  h.source = "unit test \"quoted\", ünïcödé and a tab\t";
  for (int k = 0; k < 6; ++k) {
    TimeStep step;
    step.time = 1700000000.123456789 + 0.1 * k;
    if (k > 0) step.odometry = Odometry{SE2(0.1 * k, 0.01, -0.05 * k), spd(3, rng)};
    for (int d = 0; d < k % 3; ++d) {
      Detection detection;
      detection.geometry = Vector2(0.5 + d + 1e-9 * k, -1.2 + 0.7 * d);
      detection.covariance = spd(2, rng, 1e-3);
      if (semantic == SemanticKind::Label) detection.label = (k + d) % 3;
      if (semantic == SemanticKind::Probabilities) detection.classVector = simplex(3, rng);
      if (semantic == SemanticKind::Scores) detection.classVector = scores(3, rng);
      if (d == 0) detection.truthId = k % 2 == 0 ? 4 : 9;
      if (d == 1 && k == 5) detection.truthId = kNotALandmark;
      if (d == 1 && k == 2) detection.truthId = kUnknownTruth;
      step.detections.push_back(detection);
    }
    if (k % 2 == 0) step.truePose = randomSE2(rng);
    log.steps.push_back(step);
  }
  return log;
}

/// A 3D log whose landmarks are poses, with the given sensor.
MeasurementLog makeLog3(SensorKind sensor, SemanticKind semantic, unsigned seed = 11) {
  std::mt19937 rng(seed);
  MeasurementLog log;
  LogHeader& h = log.header;
  h.dimension = 3;
  h.classes = 4;
  h.semantic = semantic;
  if (semantic == SemanticKind::Scores) {
    h.classifier.kind = ClassifierModelSpec::Kind::ViewpointGaussian;
    h.classifier.alpha = 0.5;
    h.classifier.sharpness = 3.0;
  }
  h.sensor.kind = sensor;
  h.sensor.bodyToSensor = randomSE3(rng);
  h.landmarksHavePose = true;
  h.initialPose = PosePrior{randomSE3(rng), spd(6, rng, 1e-6)};
  h.landmarkPriors.push_back(LandmarkPrior{1, randomSE3(rng), spd(6, rng)});
  h.landmarkTruth.push_back(LandmarkTruth{1, 3, randomSE3(rng)});
  h.landmarkTruth.push_back(LandmarkTruth{2, -1, randomSE3(rng)});
  for (int k = 0; k < 5; ++k) {
    TimeStep step;
    step.time = -2.5 + k / 3.0;
    if (k > 0) step.odometry = Odometry{randomSE3(rng), spd(6, rng)};
    for (int d = 0; d < 2; ++d) {
      Detection detection;
      switch (sensor) {
        case SensorKind::RangeBearingElevation:
          detection.geometry = Vector3(3.0 + d, 0.4 * d - 2.0, 0.1 * k - 0.3);
          detection.covariance = spd(3, rng);
          break;
        case SensorKind::RelativePosition:
          detection.geometry = Vector3(1.0 / 3.0, -2.0, 0.5 * d);
          detection.covariance = spd(3, rng);
          break;
        case SensorKind::RelativePose: {
          const Eigen::Quaterniond q = randomSE3(rng).rotation().toQuaternion();
          detection.geometry.resize(7);
          detection.geometry << 1.0, 2.0, 3.0 + d, q.x(), q.y(), q.z(), -q.w();  // w < 0 is allowed
          detection.covariance = spd(6, rng);
          break;
        }
        case SensorKind::RangeBearing:
          break;
      }
      if (semantic == SemanticKind::Probabilities) detection.classVector = simplex(4, rng);
      if (semantic == SemanticKind::Scores) detection.classVector = scores(4, rng);
      if (semantic == SemanticKind::Label) detection.label = d;
      detection.truthId = d == 0 ? 2 : kNotALandmark;
      step.detections.push_back(detection);
    }
    step.truePose = randomSE3(rng);
    log.steps.push_back(step);
  }
  return log;
}

// ---- comparing logs ----

// A rotation built in memory moves on its first write: an SE2 angle by about one rounding step, an SE3 rotation by a
// few tens (its quaternion is chosen on a cycle of quaternion -> matrix -> quaternion, see MeasurementLogJson.cpp).
constexpr double kRotationTolerance2 = 4e-16;
constexpr double kRotationTolerance3 = 1e-13;

void expectExact(const Matrix& a, const Matrix& b, const std::string& what) {
  ASSERT_EQ(a.rows(), b.rows()) << what;
  ASSERT_EQ(a.cols(), b.cols()) << what;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    // Bitwise, so that -0.0 and 0.0 differ.
    EXPECT_EQ(std::signbit(a.data()[i]), std::signbit(b.data()[i])) << what << " entry " << i;
    EXPECT_EQ(a.data()[i], b.data()[i]) << what << " entry " << i;
  }
}

/// Translations exactly; rotations to kRotationTolerance2/3 (they pass through an angle or a quaternion), or exactly.
void expectPose(const Pose& a, const Pose& b, const std::string& what, bool exact) {
  ASSERT_EQ(a.index(), b.index()) << what;
  const double tolerance = exact ? 0.0 : a.index() == 0 ? kRotationTolerance2 : kRotationTolerance3;
  if (const auto* p = std::get_if<SE2>(&a)) {
    const SE2& q = std::get<SE2>(b);
    expectExact(p->translation(), q.translation(), what);
    EXPECT_NEAR(p->rotation().c(), q.rotation().c(), tolerance) << what;
    EXPECT_NEAR(p->rotation().s(), q.rotation().s(), tolerance) << what;
  } else {
    const SE3& p3 = std::get<SE3>(a);
    const SE3& q3 = std::get<SE3>(b);
    expectExact(p3.translation(), q3.translation(), what);
    EXPECT_LE((p3.rotation().matrix() - q3.rotation().matrix()).cwiseAbs().maxCoeff(), tolerance) << what;
  }
}

void expectLandmark(const LandmarkState& a, const LandmarkState& b, const std::string& what, bool exact) {
  ASSERT_EQ(a.index(), b.index()) << what;
  if (const auto* p = std::get_if<Point2>(&a)) return expectExact(*p, std::get<Point2>(b), what);
  if (const auto* p = std::get_if<Point3>(&a)) return expectExact(*p, std::get<Point3>(b), what);
  if (const auto* p = std::get_if<SE2>(&a)) return expectPose(*p, Pose(std::get<SE2>(b)), what, exact);
  expectPose(std::get<SE3>(a), Pose(std::get<SE3>(b)), what, exact);
}

void expectLogsEqual(const MeasurementLog& a, const MeasurementLog& b, bool exactRotations) {
  const LogHeader& x = a.header;
  const LogHeader& y = b.header;
  EXPECT_EQ(y.version, kMeasurementLogVersion);
  EXPECT_EQ(x.dimension, y.dimension);
  EXPECT_EQ(x.classes, y.classes);
  EXPECT_EQ(x.semantic, y.semantic);
  EXPECT_EQ(x.classifier.kind, y.classifier.kind);
  if (x.classifier.kind == ClassifierModelSpec::Kind::Categorical) {
    EXPECT_EQ(x.classifier.misclassification, y.classifier.misclassification);
  }
  if (x.classifier.kind == ClassifierModelSpec::Kind::ViewpointGaussian) {
    EXPECT_EQ(x.classifier.alpha, y.classifier.alpha);
    EXPECT_EQ(x.classifier.sharpness, y.classifier.sharpness);
  }
  EXPECT_EQ(x.classifier.table, y.classifier.table);
  EXPECT_EQ(x.sensor.kind, y.sensor.kind);
  expectPose(x.sensor.bodyToSensor, y.sensor.bodyToSensor, "body_to_sensor", exactRotations);
  EXPECT_EQ(x.sensor.maxRange, y.sensor.maxRange);
  EXPECT_EQ(x.sensor.fieldOfView, y.sensor.fieldOfView);
  EXPECT_EQ(x.landmarksHavePose, y.landmarksHavePose);
  ASSERT_EQ(x.initialPose.has_value(), y.initialPose.has_value());
  if (x.initialPose) {
    expectPose(x.initialPose->mean, y.initialPose->mean, "initial pose", exactRotations);
    expectExact(x.initialPose->covariance, y.initialPose->covariance, "initial pose covariance");
  }
  ASSERT_EQ(x.landmarkPriors.size(), y.landmarkPriors.size());
  for (std::size_t i = 0; i < x.landmarkPriors.size(); ++i) {
    EXPECT_EQ(x.landmarkPriors[i].id, y.landmarkPriors[i].id);
    expectLandmark(x.landmarkPriors[i].mean, y.landmarkPriors[i].mean, "prior mean", exactRotations);
    expectExact(x.landmarkPriors[i].covariance, y.landmarkPriors[i].covariance, "prior covariance");
  }
  ASSERT_EQ(x.landmarkTruth.size(), y.landmarkTruth.size());
  for (std::size_t i = 0; i < x.landmarkTruth.size(); ++i) {
    EXPECT_EQ(x.landmarkTruth[i].id, y.landmarkTruth[i].id);
    EXPECT_EQ(x.landmarkTruth[i].classIndex, y.landmarkTruth[i].classIndex);
    expectLandmark(x.landmarkTruth[i].state, y.landmarkTruth[i].state, "landmark truth", exactRotations);
  }
  EXPECT_EQ(x.source, y.source);
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    const TimeStep& s = a.steps[k];
    const TimeStep& t = b.steps[k];
    const std::string where = "step " + std::to_string(k);
    EXPECT_EQ(s.time, t.time) << where;
    ASSERT_EQ(s.odometry.has_value(), t.odometry.has_value()) << where;
    if (s.odometry) {
      expectPose(s.odometry->increment, t.odometry->increment, where + " odometry", exactRotations);
      expectExact(s.odometry->covariance, t.odometry->covariance, where + " odometry covariance");
    }
    ASSERT_EQ(s.truePose.has_value(), t.truePose.has_value()) << where;
    if (s.truePose) expectPose(*s.truePose, *t.truePose, where + " true pose", exactRotations);
    ASSERT_EQ(s.detections.size(), t.detections.size()) << where;
    for (std::size_t d = 0; d < s.detections.size(); ++d) {
      const Detection& u = s.detections[d];
      const Detection& v = t.detections[d];
      const std::string at = where + " detection " + std::to_string(d);
      expectExact(u.geometry, v.geometry, at + " geometry");
      expectExact(u.covariance, v.covariance, at + " covariance");
      EXPECT_EQ(u.label, v.label) << at;
      ASSERT_EQ(u.classVector.has_value(), v.classVector.has_value()) << at;
      if (u.classVector) expectExact(*u.classVector, *v.classVector, at + " class vector");
      EXPECT_EQ(u.truthId, v.truthId) << at;
    }
  }
}

/// write -> read equals the log; writing what was read gives the same bytes; reading that again is exact.
void expectRoundTrip(const MeasurementLog& log) {
  TempDir dir;
  const std::string first = dir.path("first.jsonl");
  const std::string second = dir.path("second.jsonl");
  writeMeasurementLog(first, log);
  const MeasurementLog read = readMeasurementLog(first);
  expectLogsEqual(log, read, false);
  writeMeasurementLog(second, read);
  EXPECT_EQ(readText(first), readText(second)) << "re-writing a read log changed its bytes";
  expectLogsEqual(read, readMeasurementLog(second), true);
  EXPECT_FALSE(std::filesystem::exists(first + ".tmp"));
}

// ---- round trips ----

TEST(MeasurementLogFile, RoundTrip2dEverySemanticKind) {
  for (SemanticKind semantic :
       {SemanticKind::None, SemanticKind::Label, SemanticKind::Probabilities, SemanticKind::Scores}) {
    SCOPED_TRACE(std::string(semanticKindName(semantic)));
    expectRoundTrip(makeLog2(semantic));
  }
}

TEST(MeasurementLogFile, RoundTrip3dEverySensorKind) {
  for (SensorKind sensor : {SensorKind::RangeBearingElevation, SensorKind::RelativePosition, SensorKind::RelativePose}) {
    SCOPED_TRACE(std::string(sensorKindName(sensor)));
    expectRoundTrip(makeLog3(sensor, SemanticKind::Scores));
  }
  expectRoundTrip(makeLog3(SensorKind::RelativePose, SemanticKind::Probabilities));
  expectRoundTrip(makeLog3(SensorKind::RelativePosition, SemanticKind::Label));
  expectRoundTrip(makeLog3(SensorKind::RangeBearingElevation, SemanticKind::None));
}

TEST(MeasurementLogFile, RoundTrip2dPoseLandmarksAndRelativeSensors) {
  MeasurementLog log = makeLog2(SemanticKind::Probabilities);
  log.header.landmarksHavePose = true;
  log.header.sensor.kind = SensorKind::RelativePose;
  for (auto& prior : log.header.landmarkPriors) {
    prior.mean = SE2(1.0, 2.0, -3.0);
    prior.covariance = Matrix::Identity(3, 3);
  }
  for (auto& truth : log.header.landmarkTruth) truth.state = SE2(truth.id, -0.5, 0.1 * truth.id);
  for (auto& step : log.steps) {
    for (auto& detection : step.detections) {
      detection.geometry = Vector3(1.5, -0.25, 3.0);  // theta beyond pi is kept as written
      detection.covariance = Matrix::Identity(3, 3) * 0.01;
    }
  }
  expectRoundTrip(log);

  MeasurementLog points = makeLog2(SemanticKind::Label);
  points.header.sensor.kind = SensorKind::RelativePosition;
  points.header.initialPose.reset();
  points.header.landmarkPriors.clear();
  points.header.landmarkTruth.clear();  // detection truth ids then need no landmark list
  points.header.source.clear();
  points.header.classifier = ClassifierModelSpec{};
  expectRoundTrip(points);
}

TEST(MeasurementLogFile, ManyRandomRotationsRewriteByteIdentically) {
  // The rotation fields are the ones that pass through a representation change (cos/sin, rotation matrix).
  std::mt19937 rng(2024);
  const int kSteps = 1000;  // checked once with 20000
  for (int dimension : {2, 3}) {
    MeasurementLog log = dimension == 2 ? makeLog2(SemanticKind::None) : makeLog3(SensorKind::RelativePosition,
                                                                                   SemanticKind::None);
    const TimeStep last = log.steps.back();
    for (int k = 0; k < kSteps; ++k) {
      TimeStep step = last;
      step.time = last.time + k + 1;
      step.detections.clear();
      if (dimension == 2) {
        step.odometry->increment = randomSE2(rng) * randomSE2(rng);  // composed: no exact angle in general
        step.truePose = SE2(0.0, 0.0, std::numbers::pi * (k % 2 ? 1 : -1) * (1.0 - k * 1e-17));
      } else {
        step.odometry->increment = randomSE3(rng) * randomSE3(rng);
        step.truePose = SE3(SO3::fromAxisAngle(Vector3(1.0, -2.0, 0.5), std::numbers::pi - k * 1e-10), Point3::Zero());
      }
      log.steps.push_back(step);
    }
    expectRoundTrip(log);
  }
}

TEST(MeasurementLogFile, DeterministicBytesAndLayout) {
  TempDir dir;
  const MeasurementLog log = makeLog2(SemanticKind::Label);
  writeMeasurementLog(dir.path("a.jsonl"), log);
  writeMeasurementLog(dir.path("b.jsonl"), log);
  const std::string text = readText(dir.path("a.jsonl"));
  EXPECT_EQ(text, readText(dir.path("b.jsonl")));
  // One JSON object per line, header first, keys in the specification's order.
  std::istringstream lines(text);
  std::string line;
  std::vector<std::string> all;
  while (std::getline(lines, line)) all.push_back(line);
  ASSERT_EQ(all.size(), log.steps.size() + 1);
  EXPECT_EQ(all[0].rfind(R"({"format":"semslam-log","version":2,"dimension":2,"classes":3,"semantic":"label",)", 0),
            0u)
      << all[0];
  EXPECT_EQ(all[1].rfind(R"({"time":)", 0), 0u) << all[1];
  EXPECT_NE(all[2].find(R"(,"odometry":{"increment":[)"), std::string::npos) << all[2];
  EXPECT_NE(text.find(R"("truth":"not-a-landmark")"), std::string::npos);
  EXPECT_NE(text.find(R"("truth":"unknown")"), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
}

TEST(MeasurementLogFile, StreamingReaderMatchesWholeFileReader) {
  TempDir dir;
  const std::string path = dir.path("log.jsonl");
  const MeasurementLog log = makeLog3(SensorKind::RangeBearingElevation, SemanticKind::Scores);
  writeMeasurementLog(path, log);
  const MeasurementLog whole = readMeasurementLog(path);
  MeasurementLogReader reader(path);
  EXPECT_EQ(reader.path(), path);
  EXPECT_EQ(reader.lineNumber(), 1u);
  EXPECT_EQ(reader.header().classes, 4);
  MeasurementLog streamed;
  streamed.header = reader.header();
  TimeStep step;
  while (reader.next(step)) {
    streamed.steps.push_back(step);
    EXPECT_EQ(reader.lineNumber(), streamed.steps.size() + 1);
  }
  EXPECT_EQ(reader.stepsRead(), log.steps.size());
  EXPECT_FALSE(reader.next(step));
  expectLogsEqual(whole, streamed, true);
}

TEST(MeasurementLogFile, AcceptsBlankLinesCrlfAndIntegerNumbers) {
  TempDir dir;
  const std::string path = dir.write(
      "crlf.jsonl",
      "{\"format\":\"semslam-log\",\"version\":1,\"dimension\":2,\"classes\":1,\"semantic\":\"none\","
      "\"sensor\":{\"kind\":\"relative-position\"}}\r\n"
      "\r\n"
      "  \n"
      "{ \"time\" : 0 , \"detections\" : [ { \"geometry\" : [1, 2], \"covariance\" : [[1, 0], [0, 1]] } ] }\r\n"
      "{\"time\":1,\"odometry\":{\"increment\":[1,0,0],\"covariance\":[[1,0,0],[0,1,0],[0,0,1]]},"
      "\"detections\":[]}");  // no final newline
  const MeasurementLog log = readMeasurementLog(path);
  ASSERT_EQ(log.steps.size(), 2u);
  EXPECT_EQ(log.header.classifier.kind, ClassifierModelSpec::Kind::None);  // optional, "none" when absent
  EXPECT_FALSE(log.header.landmarksHavePose);
  EXPECT_TRUE(std::get<SE2>(log.header.sensor.bodyToSensor).equals(SE2()));
  EXPECT_EQ(log.header.sensor.maxRange, 0.0);
  EXPECT_EQ(log.steps[0].detections[0].geometry, Vector2(1.0, 2.0));
  EXPECT_EQ(log.steps[1].time, 1.0);
  EXPECT_FALSE(log.steps[0].detections[0].truthId.has_value());
}

TEST(MeasurementLogFile, SymmetrisesCovariancesWithinTolerance) {
  TempDir dir;
  const std::string path = dir.write(
      "nearly.jsonl",
      "{\"format\":\"semslam-log\",\"version\":1,\"dimension\":2,\"classes\":1,\"semantic\":\"none\","
      "\"sensor\":{\"kind\":\"range-bearing\"}}\n"
      "{\"time\":0,\"detections\":[{\"geometry\":[1,0],\"covariance\":[[2,0.5],[0.5000000000001,1]]}]}\n");
  const Matrix c = readMeasurementLog(path).steps[0].detections[0].covariance;
  EXPECT_EQ(c(0, 1), c(1, 0));
  EXPECT_NEAR(c(0, 1), 0.5, 1e-12);
}

TEST(MeasurementLogFile, SpecificationExampleIsValid) {
  // The example of docs/measurement-log.md: the first ```jsonl block.
  std::ifstream doc(std::string(SEMSLAM_SOURCE_DIR) + "/docs/measurement-log.md");
  ASSERT_TRUE(doc) << "docs/measurement-log.md not found";
  std::string line, example;
  bool inside = false, found = false;
  while (std::getline(doc, line)) {
    if (!found && !inside && line == "```jsonl") {
      inside = true;
    } else if (inside && line == "```") {
      inside = false;
      found = true;
    } else if (inside) {
      example += line + "\n";
    }
  }
  ASSERT_TRUE(found);
  TempDir dir;
  const std::string path = dir.write("example.jsonl", example);
  const MeasurementLog log = readMeasurementLog(path);
  EXPECT_EQ(log.header.dimension, 2);
  EXPECT_EQ(log.steps.size(), 3u);
  // Written back in the writer's canonical form, it still reads the same.
  writeMeasurementLog(dir.path("again.jsonl"), log);
  expectLogsEqual(log, readMeasurementLog(dir.path("again.jsonl")), false);
}

// ---- the writer validates ----

void expectWriteRejected(const MeasurementLog& log, const std::string& part) {
  TempDir dir;
  const std::string path = dir.write("existing.jsonl", "previous contents\n");
  try {
    writeMeasurementLog(path, log);
    ADD_FAILURE() << "expected std::invalid_argument containing \"" << part << "\"";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
  EXPECT_EQ(readText(path), "previous contents\n") << "a rejected write must leave the file untouched";
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST(MeasurementLogFile, WriterRejectsWhatTheReaderWould) {
  const MeasurementLog good = makeLog2(SemanticKind::Label);
  {
    MeasurementLog log = good;
    log.steps[2].odometry->covariance(1, 1) = std::numeric_limits<double>::quiet_NaN();
    expectWriteRejected(log, "step 2: odometry.covariance[1][1]: not finite");
  }
  {
    MeasurementLog log = good;
    log.steps[1].detections[0].covariance(0, 0) = -1.0;
    expectWriteRejected(log, "step 1: detections[0].covariance: not positive definite");
  }
  {
    MeasurementLog log = good;
    log.steps[1].detections[0].classVector = Vector3(0.2, 0.3, 0.5);
    expectWriteRejected(log, "field 'probabilities' does not match the header's semantic 'label'");
  }
  {
    MeasurementLog log = good;
    log.steps[3].truePose = SE3();
    expectWriteRejected(log, "step 3: true_pose: expected 3 numbers [x, y, theta], found 7");
  }
  {
    MeasurementLog log = good;
    log.steps[3].time = log.steps[2].time;
    expectWriteRejected(log, "times must increase strictly");
  }
  {
    MeasurementLog log = good;
    log.steps[1].odometry.reset();
    expectWriteRejected(log, "missing field 'odometry'");
  }
  {
    MeasurementLog log = good;
    log.header.classes = 0;
    expectWriteRejected(log, "header: classes: integer 0 is out of range");
  }
  {
    MeasurementLog log = good;
    log.header.source = "\xff\xfe not UTF-8";
    expectWriteRejected(log, "header");
  }
  {
    MeasurementLog log = good;
    log.steps.clear();
    expectWriteRejected(log, "no time steps");
  }
}

TEST(MeasurementLogFile, EnumNames) {
  EXPECT_EQ(sensorKindName(SensorKind::RangeBearingElevation), "range-bearing-elevation");
  EXPECT_EQ(sensorKindName(SensorKind::RelativePose), "relative-pose");
  EXPECT_EQ(semanticKindName(SemanticKind::Probabilities), "probabilities");
  EXPECT_EQ(classifierKindName(ClassifierModelSpec::Kind::ViewpointGaussian), "viewpoint-gaussian");
}

}  // namespace
}  // namespace semslam
