#include "semslam/io/convert/StarryNightConverter.h"

#include <cmath>
#include <map>
#include <sstream>

#include "semslam/core/InputError.h"
#include "semslam/io/LineReader.h"
#include "semslam/io/convert/ConversionCommon.h"
#include "semslam/models/VelocityModel3.h"

namespace semslam {

namespace {

// Stamps are printed with 9 decimals; a row's time must name its step's stamp.
constexpr double kTimeTolerance = 1e-6;

struct Calibration {
  double fu = 0.0, fv = 0.0, cu = 0.0, cv = 0.0, baseline = 0.0;
  Matrix3 cameraFromVehicle = Matrix3::Identity();  // C_c_v
  Vector3 cameraInVehicle = Vector3::Zero();        // ρ_v_c_v
  Vector3 angularVelocityVariance = Vector3::Zero();
  Vector3 velocityVariance = Vector3::Zero();
  Vector4 pixelVariance = Vector4::Zero();  // ul, vl, ur, vr
};

Calibration readCalibration(const std::string& path) {
  struct Entry {
    std::vector<double> values;
    std::size_t line = 0;
  };
  std::map<std::string, Entry> entries;
  LineReader reader(path);
  while (reader.next()) {
    reader.requireAtLeast(1, "value");
    entries[std::string(reader.tag())] = Entry{reader.numbers(1, reader.valueCount()), reader.lineNumber()};
  }
  auto find = [&](const char* name) -> const Entry& {
    const auto it = entries.find(name);
    if (it == entries.end()) throw InputError(path, 0, std::string("missing entry '") + name + "'");
    return it->second;
  };
  auto get = [&](const char* name, std::size_t count) {
    const Entry& entry = find(name);
    if (entry.values.size() != count) {
      throw InputError(path, entry.line,
                       std::string("entry '") + name + "' needs " + std::to_string(count) + " values, has " +
                           std::to_string(entry.values.size()));
    }
    return entry.values;
  };
  auto positive = [&](const char* name, std::size_t count) {
    const std::vector<double> v = get(name, count);
    for (double x : v) {
      if (!(x > 0.0)) throw InputError(path, find(name).line, std::string("entry '") + name + "' must be > 0");
    }
    return v;
  };
  Calibration c;
  c.fu = positive("fu", 1)[0];
  c.fv = positive("fv", 1)[0];
  c.cu = get("cu", 1)[0];
  c.cv = get("cv", 1)[0];
  c.baseline = positive("b", 1)[0];
  const std::vector<double> C = get("C_c_v", 9);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) c.cameraFromVehicle(i, j) = C[static_cast<std::size_t>(3 * i + j)];
  }
  const std::vector<double> rho = get("rho_v_c_v", 3);
  c.cameraInVehicle = Vector3(rho[0], rho[1], rho[2]);
  const std::vector<double> w = positive("w_var", 3);
  const std::vector<double> v = positive("v_var", 3);
  const std::vector<double> y = positive("y_var", 4);
  c.angularVelocityVariance = Vector3(w[0], w[1], w[2]);
  c.velocityVariance = Vector3(v[0], v[1], v[2]);
  c.pixelVariance = Vector4(y[0], y[1], y[2], y[3]);
  return c;
}

// The triangulated point in the vehicle frame and its Jacobian with respect to (ul, vl, ur, vr).
struct Triangulation {
  Vector3 point;
  Eigen::Matrix<double, 3, 4> jacobian;
};

Triangulation triangulate(const Calibration& c, double ul, double vl, double ur, double vr) {
  const double d = ul - ur;
  const double z = c.fu * c.baseline / d;
  const double vm = 0.5 * (vl + vr);
  const double x = (ul - c.cu) * z / c.fu;
  const double y = (vm - c.cv) * z / c.fv;
  const double dzdul = -z / d, dzdur = z / d;
  Eigen::Matrix<double, 3, 4> J;                                                     // ∂p_c/∂(ul, vl, ur, vr)
  J << z / c.fu + (ul - c.cu) / c.fu * dzdul, 0.0, (ul - c.cu) / c.fu * dzdur, 0.0,  //
      (vm - c.cv) / c.fv * dzdul, 0.5 * z / c.fv, (vm - c.cv) / c.fv * dzdur, 0.5 * z / c.fv,  //
      dzdul, 0.0, dzdur, 0.0;
  Triangulation t;
  t.point = c.cameraFromVehicle.transpose() * Vector3(x, y, z) + c.cameraInVehicle;
  t.jacobian = c.cameraFromVehicle.transpose() * J;
  return t;
}

