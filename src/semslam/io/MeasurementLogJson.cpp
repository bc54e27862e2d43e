#include "semslam/io/MeasurementLogJson.h"

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <unordered_map>
#include <utility>
#include <vector>

#include "semslam/core/ExactNumber.h"
#include "semslam/core/InputExcerpt.h"
#include "semslam/io/InputMagnitudes.h"
#include "semslam/io/MeasurementLogFile.h"

namespace semslam {

namespace {

constexpr std::array<std::pair<SensorKind, std::string_view>, 4> kSensorNames{{
    {SensorKind::RangeBearing, "range-bearing"},
    {SensorKind::RangeBearingElevation, "range-bearing-elevation"},
    {SensorKind::RelativePosition, "relative-position"},
    {SensorKind::RelativePose, "relative-pose"},
}};
constexpr std::array<std::pair<SemanticKind, std::string_view>, 4> kSemanticNames{{
    {SemanticKind::None, "none"},
    {SemanticKind::Label, "label"},
    {SemanticKind::Probabilities, "probabilities"},
    {SemanticKind::Scores, "scores"},
}};
constexpr std::array<std::pair<ClassifierModelSpec::Kind, std::string_view>, 3> kClassifierNames{{
    {ClassifierModelSpec::Kind::None, "none"},
    {ClassifierModelSpec::Kind::Categorical, "categorical"},
    {ClassifierModelSpec::Kind::ViewpointGaussian, "viewpoint-gaussian"},
}};

template <class Enum, std::size_t N>
std::string_view nameOf(const std::array<std::pair<Enum, std::string_view>, N>& names, Enum value) {
  for (const auto& [kind, name] : names) {
    if (kind == value) return name;
  }
  return "invalid";
}

}  // namespace

std::string_view sensorKindName(SensorKind kind) { return nameOf(kSensorNames, kind); }
std::string_view semanticKindName(SemanticKind kind) { return nameOf(kSemanticNames, kind); }
std::string_view classifierKindName(ClassifierModelSpec::Kind kind) { return nameOf(kClassifierNames, kind); }

namespace jsonio {

namespace {

constexpr double kProbabilitySumTolerance = 1e-6;
constexpr double kQuaternionNormTolerance = 1e-6;
/// M x M confusion matrices are allocated from the declared class count before any detection is read.
constexpr long long kMaxClasses = kMaxLogClasses;
/// A step holds at most this many detections (docs/measurement-log.md, "Limits").
constexpr std::size_t kMaxDetectionsPerStep = 10000;

template <class Enum, std::size_t N>
Enum enumFromJson(const JsonField& field, const std::array<std::pair<Enum, std::string_view>, N>& names,
                  std::string_view what) {
  const std::string text = field.string();
  std::string accepted;
  for (const auto& [kind, name] : names) {
    if (name == text) return kind;
    accepted += (accepted.empty() ? "" : ", ") + std::string(name);
  }
  field.fail("unknown " + std::string(what) + " " + inputExcerpt(text) + " (expected one of: " + accepted + ")");
}

// ---- poses and landmark states ----

const char* poseLayout(int dimension) { return dimension == 2 ? "[x, y, theta]" : "[x, y, z, qx, qy, qz, qw]"; }
const char* tangentLayout(int dimension) { return dimension == 2 ? "x, y, theta" : "x, y, z, rx, ry, rz"; }
const char* pointLayout(int dimension) { return dimension == 2 ? "[x, y]" : "[x, y, z]"; }
int tangentDimension(int dimension) { return dimension == 2 ? 3 : 6; }

/// Checks that v(3..6) is a unit quaternion (within kQuaternionNormTolerance).
void checkQuaternion(const JsonField& field, const Vector& v) {
  const double norm = v.segment<4>(3).norm();
  if (!(std::abs(norm - 1.0) <= kQuaternionNormTolerance)) {
    field.fail("the quaternion (qx, qy, qz, qw) must have norm 1 (within 1e-6), found norm " +
               seventeenDigitNumber(norm));
  }
}

Pose poseFromJson(const JsonField& field, int dimension) {
  const Vector v = field.coordinates(dimension == 2 ? 3 : 7, poseLayout(dimension));
  if (dimension == 2) return SE2(v(0), v(1), v(2));
  checkQuaternion(field, v);
  return SE3(SO3::fromQuaternion(Eigen::Quaterniond(v(6), v(3), v(4), v(5))), Point3(v(0), v(1), v(2)));
}

LandmarkState landmarkFromJson(const JsonField& field, int dimension, bool hasPose) {
  if (hasPose) {
    const Pose pose = poseFromJson(field, dimension);
    if (dimension == 2) return std::get<SE2>(pose);
    return std::get<SE3>(pose);
  }
  const Vector v = field.coordinates(dimension, pointLayout(dimension));
  if (dimension == 2) return Point2(v(0), v(1));
  return Point3(v(0), v(1), v(2));
}

int landmarkCovarianceSize(int dimension, bool hasPose) { return hasPose ? tangentDimension(dimension) : dimension; }
const char* landmarkCovarianceLayout(int dimension, bool hasPose) {
  if (hasPose) return tangentLayout(dimension);
  return dimension == 2 ? "x, y" : "x, y, z";
}

// Rotations are written in a form that reads back to itself, so that reading a written file and writing it again
// gives the same bytes. The geometry types store cos/sin (SE2) and a rotation matrix (SE3), and an angle or a
// quaternion converted to that and back can move by a few units in the last place.
//
// SE2: among the doubles within 8 ulps of atan2(s, c), the first (in the order 0, -1, +1, -2, ...) whose cos and sin
// are exactly (c, s). A rotation built from an angle has one, so it is written and read back bit for bit; a
// composed rotation (no such angle) is first snapped to SO2(atan2(s, c)), which has one. The written angle is then
// a function of the (c, s) it reads back to, hence the same on every later write.
std::optional<double> exactAngle(const SO2& rotation) {
  const double centre = rotation.theta();
  double below = centre, above = centre;
  for (int k = 0; k <= 8; ++k) {
    for (double theta : {below, above}) {
      const SO2 candidate(theta);
      if (candidate.c() == rotation.c() && candidate.s() == rotation.s()) return theta;
    }
    below = std::nextafter(below, -std::numeric_limits<double>::infinity());
    above = std::nextafter(above, std::numeric_limits<double>::infinity());
  }
  return std::nullopt;
}

double stableAngle(const SO2& rotation) {
  if (const auto theta = exactAngle(rotation)) return *theta;
  const SO2 snapped(rotation.theta());
  if (const auto theta = exactAngle(snapped)) return *theta;
  return rotation.theta();  // not met in practice (tested on 1e5 random rotations)
}

// SE3: the map F(q) = toQuaternion(fromQuaternion(q)) on the doubles is eventually periodic. The written quaternion
// is the smallest member (lexicographically in x, y, z, w; zeros made positive) of the cycle its orbit reaches within
// kMaxSteps steps. Reading it gives R = fromQuaternion(q), and writing again starts at F(q), in the same cycle, so it
// picks the same member. Measured (2000 random rotations): orbits of median length 2, at most 121 steps. Small
// rotations (odometry increments) random-walk through the last bits of their small components and often reach no
// cycle within kMaxSteps (118 of 200 rotations of 1e-4 to 2e-2 rad about one axis): q is then the
// orbit's last member, deterministic but not a fixed point of a write-read-write. Seen members are found through a
// hash map, so a long orbit costs O(kMaxSteps) conversions (it was a linear search per step, O(kMaxSteps²): 10 ms
// per small rotation, found by the Starry Night converter's fuzz harness running at 12 inputs per second).
Eigen::Quaterniond stableQuaternion(const SO3& rotation) {
  constexpr std::size_t kMaxSteps = 2048;
  const auto less = [](const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 4, b.data(), b.data() + 4);
  };
  // Zeros are made positive at every step, so that equal coefficients are equal bit for bit (and print alike).
  const auto canonical = [](const Eigen::Quaterniond& q) {
    return Eigen::Quaterniond(q.w() + 0.0, q.x() + 0.0, q.y() + 0.0, q.z() + 0.0);
  };
  const auto bitsHash = [](const Eigen::Vector4d& v) {
    std::size_t h = 0;
    for (int i = 0; i < 4; ++i) h = h * 0x9e3779b97f4a7c15ull + std::bit_cast<std::uint64_t>(v[i]);
    return h;
  };
  const auto equal = [](const Eigen::Vector4d& a, const Eigen::Vector4d& b) { return a == b; };
  // Few buckets to start: most orbits close within a few steps, and this runs for every pose written.
  std::unordered_map<Eigen::Vector4d, std::size_t, decltype(bitsHash), decltype(equal)> position(8, bitsHash, equal);
  std::vector<Eigen::Vector4d> orbit;
  Eigen::Quaterniond q = canonical(rotation.toQuaternion());
  while (orbit.size() < kMaxSteps) {
    const auto seen = position.find(q.coeffs());
    if (seen != position.end()) {
      const auto first = orbit.begin() + static_cast<std::ptrdiff_t>(seen->second);
      return Eigen::Quaterniond(*std::min_element(first, orbit.end(), less));  // coeffs order x, y, z, w
    }
    position.emplace(q.coeffs(), orbit.size());
    orbit.push_back(q.coeffs());
    q = canonical(SO3::fromQuaternion(q).toQuaternion());
  }
  return q;
}

Json se2ToJson(const SE2& pose) { return Json::array({pose.x(), pose.y(), stableAngle(pose.rotation())}); }

Json se3ToJson(const SE3& pose) {
  const Eigen::Quaterniond q = stableQuaternion(pose.rotation());
  const Point3& t = pose.translation();
  return Json::array({t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()});
}

Json poseToJson(const Pose& pose) {
  return std::visit(
      [](const auto& p) -> Json {
        if constexpr (std::is_same_v<std::decay_t<decltype(p)>, SE2>) {
          return se2ToJson(p);
        } else {
          return se3ToJson(p);
        }
      },
      pose);
}

Json landmarkToJson(const LandmarkState& state) {
  return std::visit(
      [](const auto& s) -> Json {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, SE2>) {
          return se2ToJson(s);
        } else if constexpr (std::is_same_v<T, SE3>) {
          return se3ToJson(s);
        } else {
          return vectorToJson(s);
        }
      },
      state);
}

bool isPoseState(const LandmarkState& state) {
  return std::holds_alternative<SE2>(state) || std::holds_alternative<SE3>(state);
}

// ---- header parts ----

ClassifierModelSpec classifierFromJson(const JsonField& field, int classes) {
  ClassifierModelSpec spec;
  spec.kind = enumFromJson(field["kind"], kClassifierNames, "classifier kind");
  switch (spec.kind) {
    case ClassifierModelSpec::Kind::None:
      field.requireObject({"kind"});
      break;
    case ClassifierModelSpec::Kind::Categorical: {
      field.requireObject({"kind", "misclassification"}, {"table"});
      spec.misclassification = field["misclassification"].number();
      if (spec.misclassification < 0.0 || spec.misclassification > 1.0) {
        field["misclassification"].fail("a probability must be in [0, 1], found " +
                                        seventeenDigitNumber(spec.misclassification));
      }
      if (classes == 1 && spec.misclassification != 0.0) {
        field["misclassification"].fail("with 1 class there is no other class to confuse it with: must be 0");
      }
      break;
    }
    case ClassifierModelSpec::Kind::ViewpointGaussian: {
      field.requireObject({"kind", "alpha", "sharpness"}, {"table"});
      spec.alpha = field["alpha"].number();
      if (spec.alpha < 0.0 || spec.alpha > 1.0) {
        field["alpha"].fail("the viewpoint dependency must be in [0, 1], found " + seventeenDigitNumber(spec.alpha));
      }
      spec.sharpness = field["sharpness"].number();
      if (!(spec.sharpness > 0.0))
        field["sharpness"].fail("must be positive, found " + seventeenDigitNumber(spec.sharpness));
      break;
    }
  }
  if (field.has("table")) {
    spec.table = field["table"].string();
    if (spec.table.empty()) field["table"].fail("an empty file name (omit the field instead)");
  }
  return spec;
}

void checkClassifierMatchesSemantic(const JsonField& record, const LogHeader& header) {
  using Kind = ClassifierModelSpec::Kind;
  const Kind kind = header.classifier.kind;
  const SemanticKind semantic = header.semantic;
  const std::string problem = "classifier '" + std::string(classifierKindName(kind)) +
                              "' cannot explain the semantic '" + std::string(semanticKindName(semantic)) + "'";
  if (semantic == SemanticKind::None && kind != Kind::None) {
    record["classifier"].fail(problem + " (there is no semantic part: use classifier 'none')");
  }
  if (kind == Kind::Categorical && semantic == SemanticKind::Scores) {
    record["classifier"].fail(problem + " (a categorical model explains labels or probabilities)");
  }
  if (kind == Kind::ViewpointGaussian && semantic == SemanticKind::Label) {
    record["classifier"].fail(problem + " (a viewpoint-Gaussian model explains scores or probabilities)");
  }
}

SensorSpec sensorFromJson(const JsonField& field, int dimension) {
  SensorSpec sensor;
  sensor.kind = enumFromJson(field["kind"], kSensorNames, "sensor kind");
  field.requireObject({"kind"}, {"body_to_sensor", "max_range", "field_of_view"});
  if (sensor.kind == SensorKind::RangeBearing && dimension != 2) {
    field["kind"].fail("a range-bearing sensor needs dimension 2 (use range-bearing-elevation in 3D)");
  }
  if (sensor.kind == SensorKind::RangeBearingElevation && dimension != 3) {
    field["kind"].fail("a range-bearing-elevation sensor needs dimension 3 (use range-bearing in 2D)");
  }
  if (dimension == 2) {
    sensor.bodyToSensor = SE2();
  } else {
    sensor.bodyToSensor = SE3();
  }
  if (field.has("body_to_sensor")) sensor.bodyToSensor = poseFromJson(field["body_to_sensor"], dimension);
  if (field.has("max_range")) {
    sensor.maxRange = field["max_range"].coordinate();
    if (sensor.maxRange < 0.0)
      field["max_range"].fail("must be >= 0 (0: unlimited), found " + seventeenDigitNumber(sensor.maxRange));
  }
  if (field.has("field_of_view")) {
    sensor.fieldOfView = field["field_of_view"].number();
    if (sensor.fieldOfView < 0.0 || sensor.fieldOfView > 2.0 * std::numbers::pi) {
      field["field_of_view"].fail("must be in [0, 2 pi] radians (0: all around), found " +
                                  seventeenDigitNumber(sensor.fieldOfView));
    }
  }
  return sensor;
}

int landmarkId(const JsonField& field) { return static_cast<int>(field.integer(0, INT_MAX)); }

}  // namespace

