// Every malformed measurement log the reader rejects: each case checks the file name, the line number and the
// problem (with the field's path) in the InputError.

#include <gtest/gtest.h>

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "IoTesting.h"
#include "semslam/io/MeasurementLogFile.h"

namespace semslam {
namespace {

using test::TempDir;
using Json = nlohmann::ordered_json;

// A valid 2D log: header (line 1) and three steps (lines 2, 3, 4).
Json baseHeader() {
  return Json::parse(R"({"format":"semslam-log","version":1,"dimension":2,"classes":3,"semantic":"label",
    "classifier":{"kind":"categorical","misclassification":0.1},
    "sensor":{"kind":"range-bearing","body_to_sensor":[0.1,0.0,0.0],"max_range":10.0,"field_of_view":3.0},
    "landmarks_have_pose":false,
    "initial_pose":{"mean":[0.0,0.0,0.0],"covariance":[[1e-4,0,0],[0,1e-4,0],[0,0,1e-6]]},
    "landmark_priors":[{"id":0,"mean":[2.0,1.0],"covariance":[[1.0,0.0],[0.0,1.0]]}],
    "landmark_truth":[{"id":0,"class":1,"position":[2.0,1.0]},{"id":1,"position":[5.0,-1.0]}],
    "source":"test"})");
}

std::vector<Json> baseSteps() {
  return {
      Json::parse(R"({"time":0.0,"detections":[{"geometry":[2.2,0.46],"covariance":[[0.01,0],[0,0.001]],
        "label":1,"truth":0}],"true_pose":[0.0,0.0,0.0]})"),
      Json::parse(R"({"time":0.5,"odometry":{"increment":[1.0,0.0,0.1],
        "covariance":[[0.01,0,0],[0,0.01,0],[0,0,0.001]]},"detections":[
        {"geometry":[4.1,-0.3],"covariance":[[0.01,0.0001],[0.0001,0.001]],"label":2,"truth":1},
        {"geometry":[3.0,1.0],"covariance":[[0.01,0],[0,0.001]],"label":0,"truth":"not-a-landmark"}]})"),
      Json::parse(R"({"time":1.0,"odometry":{"increment":[1.0,0.0,0.1],
        "covariance":[[0.01,0,0],[0,0.01,0],[0,0,0.001]]},"detections":[]})"),
  };
}

// A valid 3D log: range-bearing-elevation, pose landmarks, scores.
Json baseHeader3() {
  return Json::parse(R"({"format":"semslam-log","version":1,"dimension":3,"classes":2,"semantic":"scores",
    "classifier":{"kind":"viewpoint-gaussian","alpha":0.25,"sharpness":15.0},
    "sensor":{"kind":"range-bearing-elevation","body_to_sensor":[0,0,0,0,0,0,1]},
    "landmarks_have_pose":true,
    "landmark_truth":[{"id":3,"class":0,"pose":[1,2,3,0,0,0,1]}]})");
}

std::vector<Json> baseSteps3() {
  const Json cov6 = Json::parse(
      "[[1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,1,0,0,0],[0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1]]");
  Json first = Json::parse(R"({"time":0.0,"detections":[{"geometry":[3.0,0.2,-0.1],
    "covariance":[[0.1,0,0],[0,0.01,0],[0,0,0.01]],"scores":[1.3,-0.4],"truth":3}]})");
  Json second = Json::parse(R"({"time":1.0,"odometry":{"increment":[1,0,0,0,0,0.0998334166,0.9950041653]},
    "detections":[],"true_pose":[1,0,0,0,0,0,1]})");
  second["odometry"]["covariance"] = cov6;
  return {first, second};
}

std::string text(const Json& header, const std::vector<Json>& steps) {
  std::string out = header.dump() + "\n";
  for (const Json& step : steps) out += step.dump() + "\n";
  return out;
}

struct Case {
  std::string name;
  std::function<void(Json& header, std::vector<Json>& steps)> change;
  std::size_t line;
  std::string problem;  // a fragment of the message, with the field's path where there is one
  bool threeD = false;
};

void runCases(const std::vector<Case>& cases) {
  TempDir dir;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Json header = c.threeD ? baseHeader3() : baseHeader();
    std::vector<Json> steps = c.threeD ? baseSteps3() : baseSteps();
    c.change(header, steps);
    const std::string path = dir.write(c.name + ".jsonl", text(header, steps));
    EXPECT_INPUT_ERROR(readMeasurementLog(path), path, c.line, c.problem);
  }
}

