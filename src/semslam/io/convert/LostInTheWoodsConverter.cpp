#include "semslam/io/convert/LostInTheWoodsConverter.h"

#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "semslam/core/InputError.h"
#include "semslam/io/InputMagnitudes.h"
#include "semslam/io/LineReader.h"
#include "semslam/io/convert/ConversionCommon.h"
#include "semslam/models/UnicycleModel.h"

namespace semslam {

namespace {

// Time stamps are printed with 6 decimals; rows of the same instant carry the same text.
constexpr double kTimeTolerance = 1e-6;

struct LitwParameters {
  double d = 0.0, rangeVariance = 0.0, bearingVariance = 0.0, velocityVariance = 0.0, turnRateVariance = 0.0;
  std::size_t dLine = 0;  // the line of 'd' (the sensor offset)
};

struct ParameterValue {
  double value = 0.0;
  std::size_t line = 0;
};

LitwParameters readParameters(const std::string& path) {
  std::map<std::string, ParameterValue> values;
  LineReader reader(path);
  while (reader.next()) {
    if (reader.valueCount() != 1) reader.fail("expected 'name value'");
    values[std::string(reader.tag())] = ParameterValue{reader.number(1), reader.lineNumber()};
  }
  auto find = [&](const char* name) {
    const auto it = values.find(name);
    if (it == values.end()) throw InputError(path, 0, std::string("missing parameter '") + name + "'");
    return it->second;
  };
  auto get = [&](const char* name, bool positive) {
    const ParameterValue parameter = find(name);
    if (positive && !(parameter.value > 0.0)) {
      throw InputError(path, parameter.line, std::string("parameter '") + name + "' must be > 0");
    }
    return parameter.value;
  };
  LitwParameters p;
  p.d = get("d", false);
  p.dLine = find("d").line;
  p.rangeVariance = get("r_var", true);
  p.bearingVariance = get("b_var", true);
  // Every detection's covariance is diag(r_var, b_var): a variance the log may not hold is this file's error.
  for (const char* name : {"r_var", "b_var"}) {
    const ParameterValue parameter = find(name);
    if (parameter.value < jsonio::kMinVariance || parameter.value > jsonio::kMaxVariance) {
      throw InputError(path, parameter.line,
                       std::string("parameter '") + name + "' must be in [1e-18, 1e18] (a log's variances)");
    }
  }
  p.velocityVariance = get("v_var", true);
  p.turnRateVariance = get("om_var", true);
  return p;
}

}  // namespace

MeasurementLog convertLostInTheWoods(const std::string& folder, const ConvertOptions& options, ConversionStats* stats) {
  validateConvertOptions(options, 2);
  const std::string odometryPath = datasetFile(folder, "odometry.txt");
  const std::string truthPath = datasetFile(folder, "groundtruth.txt");
  const std::string landmarkPath = datasetFile(folder, "landmarks_groundtruth.txt");
  const std::string measurementPath = datasetFile(folder, "measurements.txt");
  const std::string parametersPath = datasetFile(folder, "params.txt");
  const LitwParameters params = readParameters(parametersPath);

  MeasurementLog raw;
  LogSources sources;
  sources.dataset = folder;
  sources.sensor = SourceLine{parametersPath, params.dLine, 0};
  LogHeader& header = raw.header;
  header.dimension = 2;
  header.sensor.kind = SensorKind::RangeBearing;
  header.sensor.bodyToSensor = SE2(params.d, 0.0, 0.0);
  header.sensor.maxRange = 0.0;
  header.sensor.fieldOfView = 4.0 * std::numbers::pi / 3.0;

  const std::set<int> landmarkIds =
      readLandmarkTruthTable(landmarkPath, 2, 3, "id x y", "landmark id", header.landmarkTruth, sources.landmarks);

  // Steps at the odometry stamps; the increment into step k uses row k-1's velocities.
  const std::vector<NumericRow> odometry = readDatasetTable(odometryPath, 3, "t v omega");
  const UnicycleModel model(params.velocityVariance, params.turnRateVariance);
  raw.steps.resize(odometry.size());
  sources.steps.resize(odometry.size());
  for (std::size_t k = 0; k < odometry.size(); ++k) {
    raw.steps[k].time = odometry[k].values[0];
    sources.steps[k].step = SourceLine{odometryPath, odometry[k].line, 0};
    if (k == 0) continue;
    sources.steps[k].odometry = SourceLine{odometryPath, odometry[k - 1].line, 0};
    const double dt = odometry[k].values[0] - odometry[k - 1].values[0];
    if (!(dt > 0.0)) throw InputError(odometryPath, odometry[k].line, "time stamps must increase");
    raw.steps[k].odometry = model.integrate(odometry[k - 1].values[1], odometry[k - 1].values[2], dt);
  }

  const std::vector<NumericRow> truth = readDatasetTable(truthPath, 5, "t x y theta valid");
  // One ground-truth row per odometry row: the first row the other file lacks, at its line.
  const std::string counts = " (groundtruth.txt has " + std::to_string(truth.size()) + " rows, odometry.txt " +
                             std::to_string(odometry.size()) + "; the converter expects one ground-truth row per "
                             "odometry time stamp)";
  if (truth.size() < odometry.size()) {
    throw InputError(odometryPath, odometry[truth.size()].line, "no ground-truth row for this time stamp" + counts);
  }
  if (truth.size() > odometry.size()) {
    throw InputError(truthPath, truth[odometry.size()].line, "no odometry row for this ground-truth row" + counts);
  }
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const NumericRow& row = truth[k];
    if (std::abs(row.values[0] - raw.steps[k].time) > kTimeTolerance) {
      throw InputError(truthPath, row.line, "time stamp differs from odometry.txt's row " + std::to_string(k + 1));
    }
    if (integerField(truthPath, row, 4, "valid flag", 0, 1) == 1) {
      raw.steps[k].truePose = SE2(row.values[1], row.values[2], row.values[3]);
      sources.steps[k].truePose = SourceLine{truthPath, row.line, 0};
    }
  }

  const Matrix covariance = diagonalCovariance({params.rangeVariance, params.bearingVariance});
  for (const NumericRow& row : readDatasetTable(measurementPath, 4, "t landmark_id range bearing")) {
    const std::optional<std::size_t> k = findStep(raw.steps, row.values[0], kTimeTolerance);
    if (!k) throw InputError(measurementPath, row.line, "time stamp matches no odometry time stamp");
    const int id = integerField(measurementPath, row, 1, "landmark id", 0, 1 << 30);
    if (landmarkIds.count(id) == 0) {
      throw InputError(measurementPath, row.line,
                       "landmark id " + std::to_string(id) + " is not in landmarks_groundtruth.txt");
    }
    Detection detection;
    detection.geometry = Vector2(row.values[2], row.values[3]);
    detection.covariance = covariance;
    detection.truthId = id;
    raw.steps[*k].detections.push_back(std::move(detection));
    sources.steps[*k].detections.push_back(SourceLine{measurementPath, row.line, 0});
  }

  std::ostringstream source;
  source.precision(12);
  source << "UTIAS Lost in the Woods (" << folder << "), semslam convert utias-lost-in-the-woods: steps at the "
         << "odometry stamps, unicycle odometry from the previous stamp's (v, omega) with v_var="
         << params.velocityVariance << " om_var=" << params.turnRateVariance
         << ", range-bearing from the laser at d=" << params.d << " m with r_var=" << params.rangeVariance
         << " b_var=" << params.bearingVariance << ", Vicon truth where valid";
  header.source = source.str();
  return finishConversion(std::move(raw), std::move(sources), options, stats);
}

}  // namespace semslam