// ---- header ----

LogHeader headerFromJson(const JsonField& record) {
  if (!record.json().is_object() || !record.has("format")) {
    record.fail("expected the header on the first line: an object with \"format\": \"" +
                std::string(kMeasurementLogFormat) + "\" (found " +
                (record.json().is_object() ? std::string("an object without 'format'") : describeJson(record.json())) +
                ")");
  }
  const std::string format = record["format"].string();
  if (format != kMeasurementLogFormat) {
    record["format"].fail("expected \"" + std::string(kMeasurementLogFormat) + "\", found \"" + format + "\"");
  }
  LogHeader header;
  {
    const JsonField version = record["version"];
    header.version = static_cast<int>(version.integer(INT_MIN, INT_MAX));
    if (header.version > kMeasurementLogVersion) {
      version.fail("version " + std::to_string(header.version) + " is newer than this reader, which reads versions 1 to " +
                   std::to_string(kMeasurementLogVersion));
    }
    if (header.version < 1) version.fail("invalid version " + std::to_string(header.version) + " (versions start at 1)");
  }
  record.requireObject({"format", "version", "dimension", "classes", "semantic", "sensor"},
                       {"classifier", "landmarks_have_pose", "initial_pose", "landmark_priors", "landmark_truth",
                        "source"});
  header.dimension = static_cast<int>(record["dimension"].integer(2, 3));
  const int dimension = header.dimension;
  header.classes = static_cast<int>(record["classes"].integer(1, kMaxClasses));
  header.semantic = enumFromJson(record["semantic"], kSemanticNames, "semantic kind");
  if (record.has("classifier")) header.classifier = classifierFromJson(record["classifier"], header.classes);
  checkClassifierMatchesSemantic(record, header);
  header.sensor = sensorFromJson(record["sensor"], dimension);
  if (record.has("landmarks_have_pose")) header.landmarksHavePose = record["landmarks_have_pose"].boolean();
  const bool hasPose = header.landmarksHavePose;

  if (record.has("initial_pose")) {
    const JsonField prior = record["initial_pose"];
    prior.requireObject({"mean", "covariance"});
    PosePrior pose;
    pose.mean = poseFromJson(prior["mean"], dimension);
    pose.covariance = prior["covariance"].covariance(tangentDimension(dimension), tangentLayout(dimension));
    header.initialPose = pose;
  }

  if (record.has("landmark_priors")) {
    const JsonField priors = record["landmark_priors"];
    std::set<int> ids;
    for (std::size_t i = 0, n = priors.arraySize(); i < n; ++i) {
      const JsonField item = priors.at(i);
      item.requireObject({"id", "mean", "covariance"});
      LandmarkPrior prior;
      prior.id = landmarkId(item["id"]);
      if (!ids.insert(prior.id).second) item["id"].fail("duplicate landmark id " + std::to_string(prior.id));
      prior.mean = landmarkFromJson(item["mean"], dimension, hasPose);
      prior.covariance = item["covariance"].covariance(landmarkCovarianceSize(dimension, hasPose),
                                                      landmarkCovarianceLayout(dimension, hasPose));
      header.landmarkPriors.push_back(std::move(prior));
    }
  }

  if (record.has("landmark_truth")) {
    const JsonField truth = record["landmark_truth"];
    std::set<int> ids;
    const char* stateKey = hasPose ? "pose" : "position";
    const char* otherKey = hasPose ? "position" : "pose";
    for (std::size_t i = 0, n = truth.arraySize(); i < n; ++i) {
      const JsonField item = truth.at(i);
      if (item.has(otherKey)) {
        item.fail(std::string("found '") + otherKey + "' but the header's landmarks_have_pose is " +
                  (hasPose ? "true" : "false") + ": expected '" + stateKey + "'");
      }
      item.requireObject({"id", stateKey}, {"class"});
      LandmarkTruth landmark;
      landmark.id = landmarkId(item["id"]);
      if (!ids.insert(landmark.id).second) item["id"].fail("duplicate landmark id " + std::to_string(landmark.id));
      if (item.has("class")) landmark.classIndex = static_cast<int>(item["class"].integer(0, header.classes - 1));
      landmark.state = landmarkFromJson(item[stateKey], dimension, hasPose);
      header.landmarkTruth.push_back(std::move(landmark));
    }
  }

  if (record.has("source")) header.source = record["source"].string();
  return header;
}