TEST(MeasurementLogErrors, BaseLogsAreValid) {
  TempDir dir;
  EXPECT_EQ(readMeasurementLog(dir.write("two.jsonl", text(baseHeader(), baseSteps()))).steps.size(), 3u);
  const MeasurementLog three = readMeasurementLog(dir.write("three.jsonl", text(baseHeader3(), baseSteps3())));
  EXPECT_EQ(three.steps.size(), 2u);
  // Scores may leave the simplex.
  EXPECT_EQ(three.steps[0].detections[0].classVector->sum(), 1.3 - 0.4);
}

TEST(MeasurementLogErrors, Header) {
  runCases({
      {"missing_dimension", [](Json& h, auto&) { h.erase("dimension"); }, 1, "missing field 'dimension'"},
      {"missing_sensor_kind", [](Json& h, auto&) { h["sensor"].erase("kind"); }, 1, "sensor: missing field 'kind'"},
      {"unknown_field", [](Json& h, auto&) { h["dimensions"] = 2; }, 1,
       "unknown field 'dimensions' (accepted: format, version, dimension"},
      {"unknown_sensor_field", [](Json& h, auto&) { h["sensor"]["maxrange"] = 2.0; }, 1,
       "sensor: unknown field 'maxrange'"},
      {"wrong_format", [](Json& h, auto&) { h["format"] = "semslam-graph"; }, 1,
       "format: expected \"semslam-log\", found \"semslam-graph\""},
      {"newer_version", [](Json& h, auto&) { h["version"] = 3; }, 1, "version 3 is newer than this reader"},
      {"version_zero", [](Json& h, auto&) { h["version"] = 0; }, 1, "invalid version 0"},
      {"version_string", [](Json& h, auto&) { h["version"] = "1"; }, 1,
       "version: expected an integer, found string \"1\""},
      {"version_float", [](Json& h, auto&) { h["version"] = 1.0; }, 1, "version: expected an integer, found number 1.0"},
      {"dimension_4", [](Json& h, auto&) { h["dimension"] = 4; }, 1,
       "dimension: integer 4 is out of range: expected an integer in [2, 3]"},
      {"classes_zero", [](Json& h, auto&) { h["classes"] = 0; }, 1, "classes: integer 0 is out of range"},
      {"classes_negative", [](Json& h, auto&) { h["classes"] = -3; }, 1, "classes: integer -3 is out of range"},
      {"unknown_semantic", [](Json& h, auto&) { h["semantic"] = "labels"; }, 1,
       "semantic: unknown semantic kind 'labels' (expected one of: none, label, probabilities, scores)"},
      {"semantic_not_string", [](Json& h, auto&) { h["semantic"] = 1; }, 1,
       "semantic: expected a string, found number 1"},
      {"unknown_sensor", [](Json& h, auto&) { h["sensor"]["kind"] = "lidar"; }, 1,
       "sensor.kind: unknown sensor kind 'lidar'"},
      {"sensor_dimension", [](Json& h, auto&) { h["sensor"]["kind"] = "range-bearing-elevation"; }, 1,
       "sensor.kind: a range-bearing-elevation sensor needs dimension 3"},
      {"body_to_sensor_length", [](Json& h, auto&) { h["sensor"]["body_to_sensor"] = {0, 0, 0, 0, 0, 0, 1}; }, 1,
       "sensor.body_to_sensor: expected 3 numbers [x, y, theta], found 7"},
      {"negative_range", [](Json& h, auto&) { h["sensor"]["max_range"] = -1; }, 1, "sensor.max_range: must be >= 0"},
      {"huge_max_range", [](Json& h, auto&) { h["sensor"]["max_range"] = 1e200; }, 1,
       "sensor.max_range: number 1e+200 is too large"},
      {"huge_body_to_sensor", [](Json& h, auto&) { h["sensor"]["body_to_sensor"][0] = -1e30; }, 1,
       "sensor.body_to_sensor[0]: number -1e+30 is too large"},
      {"huge_initial_pose", [](Json& h, auto&) { h["initial_pose"]["mean"][1] = 1e308; }, 1,
       "initial_pose.mean[1]: number 1e+308 is too large"},
      {"huge_landmark_prior", [](Json& h, auto&) { h["landmark_priors"][0]["mean"][0] = 2e7; }, 1,
       "landmark_priors[0].mean[0]: number 20000000.0 is too large"},
      {"huge_landmark_prior_variance", [](Json& h, auto&) { h["landmark_priors"][0]["covariance"][0][0] = 1e19; }, 1,
       "landmark_priors[0].covariance[0][0]: variance number 1e+19 is outside [1e-18, 1e18]"},
      {"field_of_view", [](Json& h, auto&) { h["sensor"]["field_of_view"] = 7.0; }, 1,
       "sensor.field_of_view: must be in [0, 2 pi]"},
      {"unknown_classifier", [](Json& h, auto&) { h["classifier"]["kind"] = "gaussian"; }, 1,
       "classifier.kind: unknown classifier kind 'gaussian' (expected one of: none, categorical, viewpoint-gaussian)"},
      {"classifier_missing_parameter", [](Json& h, auto&) { h["classifier"].erase("misclassification"); }, 1,
       "classifier: missing field 'misclassification'"},
      {"classifier_wrong_parameter", [](Json& h, auto&) { h["classifier"]["alpha"] = 0.2; }, 1,
       "classifier: unknown field 'alpha' (accepted: kind, misclassification, table)"},
      {"misclassification_range", [](Json& h, auto&) { h["classifier"]["misclassification"] = 1.5; }, 1,
       "classifier.misclassification: a probability must be in [0, 1]"},
      {"classifier_semantic_mismatch", [](Json& h, auto&) { h["semantic"] = "scores"; }, 1,
       "classifier: classifier 'categorical' cannot explain the semantic 'scores'"},
      {"classifier_without_semantic", [](Json& h, auto&) { h["semantic"] = "none"; }, 1,
       "cannot explain the semantic 'none'"},
      {"landmarks_have_pose_type", [](Json& h, auto&) { h["landmarks_have_pose"] = 0; }, 1,
       "landmarks_have_pose: expected true or false, found number 0"},
      {"initial_pose_length", [](Json& h, auto&) { h["initial_pose"]["mean"] = {0, 0}; }, 1,
       "initial_pose.mean: expected 3 numbers [x, y, theta], found 2"},
      {"initial_pose_not_pd", [](Json& h, auto&) { h["initial_pose"]["covariance"][2][2] = 0.0; }, 1,
       "initial_pose.covariance: not positive definite"},
      {"initial_pose_missing_covariance", [](Json& h, auto&) { h["initial_pose"].erase("covariance"); }, 1,
       "initial_pose: missing field 'covariance'"},
      {"prior_duplicate_id", [](Json& h, auto&) { h["landmark_priors"].push_back(h["landmark_priors"][0]); }, 1,
       "landmark_priors[1].id: duplicate landmark id 0"},
      {"prior_covariance_size", [](Json& h, auto&) { h["landmark_priors"][0]["covariance"] = {{1}}; }, 1,
       "landmark_priors[0].covariance: expected a 2x2 matrix (2 rows over x, y), found 1 rows"},
      {"prior_negative_id", [](Json& h, auto&) { h["landmark_priors"][0]["id"] = -1; }, 1,
       "landmark_priors[0].id: integer -1 is out of range"},
      {"truth_class_range", [](Json& h, auto&) { h["landmark_truth"][0]["class"] = 3; }, 1,
       "landmark_truth[0].class: integer 3 is out of range: expected an integer in [0, 2]"},
      {"truth_pose_for_point", [](Json& h, auto&) {
         h["landmark_truth"][1].erase("position");
         h["landmark_truth"][1]["pose"] = {5, -1, 0};
       },
       1, "landmark_truth[1]: found 'pose' but the header's landmarks_have_pose is false"},
      {"truth_missing_position", [](Json& h, auto&) { h["landmark_truth"][1].erase("position"); }, 1,
       "landmark_truth[1]: missing field 'position'"},
      {"truth_duplicate_id", [](Json& h, auto&) { h["landmark_truth"][1]["id"] = 0; }, 1,
       "landmark_truth[1].id: duplicate landmark id 0"},
      {"truth_position_nan_string", [](Json& h, auto&) { h["landmark_truth"][1]["position"][0] = "NaN"; }, 1,
       "landmark_truth[1].position[0]: expected a number, found string \"NaN\" (NaN and infinity are not allowed"},
      {"landmark_priors_not_array", [](Json& h, auto&) { h["landmark_priors"] = Json::object(); }, 1,
       "landmark_priors: expected an array, found an object"},
      {"source_not_string", [](Json& h, auto&) { h["source"] = 5; }, 1, "source: expected a string, found number 5"},
      {"header_missing", [](Json& h, auto& s) { h = s[0]; }, 1,
       "expected the header on the first line: an object with \"format\": \"semslam-log\""},
      {"header_not_object", [](Json& h, auto&) { h = Json::array({1, 2}); }, 1,
       "expected the header on the first line"},
  });
}

