#include "semslam/io/ScenarioFile.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "semslam/core/ExactNumber.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/core/InputError.h"
#include "semslam/io/JsonField.h"

namespace semslam {

using jsonio::Json;
using jsonio::JsonField;
using jsonio::JsonLocation;

namespace {

// ---- reading ----

std::size_t lineOfByte(const std::string& text, std::size_t byte) {
  const std::size_t end = std::min(byte, text.size());
  return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(end), '\n'));
}

/// nlohmann's message without its "[json.exception.parse_error.101] parse error at line L, column C: " prefix.
std::string parseProblem(const std::string& what) {
  std::string text = what;
  if (text.rfind("[json.exception.", 0) == 0) {
    const auto end = text.find("] ");
    if (end != std::string::npos) text = text.substr(end + 2);
  }
  if (text.rfind("parse error", 0) == 0) {
    const auto colon = text.find(": ");
    if (colon != std::string::npos) text = text.substr(colon + 2);
  }
  return text;
}

Json parseJson(const std::string& text, const std::string& file) {
  std::vector<std::vector<std::string>> keys;  // the keys seen so far in each open object
  std::string duplicate;
  const Json::parser_callback_t callback = [&keys, &duplicate](int, Json::parse_event_t event, Json& parsed) {
    if (event == Json::parse_event_t::object_start) {
      keys.emplace_back();
    } else if (event == Json::parse_event_t::key) {
      std::string key = parsed.get<std::string>();
      if (duplicate.empty() && std::find(keys.back().begin(), keys.back().end(), key) != keys.back().end()) {
        duplicate = key;
      }
      keys.back().push_back(std::move(key));
    } else if (event == Json::parse_event_t::object_end) {
      keys.pop_back();
    }
    return true;
  };
  Json json;
  try {
    json = Json::parse(text, callback);
  } catch (const Json::parse_error& error) {
    throw InputError(file, lineOfByte(text, error.byte == 0 ? 0 : error.byte - 1),
                     "not valid JSON: " + parseProblem(error.what()));
  } catch (const Json::exception& error) {
    throw InputError(file, 0, "not valid JSON: " + parseProblem(error.what()));
  }
  if (!duplicate.empty()) throw InputError(file, 0, "duplicate key '" + duplicate + "' (every key appears once)");
  return json;
}

SE2 poseFrom(const JsonField& field) {
  const Vector v = field.vector(3, "[x, y, theta]");
  return SE2(v(0), v(1), v(2));
}

Matrix3 covariance3(const JsonField& field) { return field.covariance(3, "x, y, theta"); }

void readPriors(const JsonField& field, Aliased2dPriors& priors) {
  field.requireObject({}, {"initial_pose_covariance", "object_covariance", "means"});
  if (field.has("initial_pose_covariance")) {
    priors.initialPoseCovariance = covariance3(field["initial_pose_covariance"]);
  }
  if (field.has("object_covariance")) priors.objectCovariance = covariance3(field["object_covariance"]);
  if (field.has("means")) {
    const JsonField means = field["means"];
    const std::string name = means.string();
    if (name == "sampled") {
      priors.means = PriorMeans::Sampled;
    } else if (name == "truth") {
      priors.means = PriorMeans::Truth;
    } else {
      means.fail("unknown value '" + name + "' (expected one of: sampled, truth)");
    }
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
  motion.arenaCenter = arena["center"].vector(2, "[x, y]");
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

std::string number(double value) {
  if (value == 0.0) return "0";  // also -0
  // The shortest text that reads back to the same double; plain decimals (0.0005, not 5e-04) while they stay short.
  std::string text = shortestExactNumber(value);
  if (text.find('e') != std::string::npos) {
    char buffer[400];
    const auto fixed = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
    if (fixed.ec == std::errc() && fixed.ptr - buffer <= 12) text.assign(buffer, fixed.ptr);
  }
  return text;
}

template <class V>
std::string vectorText(const V& v) {
  std::string text = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) text += (i ? ", " : "") + number(v(i));
  return text + "]";
}

std::string poseText(const SE2& pose) { return vectorText(Vector3(pose.x(), pose.y(), pose.theta())); }

template <class M>
std::string matrixText(const M& m) {
  std::string text = "[";
  for (Eigen::Index i = 0; i < m.rows(); ++i) text += (i ? ", " : "") + vectorText(Vector(m.row(i).transpose()));
  return text + "]";
}

}  // namespace

