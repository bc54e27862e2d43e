#include "semslam/io/RunMetricsFile.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <variant>

#include "semslam/core/InputError.h"
#include "semslam/core/InputExcerpt.h"
#include "semslam/core/InputFile.h"
#include "semslam/core/JsonNesting.h"
#include "semslam/core/Version.h"
#include "semslam/io/AtomicFile.h"

namespace semslam {
namespace {

using Json = nlohmann::ordered_json;

using NumberField = double RunMetrics::*;
using CountField = std::optional<long long> RunMetrics::*;
using TextField = std::string RunMetrics::*;

struct Field {
  const char* key;
  std::variant<NumberField, CountField, TextField> member;
};

// The one table of the schema: file order, key, member. "schema" and "version" are written before these.
const std::vector<Field>& fields() {
  static const std::vector<Field> table = {
      {"method", &RunMetrics::method},
      {"dimension", &RunMetrics::dimension},
      {"time_s", &RunMetrics::timeSeconds},
      {"alignment", &RunMetrics::alignment},
      {"poses", &RunMetrics::poses},
      {"ate_rmse", &RunMetrics::ateRmse},
      {"ate_mean", &RunMetrics::ateMean},
      {"ate_median", &RunMetrics::ateMedian},
      {"ate_max", &RunMetrics::ateMax},
      {"rot_rmse", &RunMetrics::rotRmse},
      {"rot_mean", &RunMetrics::rotMean},
      {"rot_median", &RunMetrics::rotMedian},
      {"rot_max", &RunMetrics::rotMax},
      {"da_accuracy", &RunMetrics::daAccuracy},
      {"da_correct", &RunMetrics::daCorrect},
      {"da_total", &RunMetrics::daTotal},
      {"da_null", &RunMetrics::daNull},
      {"da_clutter", &RunMetrics::daClutter},
      {"da_accuracy_real", &RunMetrics::daAccuracyReal},
      {"pairwise_precision", &RunMetrics::pairwisePrecision},
      {"pairwise_recall", &RunMetrics::pairwiseRecall},
      {"clutter_rejected", &RunMetrics::clutterRejected},
      {"clutter_rejected_moving", &RunMetrics::clutterRejectedMoving},
      {"clutter_rejected_false_positive", &RunMetrics::clutterRejectedFalsePositive},
      {"landmarks_merged", &RunMetrics::landmarksMerged},
      {"landmarks_split", &RunMetrics::landmarksSplit},
      {"real_unassigned", &RunMetrics::realUnassigned},
      {"real_on_another_landmark", &RunMetrics::realOnAnotherLandmark},
      {"real_on_unmatched_estimate", &RunMetrics::realOnUnmatchedEstimate},
      {"decision_accuracy_real", &RunMetrics::decisionAccuracyReal},
      {"decision_clutter_rejected", &RunMetrics::decisionClutterRejected},
      {"decisions_resighting_elsewhere", &RunMetrics::decisionsResightingElsewhere},
      {"decisions_resighting_unassigned", &RunMetrics::decisionsResightingUnassigned},
      {"decisions_first_sighting_forced", &RunMetrics::decisionsFirstSightingForced},
      {"landmarks_estimated", &RunMetrics::landmarksEstimated},
      {"landmarks_true", &RunMetrics::landmarksTrue},
      {"landmark_count_error", &RunMetrics::landmarkCountError},
      {"landmarks_matched", &RunMetrics::landmarksMatched},
      {"landmark_rmse", &RunMetrics::landmarkRmse},
      {"class_accuracy", &RunMetrics::classAccuracy},
      {"nees_mean", &RunMetrics::neesMean},
      {"nees_count", &RunMetrics::neesCount},
      {"nees_dof", &RunMetrics::neesDof},
      {"nees_lower", &RunMetrics::neesLower},
      {"nees_upper", &RunMetrics::neesUpper},
      {"entropy", &RunMetrics::entropy},
      {"det_cov", &RunMetrics::detCov},
      {"err_wmax", &RunMetrics::errWmax},
      {"err_wavg", &RunMetrics::errWavg},
      {"ess", &RunMetrics::ess},
      {"assoc_weight_max", &RunMetrics::assocWeightMax},
      {"disambiguated_fraction", &RunMetrics::disambiguatedFraction},
      {"components", &RunMetrics::components},
      {"histories", &RunMetrics::histories},
  };
  return table;
}

Json toJsonValue(const RunMetrics& metrics, const Field& field) {
  if (const auto* number = std::get_if<NumberField>(&field.member)) {
    const double value = metrics.*(*number);
    return std::isfinite(value) ? Json(value) : Json(nullptr);
  }
  if (const auto* count = std::get_if<CountField>(&field.member)) {
    const std::optional<long long>& value = metrics.*(*count);
    return value ? Json(*value) : Json(nullptr);
  }
  const std::string& text = metrics.*std::get<TextField>(field.member);
  if (text.empty() && std::string_view(field.key) != "method") return Json(nullptr);
  return Json(text);
}

void fromJsonValue(RunMetrics& metrics, const Field& field, const Json& value, const std::string& source) {
  const auto fail = [&](const std::string& expected) {
    throw InputError(source, 0, std::string("field '") + field.key + "': expected " + expected + ", found " +
                                    value.dump());
  };
  if (const auto* number = std::get_if<NumberField>(&field.member)) {
    if (value.is_null()) {
      metrics.*(*number) = RunMetrics::kNotApplicable;
    } else if (value.is_number()) {
      metrics.*(*number) = value.get<double>();
    } else {
      fail("a number or null");
    }
    return;
  }
  if (const auto* count = std::get_if<CountField>(&field.member)) {
    if (value.is_null()) {
      metrics.*(*count) = std::nullopt;
    } else if (value.is_number_integer()) {
      metrics.*(*count) = value.get<long long>();
    } else {
      fail("an integer or null");
    }
    return;
  }
  if (value.is_null()) {
    metrics.*std::get<TextField>(field.member) = std::string();
  } else if (value.is_string()) {
    metrics.*std::get<TextField>(field.member) = value.get<std::string>();
  } else {
    fail("a string or null");
  }
}

}  // namespace

const std::vector<std::string>& runMetricsKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k{"schema", "version"};
    for (const Field& field : fields()) k.emplace_back(field.key);
    return k;
  }();
  return keys;
}

