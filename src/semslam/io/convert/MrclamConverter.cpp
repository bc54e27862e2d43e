#include "semslam/io/convert/MrclamConverter.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "semslam/core/ExactNumber.h"
#include "semslam/core/InputError.h"
#include "semslam/io/convert/ConversionCommon.h"
#include "semslam/models/UnicycleModel.h"

namespace semslam {

namespace {

// Stamps have millisecond resolution; equal text gives equal doubles, the tolerance only guards the lookup.
constexpr double kTimeTolerance = 1e-6;

// The true pose at `time`, interpolated between the samples around it (sorted by time); `sample` gets the index of
// the sample at or after `time`.
std::optional<Pose> interpolateTruth(const std::vector<double>& times, const std::vector<SE2>& poses, double time,
                                     std::size_t& sample) {
  const auto upper = std::lower_bound(times.begin(), times.end(), time);
  if (upper == times.end()) return std::nullopt;
  const std::size_t j = static_cast<std::size_t>(upper - times.begin());
  sample = j;
  if (times[j] == time) return Pose(poses[j]);
  if (j == 0) return std::nullopt;
  const double gap = times[j] - times[j - 1];
  if (gap > kMrclamMaxTruthGap) return std::nullopt;
  return Pose(poses[j - 1].interpolate(poses[j], (time - times[j - 1]) / gap));
}

}  // namespace

MeasurementLog convertMrclam(const std::string& folder, const ConvertOptions& options, ConversionStats* stats) {
  validateConvertOptions(options, 2);
  if (options.robot < 1 || options.robot > 5) {
    throw InputError("--robot must be one of MRCLAM's robots 1..5, got " + std::to_string(options.robot));
  }
  const std::string robot = "Robot" + std::to_string(options.robot);
  const std::string barcodePath = datasetFile(folder, "Barcodes.dat");
  const std::string landmarkPath = datasetFile(folder, "Landmark_Groundtruth.dat");
  const std::string odometryPath = datasetFile(folder, robot + "_Odometry.dat");
  const std::string measurementPath = datasetFile(folder, robot + "_Measurement.dat");
  const std::string truthPath = datasetFile(folder, robot + "_Groundtruth.dat");

  MeasurementLog raw;
  LogSources sources;
  sources.dataset = folder;
  LogHeader& header = raw.header;
  header.dimension = 2;
  header.sensor.kind = SensorKind::RangeBearing;
  header.sensor.bodyToSensor = SE2();
  header.sensor.maxRange = 0.0;
  header.sensor.fieldOfView = 1.2;

  const std::set<int> landmarks =
      readLandmarkTruthTable(landmarkPath, 2, 5, "subject x y x_sd y_sd", "subject", header.landmarkTruth,
                             sources.landmarks);
  std::map<int, int> subjectOfBarcode;
  for (const NumericRow& row : readDatasetTable(barcodePath, 2, "subject barcode")) {
    const int subject = integerField(barcodePath, row, 0, "subject", 0, 1 << 30);
    const int barcode = integerField(barcodePath, row, 1, "barcode", 0, 1 << 30);
    if (!subjectOfBarcode.emplace(barcode, subject).second) {
      throw InputError(barcodePath, row.line, "barcode " + std::to_string(barcode) + " appears twice");
    }
  }

  // Step times: every distinct odometry and measurement stamp.
  const std::vector<NumericRow> odometry = readDatasetTable(odometryPath, 3, "t v omega");
  const std::vector<NumericRow> measurements = readDatasetTable(measurementPath, 4, "t barcode range bearing");
  for (std::size_t i = 1; i < odometry.size(); ++i) {
    if (odometry[i].values[0] < odometry[i - 1].values[0]) {
      throw InputError(odometryPath, odometry[i].line, "time stamps must not decrease");
    }
  }
  // Each stamp with the first row (odometry before measurements, each in file order) that holds it.
  struct Stamp {
    double time;
    SourceLine row;
  };
  std::vector<Stamp> stamps;
  stamps.reserve(odometry.size() + measurements.size());
  // A command takes effect options.commandDelay after its stamp: that is where its step starts.
  const double delay = options.commandDelay;
  if (!(delay >= 0.0 && delay <= kMrclamMaxCommandDelay)) {
    throw InputError("mrclam: the command delay must be in [0, " + shortestExactNumber(kMrclamMaxCommandDelay) +
                     "] seconds, not " + shortestExactNumber(delay));
  }
  for (const NumericRow& row : odometry) {
    stamps.push_back(Stamp{row.values[0] + delay, SourceLine{odometryPath, row.line, 0}});
  }
  for (const NumericRow& row : measurements) {
    stamps.push_back(Stamp{row.values[0], SourceLine{measurementPath, row.line, 0}});
  }
  std::stable_sort(stamps.begin(), stamps.end(), [](const Stamp& a, const Stamp& b) { return a.time < b.time; });
  stamps.erase(std::unique(stamps.begin(), stamps.end(), [](const Stamp& a, const Stamp& b) { return a.time == b.time; }),
               stamps.end());
  std::vector<double> times;
  times.reserve(stamps.size());
  for (const Stamp& stamp : stamps) times.push_back(stamp.time);

  // Odometry: the command in force at the start of each interval.
  raw.steps.resize(times.size());
  sources.steps.resize(times.size());
  std::size_t next = 0;  // the first odometry row after the current step's stamp
  double v = 0.0, omega = 0.0;
  Vector3 slip = UnicycleModel::defaultFloor();
  slip.y() = kMrclamLateralIntensity;
  for (std::size_t k = 0; k < times.size(); ++k) {
    raw.steps[k].time = times[k];
    sources.steps[k].step = stamps[k].row;
    if (k > 0) {
      const double dt = times[k] - times[k - 1];
      const UnicycleModel model(kMrclamVelocityIntensity / dt, kMrclamTurnRateIntensity / dt, slip);
      raw.steps[k].odometry = model.integrate(v, omega, dt);
      // The command in force, or the step's own stamp before the first command.
      sources.steps[k].odometry = next > 0 ? SourceLine{odometryPath, odometry[next - 1].line, 0} : stamps[k].row;
    }
    while (next < odometry.size() && odometry[next].values[0] + delay <= times[k]) {
      v = odometry[next].values[1];
      omega = odometry[next].values[2];
      ++next;
    }
  }

  // Ground truth, interpolated at the step times.
  const std::vector<NumericRow> truth = readDatasetTable(truthPath, 4, "t x y theta");
  std::vector<double> truthTimes;
  std::vector<SE2> truthPoses;
  for (const NumericRow& row : truth) {
    if (!truthTimes.empty() && row.values[0] <= truthTimes.back()) {
      throw InputError(truthPath, row.line, "time stamps must increase");
    }
    truthTimes.push_back(row.values[0]);
    truthPoses.emplace_back(row.values[1], row.values[2], row.values[3]);
  }
  for (std::size_t k = 0; k < raw.steps.size(); ++k) {
    std::size_t sample = 0;
    raw.steps[k].truePose = interpolateTruth(truthTimes, truthPoses, raw.steps[k].time, sample);
    if (raw.steps[k].truePose) sources.steps[k].truePose = SourceLine{truthPath, truth[sample].line, 0};
  }

  // Detections: every measurement row, landmarks with their subject as truth, the rest as clutter.
  const Matrix covariance =
      diagonalCovariance({kMrclamRangeSigma * kMrclamRangeSigma, kMrclamBearingSigma * kMrclamBearingSigma});
  std::size_t robotSightings = 0, unknownBarcodes = 0;
  for (const NumericRow& row : measurements) {
    const std::optional<std::size_t> k = findStep(raw.steps, row.values[0], kTimeTolerance);
    if (!k) throw InputError(measurementPath, row.line, "internal error: no step at this time stamp");
    const int barcode = integerField(measurementPath, row, 1, "barcode", 0, 1 << 30);
    Detection detection;
    detection.geometry = Vector2(row.values[2], row.values[3]);
    detection.covariance = covariance;
    const auto subject = subjectOfBarcode.find(barcode);
    if (subject == subjectOfBarcode.end()) {
      detection.truthId = kNotALandmark;
      ++unknownBarcodes;
    } else if (landmarks.count(subject->second) == 0) {
      detection.truthId = kNotALandmark;
      detection.clutterSource = subject->second;  // the robot seen (subjects 1-5)
      ++robotSightings;
    } else {
      detection.truthId = subject->second;
    }
    raw.steps[*k].detections.push_back(std::move(detection));
    sources.steps[*k].detections.push_back(SourceLine{measurementPath, row.line, 0});
  }

  std::ostringstream source;
  source.precision(12);
  source << "UTIAS MRCLAM " << robot << " (" << folder << "), semslam convert mrclam: steps at every odometry and "
         << "measurement stamp, unicycle odometry of the command in force"
         << (delay > 0.0 ? " (from " + shortestExactNumber(delay) + " s after its stamp)" : std::string()) << " "
         << "with white input noise intensities "
         << kMrclamVelocityIntensity << " (m/s)^2 s and " << kMrclamTurnRateIntensity << " (rad/s)^2 s (lateral slip "
         << kMrclamLateralIntensity << " m^2/s), range-bearing with sigma " << kMrclamRangeSigma << " m, "
         << kMrclamBearingSigma
         << " rad, barcodes mapped through Barcodes.dat; clutter kept with truth not-a-landmark: " << robotSightings
         << " sightings of other robots, " << unknownBarcodes << " unknown barcodes; Vicon truth interpolated";
  header.source = source.str();
  return finishConversion(std::move(raw), std::move(sources), options, stats);
}

}  // namespace semslam
