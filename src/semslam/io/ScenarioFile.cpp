#include "semslam/io/ScenarioFile.h"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

#include "semslam/core/InputError.h"
#include "semslam/core/InputFile.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/io/JsonField.h"
#include "semslam/io/StrictJson.h"

namespace semslam {

using jsonio::Json;
using jsonio::JsonField;
using jsonio::JsonLocation;

namespace {

// ---- reading ----

SE2 poseFrom(const JsonField& field) {
  const Vector v = field.coordinates(3, "[x, y, theta]");
  return SE2(v(0), v(1), v(2));
}

Matrix3 covariance3(const JsonField& field) { return field.covariance(3, "x, y, theta"); }

/// One of `names` (the enum's values in order) at `field`, or a failure listing them.
template <class Enum>
Enum choice(const JsonField& field, const std::vector<std::pair<std::string, Enum>>& names) {
  const std::string name = field.string();
  std::string expected;
  for (const auto& [text, value] : names) {
    if (text == name) return value;
    expected += (expected.empty() ? "" : ", ") + text;
  }
  field.fail("unknown value '" + name + "' (expected one of: " + expected + ")");
}

/// Version 2 states the two means apart; version 1's single "means" set both ("sampled", its default: both drawn;
/// "truth": the start and the objects' truth), and is still read as it was meant.
void readPriors(const JsonField& field, Aliased2dPriors& priors, long long version) {
  if (version == 1) {
    priors.poseMean = PoseMean::Sampled;
    field.requireObject({}, {"initial_pose_covariance", "object_covariance", "means"});
  } else {
    field.requireObject({}, {"initial_pose_covariance", "object_covariance", "pose_mean", "object_means"});
  }
  if (field.has("initial_pose_covariance")) {
    priors.initialPoseCovariance = covariance3(field["initial_pose_covariance"]);
  }
  if (field.has("object_covariance")) priors.objectCovariance = covariance3(field["object_covariance"]);
  if (field.has("means")) {
    const bool sampled = choice<bool>(field["means"], {{"sampled", true}, {"truth", false}});
    priors.poseMean = sampled ? PoseMean::Sampled : PoseMean::Start;
    priors.objectMeans = sampled ? ObjectMeans::Sampled : ObjectMeans::Truth;
  }
  if (field.has("pose_mean")) {
    priors.poseMean = choice<PoseMean>(field["pose_mean"], {{"start", PoseMean::Start}, {"sampled", PoseMean::Sampled}});
  }
  if (field.has("object_means")) {
    priors.objectMeans =
        choice<ObjectMeans>(field["object_means"], {{"sampled", ObjectMeans::Sampled}, {"truth", ObjectMeans::Truth}});
  }
}

void readMotion(const JsonField& field, Aliased2dMotion& motion) {
  field.requireObject({"arena"}, {"covariance", "step_length", "max_turn", "clearance", "time_step"});
  if (field.has("covariance")) motion.covariance = covariance3(field["covariance"]);
  if (field.has("step_length")) motion.stepLength = field["step_length"].number();
  if (field.has("max_turn")) motion.maxTurn = field["max_turn"].number();
  if (field.has("clearance")) motion.clearance = field["clearance"].number();
  if (field.has("time_step")) motion.timeStep = field["time_step"].number();
  const JsonField arena = field["arena"];
  arena.requireObject({"center", "radius"});
  motion.arenaCenter = arena["center"].coordinates(2, "[x, y]");
  motion.arenaRadius = arena["radius"].number();
}

void readSensor(const JsonField& field, Aliased2dSensor& sensor) {
  field.requireObject({}, {"body_to_sensor", "max_range", "field_of_view", "covariance"});
  if (field.has("body_to_sensor")) sensor.bodyToSensor = poseFrom(field["body_to_sensor"]);
  if (field.has("max_range")) sensor.maxRange = field["max_range"].number();
  if (field.has("field_of_view")) sensor.fieldOfView = field["field_of_view"].number();
  if (field.has("covariance")) sensor.covariance = field["covariance"].covariance(2, "range, bearing");
}

// ---- writing ----

// nlohmann writes every number as the shortest text that reads back to the same double
// (https://json.nlohmann.me/api/basic_json/dump/), so a written scenario reads back equal.

Json vectorJson(const Vector& v) {
  Json array = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) array.push_back(v(i));
  return array;
}

Json poseJson(const SE2& pose) { return vectorJson(Vector3(pose.x(), pose.y(), pose.theta())); }

template <class M>
Json matrixJson(const M& m) {
  Json rows = Json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) rows.push_back(vectorJson(Vector(m.row(i).transpose())));
  return rows;
}

}  // namespace

