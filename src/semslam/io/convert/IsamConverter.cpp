#include "semslam/io/convert/IsamConverter.h"

#include <array>
#include <filesystem>
#include <set>
#include <sstream>
#include <string_view>

#include "semslam/core/InputError.h"
#include "semslam/core/InputExcerpt.h"
#include "semslam/io/LineReader.h"
#include "semslam/io/TriangularEntries.h"
#include "semslam/io/convert/ConversionCommon.h"

namespace semslam {

namespace {

constexpr std::array<std::string_view, 11> kOdometryFields = {"i",   "j",   "dx",  "dy",  "dtheta", "s11",
                                                              "s12", "s13", "s22", "s23", "s33"};
constexpr std::array<std::string_view, 7> kLandmarkFields = {"i", "l", "dx", "dy", "s11", "s12", "s22"};

// (RᵀR)⁻¹ for an upper-triangular square-root information R given row-major.
Matrix covarianceFromSqrtInformation(const LineReader& reader, const std::vector<double>& entries, int n) {
  const Matrix R = upperFromEntries(entries, n);
  for (int i = 0; i < n; ++i) {
    if (R(i, i) == 0.0) reader.fail("the square-root information matrix is singular (zero on its diagonal)");
  }
  const Matrix inverse = R.triangularView<Eigen::Upper>().solve(Matrix::Identity(n, n));
  const Matrix covariance = inverse * inverse.transpose();
  return 0.5 * (covariance + covariance.transpose());
}

int idField(const LineReader& reader, std::size_t i) {
  const std::uint64_t id = reader.id(i);
  if (id > static_cast<std::uint64_t>(1 << 30)) reader.fail(reader.describe(i) + " is too large for a log id");
  return static_cast<int>(id);
}

}  // namespace

MeasurementLog convertIsam(const std::string& path, const ConvertOptions& options, ConversionStats* stats) {
  validateConvertOptions(options, 2);
  MeasurementLog raw;
  LogSources sources;
  sources.dataset = path;
  LogHeader& header = raw.header;
  header.dimension = 2;
  header.sensor.kind = SensorKind::RelativePosition;
  header.sensor.bodyToSensor = SE2();

  LineReader reader(path);
  raw.steps.emplace_back();  // pose 0, which no line makes
  raw.steps.front().time = 0.0;
  sources.steps.emplace_back();
  sources.steps.front().step = SourceLine{path, 0, 0};
  while (reader.next()) {
    const std::string_view tag = reader.tag();
    if (tag == "EDGE2" || tag == "ODOMETRY") {
      reader.requireValueCount(kOdometryFields);
      const int i = idField(reader, 1), j = idField(reader, 2);
      const int newest = static_cast<int>(raw.steps.size()) - 1;
      if (i != newest || j != newest + 1) {
        reader.fail(std::string(tag) + " " + std::to_string(i) + " " + std::to_string(j) +
                    ": the converter reads odometry in time order, from the newest pose " + std::to_string(newest) +
                    " to the next, " + std::to_string(newest + 1));
      }
      const std::vector<double> z = reader.numbers(3, 3);
      TimeStep step;
      step.time = static_cast<double>(j);
      Odometry odometry;
      odometry.increment = SE2(z[0], z[1], z[2]);
      odometry.covariance = covarianceFromSqrtInformation(reader, reader.numbers(6, 6), 3);
      step.odometry = std::move(odometry);
      raw.steps.push_back(std::move(step));
      StepSources rows;
      rows.step = rows.odometry = SourceLine{path, reader.lineNumber(), 0};
      sources.steps.push_back(std::move(rows));
    } else if (tag == "LANDMARK") {
      reader.requireValueCount(kLandmarkFields);
      const int i = idField(reader, 1), l = idField(reader, 2);
      if (i >= static_cast<int>(raw.steps.size())) {
        reader.fail("LANDMARK names pose " + std::to_string(i) + ", which no earlier odometry record created");
      }
      const std::vector<double> z = reader.numbers(3, 2);
      Detection detection;
      detection.geometry = Vector2(z[0], z[1]);
      detection.covariance = covarianceFromSqrtInformation(reader, reader.numbers(5, 3), 2);
      detection.truthId = l;
      raw.steps[static_cast<std::size_t>(i)].detections.push_back(std::move(detection));
      sources.steps[static_cast<std::size_t>(i)].detections.push_back(SourceLine{path, reader.lineNumber(), 0});
    } else {
      reader.fail("unsupported record type " + inputExcerpt(tag) +
                  " (the iSAM landmark converter reads EDGE2, ODOMETRY and LANDMARK)");
    }
  }

  // Ground truth beside the file, where present.
  const std::filesystem::path file(path);
  const std::string stem = (file.parent_path() / file.stem()).string();
  const std::string posesPath = stem + "_gt_poses_DERIVED.txt";
  const std::string landmarksPath = stem + "_gt_landmarks_DERIVED.txt";
  bool havePoses = false, haveLandmarks = false;
  if (std::filesystem::exists(posesPath)) {
    havePoses = true;
    const std::vector<NumericRow> rows = readDatasetTable(posesPath, 4, "pose_id x y theta");
    // The first pose the other file lacks, at its line (no data rows at all is refused by readDatasetTable).
    if (rows.size() < raw.steps.size()) {
      throw InputError(path, sources.steps[rows.size()].step.line,
                       "pose " + std::to_string(rows.size()) + " has no row in " + posesPath + " (which has " +
                           std::to_string(rows.size()) + " poses, the iSAM file " +
                           std::to_string(raw.steps.size()) + ")");
    }
    if (rows.size() > raw.steps.size()) {
      throw InputError(posesPath, rows[raw.steps.size()].line,
                       "pose " + std::to_string(raw.steps.size()) + " is not in the iSAM file (which has " +
                           std::to_string(raw.steps.size()) + " poses, this file " + std::to_string(rows.size()) +
                           ")");
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
      integerField(posesPath, rows[k], 0, "pose id", static_cast<int>(k), static_cast<int>(k));
      raw.steps[k].truePose = SE2(rows[k].values[1], rows[k].values[2], rows[k].values[3]);
      sources.steps[k].truePose = SourceLine{posesPath, rows[k].line, 0};
    }
  }
  if (std::filesystem::exists(landmarksPath)) {
    haveLandmarks = true;
    const std::set<int> ids = readLandmarkTruthTable(landmarksPath, 2, 4, "landmark_id x y n_observations",
                                                     "landmark id", header.landmarkTruth, sources.landmarks);
    for (std::size_t k = 0; k < raw.steps.size(); ++k) {
      for (std::size_t j = 0; j < raw.steps[k].detections.size(); ++j) {
        const int id = *raw.steps[k].detections[j].truthId;
        if (ids.count(id) == 0) {
          throw InputError(path, sources.steps[k].detections[j].line,
                           "landmark " + std::to_string(id) + " is observed but not in " + landmarksPath);
        }
      }
    }
  }

  std::ostringstream source;
  source << "iSAM landmark file " << path << ", semslam convert isam: one step per pose (time = pose index), "
         << "EDGE2 odometry and LANDMARK relative positions with covariance (R^T R)^-1 of their square-root "
         << "information; true poses " << (havePoses ? "from " + posesPath : std::string("absent"))
         << ", landmark truth " << (haveLandmarks ? "from " + landmarksPath : std::string("absent"));
  header.source = source.str();
  return finishConversion(std::move(raw), std::move(sources), options, stats);
}

}  // namespace semslam