TEST(MeasurementLogErrors, Steps) {
  const auto erase = [](const char* key) { return [key](Json&, std::vector<Json>& s) { s[1].erase(key); }; };
  runCases({
      {"missing_time", erase("time"), 3, "missing field 'time'"},
      {"missing_detections", erase("detections"), 3, "missing field 'detections'"},
      {"missing_odometry", erase("odometry"), 3, "missing field 'odometry' (every step after the first"},
      {"odometry_on_first_step", [](Json&, auto& s) { s[0]["odometry"] = s[1]["odometry"]; }, 2,
       "odometry: the first step has no odometry"},
      {"unknown_step_field", [](Json&, auto& s) { s[1]["stamp"] = 1.0; }, 3,
       "unknown field 'stamp' (accepted: time, detections, odometry, true_pose)"},
      {"second_header", [](Json& h, auto& s) { s[1] = h; }, 3, "a second header"},
      {"time_string", [](Json&, auto& s) { s[1]["time"] = "0.5"; }, 3, "time: expected a number, found string \"0.5\""},
      {"time_null", [](Json&, auto& s) { s[1]["time"] = nullptr; }, 3,
       "time: expected a number, found null (NaN and infinity are not allowed"},
      {"time_nan_string", [](Json&, auto& s) { s[1]["time"] = "NaN"; }, 3, "NaN and infinity are not allowed"},
      {"time_infinity_string", [](Json&, auto& s) { s[1]["time"] = "-Infinity"; }, 3,
       "time: expected a number, found string \"-Infinity\" (NaN and infinity are not allowed"},
      {"time_boolean", [](Json&, auto& s) { s[1]["time"] = true; }, 3, "time: expected a number, found true"},
      {"time_equal", [](Json&, auto& s) { s[2]["time"] = 0.5; }, 4,
       "time: time 0.5 is not after the previous step's time 0.5 (times must increase strictly)"},
      {"time_decreasing", [](Json&, auto& s) { s[2]["time"] = 0.25; }, 4, "is not after the previous step's time"},
      {"odometry_missing_increment", [](Json&, auto& s) { s[1]["odometry"].erase("increment"); }, 3,
       "odometry: missing field 'increment'"},
      {"odometry_length", [](Json&, auto& s) { s[1]["odometry"]["increment"] = {1, 0, 0, 0}; }, 3,
       "odometry.increment: expected 3 numbers [x, y, theta], found 4"},
      {"odometry_not_array", [](Json&, auto& s) { s[1]["odometry"]["increment"] = 1.0; }, 3,
       "odometry.increment: expected an array of 3 numbers [x, y, theta], found number 1.0"},
      {"odometry_nan_entry", [](Json&, auto& s) { s[1]["odometry"]["increment"][2] = "nan"; }, 3,
       "odometry.increment[2]: expected a number, found string \"nan\""},
      {"covariance_not_pd", [](Json&, auto& s) { s[1]["odometry"]["covariance"][1][1] = -0.01; }, 3,
       "odometry.covariance: not positive definite"},
      {"covariance_singular", [](Json&, auto& s) { s[1]["odometry"]["covariance"][0] = {0, 0, 0}; }, 3,
       "odometry.covariance: not positive definite"},
      {"covariance_not_pd_off_diagonal",
       [](Json&, auto& s) { s[1]["odometry"]["covariance"][0][1] = s[1]["odometry"]["covariance"][1][0] = 1.0; }, 3,
       "odometry.covariance: not positive definite"},
      // Finite but huge numbers (issue 16): refused at the line, not left to overflow in the solver.
      {"odometry_huge", [](Json&, auto& s) { s[1]["odometry"]["increment"][0] = 1e308; }, 3,
       "odometry.increment[0]: number 1e+308 is too large: coordinates, ranges and angles are at most 1e7"},
      {"odometry_huge_angle", [](Json&, auto& s) { s[1]["odometry"]["increment"][2] = -1e200; }, 3,
       "odometry.increment[2]: number -1e+200 is too large"},
      {"odometry_huge_variance", [](Json&, auto& s) { s[1]["odometry"]["covariance"][0][0] = 1e300; }, 3,
       "odometry.covariance[0][0]: variance number 1e+300 is outside [1e-18, 1e18]"},
      {"odometry_tiny_variance", [](Json&, auto& s) { s[1]["odometry"]["covariance"][2][2] = 1e-300; }, 3,
       "odometry.covariance[2][2]: variance number 1e-300 is outside [1e-18, 1e18]"},
      {"geometry_huge", [](Json&, auto& s) { s[1]["detections"][1]["geometry"][0] = 1e308; }, 3,
       "detections[1].geometry[0]: number 1e+308 is too large"},
      {"geometry_tiny_range", [](Json&, auto& s) { s[1]["detections"][1]["geometry"][0] = 1e-300; }, 3,
       "detections[1].geometry: the range must be at least 1e-6"},
      {"detection_huge_variance", [](Json&, auto& s) { s[1]["detections"][0]["covariance"][1][1] = 1e308; }, 3,
       "detections[0].covariance[1][1]: variance number 1e+308 is outside"},
      {"true_pose_huge", [](Json&, auto& s) { s[0]["true_pose"][1] = 1e154; }, 2,
       "true_pose[1]: number 1e+154 is too large"},
      // Positive definite to Cholesky, but not through the rotations and sums the models take of it: the hybrid
      // belief stopped with "covariance is not positive definite" at no line (issue 16).
      {"covariance_badly_conditioned",
       [](Json&, auto& s) {
         s[1]["odometry"]["covariance"][0][0] = 1e-18;
         s[1]["odometry"]["covariance"][1][1] = 1e18;
       },
       3, "odometry.covariance: badly conditioned: eigenvalues from 1e-18 to 1e+18, a ratio above 1e12"},
      {"detection_nearly_singular",
       [](Json&, auto& s) { s[1]["detections"][0]["covariance"] = {{1.0, 1.0 - 1e-15}, {1.0 - 1e-15, 1.0}}; }, 3,
       "detections[0].covariance: badly conditioned"},
      {"covariance_not_symmetric", [](Json&, auto& s) { s[1]["odometry"]["covariance"][0][2] = 0.0005; }, 3,
       "odometry.covariance: not symmetric: entry (0, 2) is 0.00050000000000000001 but (2, 0) is 0"},
      {"covariance_wrong_size", [](Json&, auto& s) { s[1]["odometry"]["covariance"] = {{1, 0}, {0, 1}}; }, 3,
       "odometry.covariance: expected a 3x3 matrix (3 rows over x, y, theta), found 2 rows"},
      {"covariance_short_row", [](Json&, auto& s) { s[1]["odometry"]["covariance"][1] = {0, 1}; }, 3,
       "odometry.covariance[1]: expected a row of 3 numbers (the matrix is 3x3), found 2"},
      {"covariance_flat", [](Json&, auto& s) { s[1]["odometry"]["covariance"] = {1, 0, 0}; }, 3,
       "odometry.covariance[0]: expected a row of 3 numbers, found number 1"},
      {"covariance_null", [](Json&, auto& s) { s[1]["odometry"]["covariance"][2][2] = nullptr; }, 3,
       "odometry.covariance[2][2]: expected a number, found null"},
      {"true_pose_dimension", [](Json&, auto& s) { s[0]["true_pose"] = {0, 0, 0, 0, 0, 0, 1}; }, 2,
       "true_pose: expected 3 numbers [x, y, theta], found 7"},
      {"detections_not_array", [](Json&, auto& s) { s[1]["detections"] = Json::object(); }, 3,
       "detections: expected an array, found an object"},
      {"detection_not_object", [](Json&, auto& s) { s[1]["detections"][1] = 5; }, 3,
       "detections[1]: expected an object, found number 5"},
      {"detection_missing_covariance", [](Json&, auto& s) { s[1]["detections"][1].erase("covariance"); }, 3,
       "detections[1]: missing field 'covariance'"},
      {"detection_missing_geometry", [](Json&, auto& s) { s[1]["detections"][0].erase("geometry"); }, 3,
       "detections[0]: missing field 'geometry'"},
      {"detection_typo", [](Json&, auto& s) { s[1]["detections"][0]["lable"] = 1; }, 3,
       "detections[0]: unknown field 'lable' (accepted: geometry, covariance, label, truth, clutter_source)"},
      {"geometry_length", [](Json&, auto& s) { s[1]["detections"][1]["geometry"] = {3.0, 1.0, 0.0}; }, 3,
       "detections[1].geometry: expected 2 numbers [range, bearing], found 3"},
      {"geometry_range", [](Json&, auto& s) { s[1]["detections"][1]["geometry"][0] = -3.0; }, 3,
       "detections[1].geometry: the range must be at least 1e-6 (docs/measurement-log.md), found -3"},
      {"geometry_covariance_size", [](Json&, auto& s) { s[0]["detections"][0]["covariance"] = s[1]["odometry"]["covariance"]; },
       2, "detections[0].covariance: expected a 2x2 matrix (2 rows over range, bearing), found 3 rows"},
      {"label_missing", [](Json&, auto& s) { s[1]["detections"][1].erase("label"); }, 3,
       "detections[1]: missing field 'label'"},
      {"label_range", [](Json&, auto& s) { s[1]["detections"][1]["label"] = 3; }, 3,
       "detections[1].label: integer 3 is out of range: expected an integer in [0, 2]"},
      {"label_negative", [](Json&, auto& s) { s[1]["detections"][1]["label"] = -1; }, 3,
       "detections[1].label: integer -1 is out of range"},
      {"label_float", [](Json&, auto& s) { s[1]["detections"][1]["label"] = 1.0; }, 3,
       "detections[1].label: expected an integer, found number 1.0"},
      {"label_string", [](Json&, auto& s) { s[1]["detections"][1]["label"] = "car"; }, 3,
       "detections[1].label: expected an integer, found string \"car\""},
      {"semantic_mismatch", [](Json&, auto& s) { s[1]["detections"][1]["probabilities"] = {0.2, 0.3, 0.5}; }, 3,
       "detections[1]: field 'probabilities' does not match the header's semantic 'label' (expected 'label')"},
      {"truth_unknown_string", [](Json&, auto& s) { s[1]["detections"][1]["truth"] = "clutter"; }, 3,
       "detections[1].truth: expected a landmark id, \"not-a-landmark\" or \"unknown\", found string \"clutter\""},
      {"truth_unknown_in_version_1", [](Json&, auto& s) { s[1]["detections"][1]["truth"] = "unknown"; }, 3,
       "detections[1].truth: \"unknown\" truth needs version 2 or later; this file is version 1"},
      {"clutter_source_on_unknown", [](Json& h, auto& s) {
         h["version"] = 2;
         s[1]["detections"][1]["truth"] = "unknown";
         s[1]["detections"][1]["clutter_source"] = 1;
       },
       3, "detections[1].clutter_source: a clutter source needs \"truth\": \"not-a-landmark\""},
      {"truth_not_in_header", [](Json&, auto& s) { s[1]["detections"][0]["truth"] = 7; }, 3,
       "detections[0].truth: landmark 7 is not in the header's landmark_truth"},
      {"truth_negative", [](Json&, auto& s) { s[1]["detections"][0]["truth"] = -1; }, 3,
       "detections[0].truth: integer -1 is out of range"},
      {"truth_null", [](Json&, auto& s) { s[1]["detections"][0]["truth"] = nullptr; }, 3,
       "detections[0].truth: expected a landmark id, \"not-a-landmark\" or \"unknown\", found null"},
      {"clutter_source_on_a_landmark", [](Json&, auto& s) { s[1]["detections"][0]["clutter_source"] = 2; }, 3,
       "detections[0].clutter_source: a clutter source needs \"truth\": \"not-a-landmark\""},
      {"clutter_source_negative", [](Json&, auto& s) {
         s[1]["detections"][0]["truth"] = "not-a-landmark";
         s[1]["detections"][0]["clutter_source"] = -3;
       }, 3, "detections[0].clutter_source: integer -3 is out of range"},
      {"step_not_object", [](Json&, auto& s) { s[2] = Json::array(); }, 4, "expected an object, found an array of 0"},
  });
}