Json headerToJson(const LogHeader& header) {
  Json json = Json::object();
  json["format"] = kMeasurementLogFormat;
  json["version"] = kMeasurementLogVersion;
  json["dimension"] = header.dimension;
  json["classes"] = header.classes;
  json["semantic"] = semanticKindName(header.semantic);
  Json classifier = Json::object();
  classifier["kind"] = classifierKindName(header.classifier.kind);
  if (header.classifier.kind == ClassifierModelSpec::Kind::Categorical) {
    classifier["misclassification"] = header.classifier.misclassification;
  } else if (header.classifier.kind == ClassifierModelSpec::Kind::ViewpointGaussian) {
    classifier["alpha"] = header.classifier.alpha;
    classifier["sharpness"] = header.classifier.sharpness;
  }
  if (!header.classifier.table.empty()) classifier["table"] = header.classifier.table;
  json["classifier"] = std::move(classifier);
  Json sensor = Json::object();
  sensor["kind"] = sensorKindName(header.sensor.kind);
  sensor["body_to_sensor"] = poseToJson(header.sensor.bodyToSensor);
  sensor["max_range"] = header.sensor.maxRange;
  sensor["field_of_view"] = header.sensor.fieldOfView;
  json["sensor"] = std::move(sensor);
  json["landmarks_have_pose"] = header.landmarksHavePose;
  if (header.initialPose) {
    Json prior = Json::object();
    prior["mean"] = poseToJson(header.initialPose->mean);
    prior["covariance"] = matrixToJson(header.initialPose->covariance);
    json["initial_pose"] = std::move(prior);
  }
  if (!header.landmarkPriors.empty()) {
    Json priors = Json::array();
    for (const LandmarkPrior& prior : header.landmarkPriors) {
      Json item = Json::object();
      item["id"] = prior.id;
      item["mean"] = landmarkToJson(prior.mean);
      item["covariance"] = matrixToJson(prior.covariance);
      priors.push_back(std::move(item));
    }
    json["landmark_priors"] = std::move(priors);
  }
  if (!header.landmarkTruth.empty()) {
    Json truth = Json::array();
    for (const LandmarkTruth& landmark : header.landmarkTruth) {
      Json item = Json::object();
      item["id"] = landmark.id;
      if (landmark.classIndex != -1) item["class"] = landmark.classIndex;
      item[isPoseState(landmark.state) ? "pose" : "position"] = landmarkToJson(landmark.state);
      truth.push_back(std::move(item));
    }
    json["landmark_truth"] = std::move(truth);
  }
  if (!header.source.empty()) json["source"] = header.source;
  return json;
}