Aliased2dScenario parseAliased2dScenario(const std::string& text, const std::string& file) {
  const Json json = jsonio::parseStrictJson(text, file, 1);
  const JsonLocation location{file, 0};
  const JsonField root(json, location);
  root.requireObject({"format", "version", "kind", "objects", "start", "motion"},
                     {"name", "classes", "priors", "sensor", "classifier"});
  const std::string format = root["format"].string();
  if (format != kScenarioFormat) {
    root["format"].fail("expected \"" + std::string(kScenarioFormat) + "\", found \"" + format + "\"");
  }
  const JsonField version = root["version"];
  const long long versionNumber = version.integer(0, 1'000'000);
  if (versionNumber < 1 || versionNumber > kScenarioVersion) {
    version.fail("version " + std::to_string(versionNumber) + " is not supported (this reader reads versions 1 to " +
                 std::to_string(kScenarioVersion) + ")");
  }
  const std::string kind = root["kind"].string();
  if (kind != "aliased2d") root["kind"].fail("unknown scenario kind '" + kind + "' (expected: aliased2d)");

  Aliased2dScenario scenario = defaultAliased2dScenario();
  scenario.name = root.has("name") ? root["name"].string() : std::filesystem::path(file).stem().string();
  if (root.has("classes")) scenario.classes = static_cast<int>(root["classes"].integer(1, 1'000'000));

  const JsonField objects = root["objects"];
  scenario.objects.clear();
  const std::size_t count = objects.arraySize();
  if (count == 0) objects.fail("at least one object is needed");
  for (std::size_t i = 0; i < count; ++i) {
    const JsonField item = objects.at(i);
    item.requireObject({"id", "class", "pose"});
    Aliased2dObject object;
    object.id = static_cast<int>(item["id"].integer(0, 1'000'000'000));
    object.classIndex = static_cast<int>(item["class"].integer(0, 1'000'000));
    object.pose = poseFrom(item["pose"]);
    scenario.objects.push_back(object);
  }
  scenario.start = poseFrom(root["start"]);
  const Json noPriors = Json::object();  // absent: every prior field takes its default (of the file's version)
  readPriors(root.has("priors") ? root["priors"] : JsonField(noPriors, location), scenario.priors, versionNumber);
  readMotion(root["motion"], scenario.motion);
  if (root.has("sensor")) readSensor(root["sensor"], scenario.sensor);
  if (root.has("classifier")) {
    const JsonField classifier = root["classifier"];
    classifier.requireObject({}, {"alpha", "sharpness"});
    if (classifier.has("alpha")) scenario.alpha = classifier["alpha"].number();
    if (classifier.has("sharpness")) scenario.sharpness = classifier["sharpness"].number();
  }
  try {
    validateAliased2dScenario(scenario);
  } catch (const std::invalid_argument& error) {
    throw InputError(file, 0, error.what());
  }
  return scenario;
}

Aliased2dScenario readAliased2dScenario(const std::string& path) {
  const std::string text = readInputText(path);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(path, 0, "the file is empty");
  return parseAliased2dScenario(text, path);
}

std::string aliased2dScenarioToJson(const Aliased2dScenario& scenario) {
  validateAliased2dScenario(scenario);
  Json root;  // ordered: the keys in the order of docs/simulators.md
  root["format"] = kScenarioFormat;
  root["version"] = kScenarioVersion;
  root["kind"] = "aliased2d";
  root["name"] = scenario.name;
  root["classes"] = scenario.classes;
  Json objects = Json::array();
  for (const Aliased2dObject& object : scenario.objects) {
    objects.push_back({{"id", object.id}, {"class", object.classIndex}, {"pose", poseJson(object.pose)}});
  }
  root["objects"] = std::move(objects);
  root["start"] = poseJson(scenario.start);
  const Aliased2dPriors& priors = scenario.priors;
  root["priors"] = {{"initial_pose_covariance", matrixJson(priors.initialPoseCovariance)},
                    {"object_covariance", matrixJson(priors.objectCovariance)},
                    {"pose_mean", poseMeanName(priors.poseMean)},
                    {"object_means", objectMeansName(priors.objectMeans)}};
  const Aliased2dMotion& motion = scenario.motion;
  root["motion"] = {{"covariance", matrixJson(motion.covariance)},
                    {"step_length", motion.stepLength},
                    {"max_turn", motion.maxTurn},
                    {"arena", {{"center", vectorJson(motion.arenaCenter)}, {"radius", motion.arenaRadius}}},
                    {"clearance", motion.clearance},
                    {"time_step", motion.timeStep}};
  const Aliased2dSensor& sensor = scenario.sensor;
  root["sensor"] = {{"body_to_sensor", poseJson(sensor.bodyToSensor)},
                    {"max_range", sensor.maxRange},
                    {"field_of_view", sensor.fieldOfView},
                    {"covariance", matrixJson(sensor.covariance)}};
  root["classifier"] = {{"alpha", scenario.alpha}, {"sharpness", scenario.sharpness}};
  return root.dump(2) + "\n";
}

void writeAliased2dScenario(const std::string& path, const Aliased2dScenario& scenario) {
  const std::string text = aliased2dScenarioToJson(scenario);
  writeFileAtomically(path, [&text](std::ostream& out) { out << text; });
}

}  // namespace semslam