TEST(MeasurementLogErrors, ClassVectors) {
  const auto probabilities = [](Json& h, std::vector<Json>& s) {
    h["semantic"] = "probabilities";
    for (Json& step : s) {
      for (Json& d : step["detections"]) {
        d.erase("label");
        d["probabilities"] = {0.25, 0.25, 0.5};
      }
    }
  };
  const auto with = [probabilities](std::function<void(Json&)> edit) {
    return [probabilities, edit](Json& h, std::vector<Json>& s) {
      probabilities(h, s);
      edit(s[1]["detections"][1]);
    };
  };
  runCases({
      {"probabilities_size", with([](Json& d) { d["probabilities"] = {0.5, 0.5}; }), 3,
       "detections[1].probabilities: expected 3 numbers (one per class: the header has 3 classes), found 2"},
      {"probabilities_negative", with([](Json& d) { d["probabilities"] = {-0.25, 0.75, 0.5}; }), 3,
       "detections[1].probabilities: probabilities must be non-negative, found -0.25 for class 0"},
      {"probabilities_sum", with([](Json& d) { d["probabilities"] = {0.2, 0.2, 0.5}; }), 3,
       "detections[1].probabilities: probabilities must sum to 1 (within 1e-6), found a sum of 0.9"},
      {"probabilities_missing", with([](Json& d) { d.erase("probabilities"); }), 3,
       "detections[1]: missing field 'probabilities'"},
      {"probabilities_with_label", with([](Json& d) { d["label"] = 1; }), 3,
       "detections[1]: field 'label' does not match the header's semantic 'probabilities'"},
      {"probabilities_null_entry", with([](Json& d) { d["probabilities"][2] = nullptr; }), 3,
       "detections[1].probabilities[2]: expected a number, found null"},
  });
  // Within 1e-6 of one is accepted.
  TempDir dir;
  Json header = baseHeader();
  std::vector<Json> steps = baseSteps();
  probabilities(header, steps);
  steps[1]["detections"][1]["probabilities"] = {0.2500004, 0.25, 0.5};
  EXPECT_NO_THROW(readMeasurementLog(dir.write("near.jsonl", text(header, steps))));
}