// ---- steps ----

StepParser::StepParser(const LogHeader& header) : header_(header) {
  for (const LandmarkTruth& landmark : header.landmarkTruth) truthIds_.insert(landmark.id);
}

Detection StepParser::parseDetection(const JsonField& field) const {
  const int dimension = header_.dimension;
  const char* semanticKey = nullptr;
  switch (header_.semantic) {
    case SemanticKind::None:
      break;
    case SemanticKind::Label:
      semanticKey = "label";
      break;
    case SemanticKind::Probabilities:
      semanticKey = "probabilities";
      break;
    case SemanticKind::Scores:
      semanticKey = "scores";
      break;
  }
  for (const char* key : {"label", "probabilities", "scores"}) {
    if (field.has(key) && (semanticKey == nullptr || std::string_view(key) != semanticKey)) {
      field.fail(std::string("field '") + key + "' does not match the header's semantic '" +
                 std::string(semanticKindName(header_.semantic)) + "'" +
                 (semanticKey ? std::string(" (expected '") + semanticKey + "')" : " (detections carry no class)"));
    }
  }
  if (semanticKey) {
    field.requireObject({"geometry", "covariance", semanticKey}, {"truth", "clutter_source"});
  } else {
    field.requireObject({"geometry", "covariance"}, {"truth", "clutter_source"});
  }

  Detection detection;
  const JsonField geometry = field["geometry"];
  int covarianceSize = 0;
  const char* covarianceLayout = "";
  switch (header_.sensor.kind) {
    case SensorKind::RangeBearing:
      detection.geometry = geometry.coordinates(2, "[range, bearing]");
      covarianceSize = 2;
      covarianceLayout = "range, bearing";
      break;
    case SensorKind::RangeBearingElevation:
      detection.geometry = geometry.coordinates(3, "[range, bearing, elevation]");
      covarianceSize = 3;
      covarianceLayout = "range, bearing, elevation";
      if (std::abs(detection.geometry(2)) > 0.5 * std::numbers::pi) {
        geometry.fail("the elevation must be in [-pi/2, pi/2], found " + seventeenDigitNumber(detection.geometry(2)));
      }
      break;
    case SensorKind::RelativePosition:
      detection.geometry = geometry.coordinates(dimension, pointLayout(dimension));
      covarianceSize = dimension;
      covarianceLayout = dimension == 2 ? "x, y" : "x, y, z";
      break;
    case SensorKind::RelativePose:
      detection.geometry = geometry.coordinates(dimension == 2 ? 3 : 7, poseLayout(dimension));
      if (dimension == 3) checkQuaternion(geometry, detection.geometry);
      covarianceSize = tangentDimension(dimension);
      covarianceLayout = tangentLayout(dimension);
      break;
  }
  if ((header_.sensor.kind == SensorKind::RangeBearing || header_.sensor.kind == SensorKind::RangeBearingElevation) &&
      !(detection.geometry(0) >= kMinRange)) {
    geometry.fail("the range must be at least 1e-6 (docs/measurement-log.md), found " +
                  seventeenDigitNumber(detection.geometry(0)));
  }
  detection.covariance = field["covariance"].covariance(covarianceSize, covarianceLayout);

  const int classes = header_.classes;
  if (header_.semantic == SemanticKind::Label) {
    detection.label = static_cast<int>(field["label"].integer(0, classes - 1));
  } else if (semanticKey != nullptr) {
    const JsonField vector = field[semanticKey];
    const Vector v = vector.vector(classes, "(one per class: the header has " + std::to_string(classes) +
                                                (classes == 1 ? " class)" : " classes)"));
    if (header_.semantic == SemanticKind::Probabilities) {
      for (Eigen::Index i = 0; i < v.size(); ++i) {
        if (v(i) < 0.0) {
          vector.fail("probabilities must be non-negative, found " + seventeenDigitNumber(v(i)) + " for class " +
                      std::to_string(i));
        }
      }
      const double sum = v.sum();
      if (!(std::abs(sum - 1.0) <= kProbabilitySumTolerance)) {
        vector.fail("probabilities must sum to 1 (within 1e-6), found a sum of " + seventeenDigitNumber(sum));
      }
    }
    detection.classVector = v;
  }

  if (field.has("truth")) {
    const JsonField truth = field["truth"];
    const std::string expected = "expected a landmark id, \"not-a-landmark\" or \"unknown\", found ";
    if (truth.json().is_string()) {
      const std::string kind = truth.string();
      if (kind == "not-a-landmark") {
        detection.truthId = kNotALandmark;
      } else if (kind == "unknown") {
        if (header_.version < kUnknownTruthVersion) {
          truth.fail("\"unknown\" truth needs version " + std::to_string(kUnknownTruthVersion) +
                     " or later; this file is version " + std::to_string(header_.version));
        }
        detection.truthId = kUnknownTruth;
      } else {
        truth.fail(expected + describeJson(truth.json()));
      }
    } else {
      if (!truth.json().is_number()) truth.fail(expected + describeJson(truth.json()));
      const int id = landmarkId(truth);
      if (!truthIds_.empty() && !truthIds_.contains(id)) {
        truth.fail("landmark " + std::to_string(id) + " is not in the header's landmark_truth");
      }
      detection.truthId = id;
    }
  }
  if (field.has("clutter_source")) {
    const JsonField source = field["clutter_source"];
    if (detection.truthId != kNotALandmark) source.fail("a clutter source needs \"truth\": \"not-a-landmark\"");
    detection.clutterSource = static_cast<int>(source.integer(0, INT_MAX));
  }
  return detection;
}