// ∂(range, bearing, elevation)/∂p.
Matrix3 rangeBearingElevationJacobian(const Vector3& p) {
  const double r2 = p.squaredNorm(), r = std::sqrt(r2);
  const double rho2 = p.x() * p.x() + p.y() * p.y(), rho = std::sqrt(rho2);
  Matrix3 J;
  J << p.x() / r, p.y() / r, p.z() / r,  //
      -p.y() / rho2, p.x() / rho2, 0.0,  //
      -p.x() * p.z() / (r2 * rho), -p.y() * p.z() / (r2 * rho), rho / r2;
  return J;
}

}  // namespace

MeasurementLog convertStarryNight(const std::string& folder, const ConvertOptions& options, ConversionStats* stats) {
  validateConvertOptions(options, 3);
  const std::string velocityPath = datasetFile(folder, "imu_velocities.txt");
  const std::string truthPath = datasetFile(folder, "groundtruth.txt");
  const std::string landmarkPath = datasetFile(folder, "landmarks_groundtruth.txt");
  const std::string rbePath = datasetFile(folder, "rbe_measurements_vehicle_frame.txt");
  const std::string stereoPath = datasetFile(folder, "stereo_measurements.txt");
  const Calibration calibration = readCalibration(datasetFile(folder, "calibration.txt"));

  MeasurementLog raw;
  LogSources sources;
  sources.dataset = folder;
  LogHeader& header = raw.header;
  header.dimension = 3;
  header.sensor.kind = SensorKind::RangeBearingElevation;
  header.sensor.bodyToSensor = SE3();

  const std::set<int> landmarkIds =
      readLandmarkTruthTable(landmarkPath, 3, 4, "id x y z", "landmark id", header.landmarkTruth, sources.landmarks);

  const std::vector<NumericRow> velocities = readDatasetTable(velocityPath, 7, "t wx wy wz vx vy vz");
  const VelocityModel3 model(calibration.velocityVariance, calibration.angularVelocityVariance);
  raw.steps.resize(velocities.size());
  sources.steps.resize(velocities.size());
  for (std::size_t k = 0; k < velocities.size(); ++k) {
    const std::vector<double>& u = velocities[k].values;
    raw.steps[k].time = u[0];
    sources.steps[k].step = SourceLine{velocityPath, velocities[k].line, 0};
    if (k == 0) continue;
    sources.steps[k].odometry = sources.steps[k].step;
    const double dt = u[0] - velocities[k - 1].values[0];
    if (!(dt > 0.0)) throw InputError(velocityPath, velocities[k].line, "time stamps must increase");
    raw.steps[k].odometry = model.integrate(Vector3(u[4], u[5], u[6]), Vector3(u[1], u[2], u[3]), dt);
  }

  const std::vector<NumericRow> truth = readDatasetTable(truthPath, 7, "t theta(3) r(3)");
  // One ground-truth row per velocity row: the first row the other file lacks, at its line.
  const std::string truthCounts = " (groundtruth.txt has " + std::to_string(truth.size()) + " rows, imu_velocities.txt " +
                                  std::to_string(velocities.size()) + "; the converter expects one row per velocity "
                                  "stamp)";
  if (truth.size() < velocities.size()) {
    throw InputError(velocityPath, velocities[truth.size()].line, "no ground-truth row for this stamp" + truthCounts);
  }
  if (truth.size() > velocities.size()) {
    throw InputError(truthPath, truth[velocities.size()].line, "no velocity row for this ground-truth row" + truthCounts);
  }
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const std::vector<double>& g = truth[k].values;
    if (std::abs(g[0] - raw.steps[k].time) > kTimeTolerance) {
      throw InputError(truthPath, truth[k].line,
                       "time stamp differs from imu_velocities.txt's row " + std::to_string(k + 1));
    }
    // C_vk_i = Exp(θ)ᵀ, so the vehicle's orientation in the inertial frame is C_vk_iᵀ = Exp(θ).
    raw.steps[k].truePose = SE3(SO3::Exp(Vector3(g[1], g[2], g[3])), Point3(g[4], g[5], g[6]));
    sources.steps[k].truePose = SourceLine{truthPath, truth[k].line, 0};
  }

  // Pixel covariance: the stated variances with the measured correlations.
  Matrix4 pixelCovariance;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      pixelCovariance(i, j) = kStereoPixelCorrelation[static_cast<std::size_t>(4 * i + j)] *
                              std::sqrt(calibration.pixelVariance(i) * calibration.pixelVariance(j));
    }
  }
  const std::vector<NumericRow> rbe = readDatasetTable(rbePath, 9, "k t landmark_id range bearing elevation px py pz");
  const std::vector<NumericRow> stereo = readDatasetTable(stereoPath, 7, "k t landmark_id ul vl ur vr");
  // Row-aligned: the first row the other file lacks, at its line.
  const std::string rowCounts = " (stereo_measurements.txt has " + std::to_string(stereo.size()) +
                                " rows, rbe_measurements_vehicle_frame.txt " + std::to_string(rbe.size()) +
                                "; the two must be row-aligned)";
  if (stereo.size() < rbe.size()) {
    throw InputError(rbePath, rbe[stereo.size()].line, "no stereo row for this row" + rowCounts);
  }
  if (stereo.size() > rbe.size()) {
    throw InputError(stereoPath, stereo[rbe.size()].line, "no range-bearing-elevation row for this row" + rowCounts);
  }
  const int lastStep = static_cast<int>(raw.steps.size()) - 1;
  for (std::size_t i = 0; i < rbe.size(); ++i) {
    const NumericRow& row = rbe[i];
    const std::vector<double>& s = stereo[i].values;
    const int k = integerField(rbePath, row, 0, "step index k", 0, lastStep);
    const int id = integerField(rbePath, row, 2, "landmark id", 0, 1 << 30);
    if (std::abs(row.values[1] - raw.steps[static_cast<std::size_t>(k)].time) > kTimeTolerance) {
      throw InputError(rbePath, row.line, "time stamp differs from that of step k = " + std::to_string(k));
    }
    if (landmarkIds.count(id) == 0) {
      throw InputError(rbePath, row.line, "landmark id " + std::to_string(id) + " is not in landmarks_groundtruth.txt");
    }
    if (s[0] != row.values[0] || s[2] != row.values[2] || std::abs(s[1] - row.values[1]) > kTimeTolerance) {
      throw InputError(stereoPath, stereo[i].line,
                       "does not match line " + std::to_string(row.line) +
                           " of rbe_measurements_vehicle_frame.txt (k, t, landmark id): the files must be row-aligned");
    }
    if (!(s[3] - s[5] > 0.0)) throw InputError(stereoPath, stereo[i].line, "disparity ul - ur must be > 0");
    const Triangulation t = triangulate(calibration, s[3], s[4], s[5], s[6]);
    const Vector3 filePoint(row.values[6], row.values[7], row.values[8]);
    if ((t.point - filePoint).norm() > 1e-6 * (1.0 + filePoint.norm())) {
      throw InputError(rbePath, row.line,
                       "the point (px, py, pz) differs from the triangulation of the stereo pixels of line " +
                           std::to_string(stereo[i].line) + " of stereo_measurements.txt");
    }
    const Eigen::Matrix<double, 3, 4> J = rangeBearingElevationJacobian(t.point) * t.jacobian;
    Matrix3 covariance = J * pixelCovariance * J.transpose();
    covariance = 0.5 * (covariance + covariance.transpose()).eval();
    Detection detection;
    detection.geometry = Vector3(row.values[3], row.values[4], row.values[5]);
    detection.covariance = covariance;
    detection.truthId = id;
    raw.steps[static_cast<std::size_t>(k)].detections.push_back(std::move(detection));
    // The range, bearing and elevation are the rbe row's; its covariance comes from the stereo row of the same line.
    sources.steps[static_cast<std::size_t>(k)].detections.push_back(SourceLine{rbePath, row.line, 0});
  }

  std::ostringstream source;
  source.precision(12);
  source << "UTIAS Starry Night (" << folder << "), semslam convert utias-starry-night: steps at the velocity stamps, "
         << "SE3 odometry Exp(dt (v_k, w_k)) with v_var, w_var of calibration.txt, range-bearing-elevation of the "
         << "triangulated point in the vehicle frame with covariance propagated from the stereo pixel noise (y_var "
         << "with measured correlations), Vicon truth";
  header.source = source.str();
  return finishConversion(std::move(raw), std::move(sources), options, stats);
}

}  // namespace semslam