TEST(MeasurementLogErrors, ThreeDimensional) {
  runCases({
      {"scores_size", [](Json&, auto& s) { s[0]["detections"][0]["scores"] = {1.0, 2.0, 3.0}; }, 2,
       "detections[0].scores: expected 2 numbers (one per class: the header has 2 classes), found 3", true},
      {"scores_inf_string", [](Json&, auto& s) { s[0]["detections"][0]["scores"][1] = "inf"; }, 2,
       "detections[0].scores[1]: expected a number, found string \"inf\" (NaN and infinity are not allowed", true},
      {"elevation_range", [](Json&, auto& s) { s[0]["detections"][0]["geometry"][2] = 2.0; }, 2,
       "detections[0].geometry: the elevation must be in [-pi/2, pi/2], found 2", true},
      {"geometry_2d_in_3d", [](Json&, auto& s) { s[0]["detections"][0]["geometry"] = {3.0, 0.2}; }, 2,
       "detections[0].geometry: expected 3 numbers [range, bearing, elevation], found 2", true},
      {"odometry_2d_in_3d", [](Json&, auto& s) { s[1]["odometry"]["increment"] = {1, 0, 0}; }, 3,
       "odometry.increment: expected 7 numbers [x, y, z, qx, qy, qz, qw], found 3", true},
      {"quaternion_not_unit", [](Json&, auto& s) { s[1]["true_pose"] = {1, 0, 0, 0, 0, 0, 2}; }, 3,
       "true_pose: the quaternion (qx, qy, qz, qw) must have norm 1 (within 1e-6), found norm 2", true},
      {"quaternion_zero", [](Json&, auto& s) { s[1]["true_pose"] = {1, 0, 0, 0, 0, 0, 0}; }, 3,
       "true_pose: the quaternion (qx, qy, qz, qw) must have norm 1", true},
      {"covariance_6_not_pd", [](Json&, auto& s) { s[1]["odometry"]["covariance"][5][5] = -1; }, 3,
       "odometry.covariance: not positive definite", true},
      {"covariance_3_in_3d", [](Json&, auto& s) {
         s[1]["odometry"]["covariance"] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
       },
       3, "odometry.covariance: expected a 6x6 matrix (6 rows over x, y, z, rx, ry, rz), found 3 rows", true},
      {"truth_position_for_pose", [](Json& h, auto&) {
         h["landmark_truth"][0].erase("pose");
         h["landmark_truth"][0]["position"] = {1, 2, 3};
       },
       1, "landmark_truth[0]: found 'position' but the header's landmarks_have_pose is true: expected 'pose'", true},
      {"range_bearing_in_3d", [](Json& h, auto&) { h["sensor"]["kind"] = "range-bearing"; }, 1,
       "sensor.kind: a range-bearing sensor needs dimension 2", true},
      {"viewpoint_alpha", [](Json& h, auto&) { h["classifier"]["alpha"] = 1.5; }, 1,
       "classifier.alpha: the viewpoint dependency must be in [0, 1]", true},
      {"viewpoint_sharpness", [](Json& h, auto&) { h["classifier"]["sharpness"] = 0; }, 1,
       "classifier.sharpness: must be positive", true},
      {"viewpoint_label", [](Json& h, auto& s) {
         h["semantic"] = "label";
         s[0]["detections"][0].erase("scores");
         s[0]["detections"][0]["label"] = 1;
       },
       1, "classifier 'viewpoint-gaussian' cannot explain the semantic 'label'", true},
  });
}