TimeStep StepParser::parse(const JsonField& record) {
  if (record.has("format")) record.fail("a second header: the header is the first line only");
  record.requireObject({"time", "detections"}, {"odometry", "true_pose"});
  TimeStep step;
  step.time = record["time"].number();
  if (previousTime_ && !(step.time > *previousTime_)) {
    record["time"].fail("time " + seventeenDigitNumber(step.time) + " is not after the previous step's time " +
                        seventeenDigitNumber(*previousTime_) + " (times must increase strictly)");
  }
  const int dimension = header_.dimension;
  if (steps_ == 0 && record.has("odometry")) {
    record["odometry"].fail("the first step has no odometry: there is no previous pose to move from");
  }
  if (steps_ > 0 && !record.has("odometry")) {
    record.fail("missing field 'odometry' (every step after the first has the odometry from the previous step)");
  }
  if (record.has("odometry")) {
    const JsonField odometry = record["odometry"];
    odometry.requireObject({"increment", "covariance"});
    Odometry value;
    value.increment = poseFromJson(odometry["increment"], dimension);
    value.covariance = odometry["covariance"].covariance(tangentDimension(dimension), tangentLayout(dimension));
    step.odometry = value;
  }
  const JsonField detections = record["detections"];
  const std::size_t count = detections.arraySize();
  if (count > kMaxDetectionsPerStep) {
    detections.fail(std::to_string(count) + " detections in one step (at most " +
                    std::to_string(kMaxDetectionsPerStep) + ")");
  }
  step.detections.reserve(count);
  for (std::size_t i = 0; i < count; ++i) step.detections.push_back(parseDetection(detections.at(i)));
  if (record.has("true_pose")) step.truePose = poseFromJson(record["true_pose"], dimension);

  previousTime_ = step.time;
  ++steps_;
  return step;
}