Aliased2dScenario parseAliased2dScenario(const std::string& text, const std::string& file) {
  const Json json = parseJson(text, file);
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
  if (versionNumber != kScenarioVersion) {
    version.fail("version " + std::to_string(versionNumber) + " is not supported (this reader reads version " +
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
  if (root.has("priors")) readPriors(root["priors"], scenario.priors);
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
  if (std::filesystem::is_directory(path)) throw InputError(path, 0, "is a directory, not a scenario file");
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path, 0, "cannot open the scenario file");
  std::ostringstream contents;
  contents << stream.rdbuf();
  if (stream.bad()) throw InputError(path, 0, "read error");
  const std::string text = contents.str();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(path, 0, "the file is empty");
  return parseAliased2dScenario(text, path);
}

std::string aliased2dScenarioToJson(const Aliased2dScenario& scenario) {
  validateAliased2dScenario(scenario);
  std::string out;
  out += "{\n";
  out += "  \"format\": \"" + std::string(kScenarioFormat) + "\",\n";
  out += "  \"version\": " + std::to_string(kScenarioVersion) + ",\n";
  out += "  \"kind\": \"aliased2d\",\n";
  out += "  \"name\": " + Json(scenario.name).dump() + ",\n";
  out += "  \"classes\": " + std::to_string(scenario.classes) + ",\n";
  out += "  \"objects\": [\n";
  for (std::size_t i = 0; i < scenario.objects.size(); ++i) {
    const Aliased2dObject& object = scenario.objects[i];
    out += "    {\"id\": " + std::to_string(object.id) + ", \"class\": " + std::to_string(object.classIndex) +
           ", \"pose\": " + poseText(object.pose) + "}" + (i + 1 < scenario.objects.size() ? "," : "") + "\n";
  }
  out += "  ],\n";
  out += "  \"start\": " + poseText(scenario.start) + ",\n";
  const Aliased2dPriors& priors = scenario.priors;
  out += "  \"priors\": {\n";
  out += "    \"initial_pose_covariance\": " + matrixText(priors.initialPoseCovariance) + ",\n";
  out += "    \"object_covariance\": " + matrixText(priors.objectCovariance) + ",\n";
  out += std::string("    \"means\": \"") + (priors.means == PriorMeans::Sampled ? "sampled" : "truth") + "\"\n";
  out += "  },\n";
  const Aliased2dMotion& motion = scenario.motion;
  out += "  \"motion\": {\n";
  out += "    \"covariance\": " + matrixText(motion.covariance) + ",\n";
  out += "    \"step_length\": " + number(motion.stepLength) + ",\n";
  out += "    \"max_turn\": " + number(motion.maxTurn) + ",\n";
  out += "    \"arena\": {\"center\": " + vectorText(motion.arenaCenter) +
         ", \"radius\": " + number(motion.arenaRadius) + "},\n";
  out += "    \"clearance\": " + number(motion.clearance) + ",\n";
  out += "    \"time_step\": " + number(motion.timeStep) + "\n";
  out += "  },\n";
  const Aliased2dSensor& sensor = scenario.sensor;
  out += "  \"sensor\": {\n";
  out += "    \"body_to_sensor\": " + poseText(sensor.bodyToSensor) + ",\n";
  out += "    \"max_range\": " + number(sensor.maxRange) + ",\n";
  out += "    \"field_of_view\": " + number(sensor.fieldOfView) + ",\n";
  out += "    \"covariance\": " + matrixText(sensor.covariance) + "\n";
  out += "  },\n";
  out += "  \"classifier\": {\"alpha\": " + number(scenario.alpha) + ", \"sharpness\": " + number(scenario.sharpness) +
         "}\n";
  out += "}\n";
  return out;
}

void writeAliased2dScenario(const std::string& path, const Aliased2dScenario& scenario) {
  const std::string text = aliased2dScenarioToJson(scenario);
  writeFileAtomically(path, [&text](std::ostream& out) { out << text; });
}

}  // namespace semslam