// Cases written as raw text: what a JSON library cannot produce.
TEST(MeasurementLogErrors, RawText) {
  TempDir dir;
  const std::string header = baseHeader().dump();
  const std::string step0 = baseSteps()[0].dump();
  const std::string step1 = baseSteps()[1].dump();
  struct Raw {
    std::string name;
    std::string contents;
    std::size_t line;
    std::string problem;
  };
  const std::vector<Raw> cases = {
      {"empty", "", 0, "the file is empty: expected a header line"},
      {"blank_only", "\n  \n\r\n", 0, "the file is empty"},
      {"header_only", header + "\n", 0, "no time steps: the file has a header but no step lines"},
      {"truncated_line", header + "\n" + step0.substr(0, step0.size() / 2) + "\n", 2, "not valid JSON: column "},
      {"truncated_file", header + "\n" + step0 + "\n" + step1.substr(0, step1.size() - 3), 3, "not valid JSON"},
      {"truncated_header", header.substr(0, 40) + "\n" + step0 + "\n", 1, "not valid JSON"},
      {"nan_literal", header + "\n" + R"({"time":NaN,"detections":[]})" + "\n", 2, "not valid JSON"},
      {"infinity_literal", header + "\n" + R"({"time":-Infinity,"detections":[]})" + "\n", 2, "not valid JSON"},
      {"overflow", header + "\n" + R"({"time":1e999,"detections":[]})" + "\n", 2,
       "not valid JSON: number overflow parsing '1e999'"},
      {"trailing_garbage", header + "\n" + step0 + " x\n", 2, "not valid JSON"},
      {"two_records_on_a_line", header + "\n" + step0 + step0 + "\n", 2, "not valid JSON"},
      {"single_quotes", header + "\n" + R"({'time':0,'detections':[]})" + "\n", 2, "not valid JSON"},
      {"duplicate_key", header + "\n" + R"({"time":0,"time":1,"detections":[]})" + "\n", 2,
       "duplicate key 'time' (every key appears once)"},
      {"duplicate_nested_key",
       header + "\n" + R"({"time":0,"detections":[{"geometry":[1,0],"geometry":[2,0],"covariance":[[1,0],[0,1]],"label":0}]})" +
           "\n",
       2, "duplicate key 'geometry'"},
      {"blank_lines_counted", header + "\n\n\n" + step0 + "\n\n" + R"({"time":0.5,"detections":[]})" + "\n", 6,
       "missing field 'odometry'"},
  };
  for (const Raw& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = dir.write(c.name + ".jsonl", c.contents);
    EXPECT_INPUT_ERROR(readMeasurementLog(path), path, c.line, c.problem);
  }
  const std::string missing = dir.path("does_not_exist.jsonl");
  EXPECT_INPUT_ERROR(readMeasurementLog(missing), missing, 0, "file does not exist");
  EXPECT_INPUT_ERROR(readMeasurementLog(dir.path("")), dir.path(""), 0, "is a directory");
}

TEST(MeasurementLogErrors, StreamingReaderReportsTheBadStepAfterTheGoodOnes) {
  TempDir dir;
  std::vector<Json> steps = baseSteps();
  steps[2]["time"] = 0.0;
  const std::string path = dir.write("late.jsonl", text(baseHeader(), steps));
  MeasurementLogReader reader(path);
  TimeStep step;
  EXPECT_TRUE(reader.next(step));
  EXPECT_TRUE(reader.next(step));
  EXPECT_EQ(step.detections.size(), 2u);
  EXPECT_INPUT_ERROR(reader.next(step), path, 4, "times must increase strictly");
}

}  // namespace
}  // namespace semslam