Json stepToJson(const TimeStep& step, SemanticKind semantic) {
  Json json = Json::object();
  json["time"] = step.time;
  if (step.odometry) {
    Json odometry = Json::object();
    odometry["increment"] = poseToJson(step.odometry->increment);
    odometry["covariance"] = matrixToJson(step.odometry->covariance);
    json["odometry"] = std::move(odometry);
  }
  Json detections = Json::array();
  for (const Detection& detection : step.detections) {
    Json item = Json::object();
    item["geometry"] = vectorToJson(detection.geometry);
    item["covariance"] = matrixToJson(detection.covariance);
    if (detection.label) item["label"] = *detection.label;
    if (detection.classVector) {
      item[semantic == SemanticKind::Scores ? "scores" : "probabilities"] = vectorToJson(*detection.classVector);
    }
    if (detection.truthId) {
      if (*detection.truthId == kNotALandmark) {
        item["truth"] = "not-a-landmark";
        if (detection.clutterSource) item["clutter_source"] = *detection.clutterSource;
      } else if (*detection.truthId == kUnknownTruth) {
        item["truth"] = "unknown";
      } else {
        item["truth"] = *detection.truthId;
      }
    }
    detections.push_back(std::move(item));
  }
  json["detections"] = std::move(detections);
  if (step.truePose) json["true_pose"] = poseToJson(*step.truePose);
  return json;
}

}  // namespace jsonio

}  // namespace semslam