std::string runMetricsToJson(const RunMetrics& metrics) {
  Json json = Json::object();
  json["schema"] = std::string(kRunMetricsSchema);
  json["version"] = std::string(version());
  for (const Field& field : fields()) json[field.key] = toJsonValue(metrics, field);
  return json.dump(2) + "\n";
}

RunMetrics runMetricsFromJson(const std::string& text, const std::string& source) {
  Json json;
  try {
    requireJsonNestingAtMost(text, source, 1);
    json = Json::parse(text);
  } catch (const Json::exception& error) {
    // parse_error, and out_of_range for a number beyond a double (2e308): the fuzzer found the latter uncaught.
    throw InputError(source, 0, "not valid JSON: " + boundedMessage(error.what(), 200));
  }
  if (!json.is_object()) throw InputError(source, 0, "metrics.json must hold one JSON object");
  const auto schema = json.find("schema");
  if (schema == json.end() || !schema->is_string() || schema->get<std::string>() != kRunMetricsSchema) {
    throw InputError(source, 0,
                     "missing or unknown \"schema\" (expected \"" + std::string(kRunMetricsSchema) + "\")");
  }
  RunMetrics metrics;
  for (const Field& field : fields()) {
    const auto it = json.find(field.key);
    if (it != json.end()) fromJsonValue(metrics, field, *it, source);
  }
  return metrics;
}

void writeRunMetrics(const std::string& path, const RunMetrics& metrics) {
  const std::string text = runMetricsToJson(metrics);
  writeFileAtomically(path, [&](std::ostream& out) { out << text; });
}

RunMetrics readRunMetrics(const std::string& path) {
  return runMetricsFromJson(readInputText(path), path);
}

}  // namespace semslam
