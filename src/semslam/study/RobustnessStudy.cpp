#include "semslam/study/RobustnessStudy.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "semslam/run/RunMethod.h"
#include "semslam/study/ParallelJobs.h"

namespace semslam {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string number(double value) {
  if (!std::isfinite(value)) return "";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string count(const std::optional<long long>& value) { return value ? std::to_string(*value) : ""; }

void checkLevels(const std::vector<double>& levels, const std::string& name, bool rate) {
  if (levels.empty()) throw std::invalid_argument(name + ": at least one level is needed");
  for (double level : levels) {
    if (!std::isfinite(level) || level < 0.0) {
      throw std::invalid_argument(name + ": " + number(level) + " is not a finite value >= 0");
    }
    if (rate && level >= 1.0) throw std::invalid_argument(name + ": " + number(level) + " is not in [0, 1)");
  }
}

bool isMaxMixture(const std::string& method) {
  return method == strategyName(AssociationStrategy::MaxMixture) ||
         method == strategyName(AssociationStrategy::MaxMixtureNullHypothesis);
}

}  // namespace

std::string robustnessAxisName(RobustnessAxis axis) {
  return axis == RobustnessAxis::OdometryNoise ? "odom_noise" : "misclassification";
}

void validateRobustnessOptions(const RobustnessStudyOptions& options) {
  if (options.methods.empty()) throw std::invalid_argument("methods: at least one method is needed");
  checkLevels(options.noiseScales, "odometry noise scales", false);
  checkLevels(options.misclassificationRates, "misclassification rates", true);
  checkLevels({options.noiseSweepMisclassification}, "noise sweep misclassification", true);
  checkLevels({options.misclassificationSweepNoiseScale}, "misclassification sweep noise scale", false);
  if (options.seeds < 1) throw std::invalid_argument("seeds: must be >= 1");
  if (options.threads < 1) throw std::invalid_argument("threads: must be >= 1");
  if (options.maxSteps < 0) throw std::invalid_argument("max steps: must be >= 0");
  if (!(options.modelMisclassificationFloor >= 0.0 && options.modelMisclassificationFloor < 1.0)) {
    throw std::invalid_argument("model misclassification floor: must be in [0, 1)");
  }
  if (!(options.stuckRatio > 0.0) || !(options.stuckMargin >= 0.0)) {
    throw std::invalid_argument("stuck: ratio must be > 0 and margin >= 0");
  }
}

std::vector<RobustnessCell> robustnessCells(const RobustnessStudyOptions& options) {
  std::vector<RobustnessCell> cells;
  auto add = [&](RobustnessAxis axis, const std::vector<double>& levels) {
    for (double level : levels) {
      for (int seed = 0; seed < options.seeds; ++seed) {
        RobustnessCell cell;
        cell.axis = axis;
        cell.level = level;
        cell.seed = seed;
        cell.perturbation.baseline = options.baseline;
        cell.perturbation.maxSteps = options.maxSteps;
        cell.perturbation.modelMisclassificationFloor = options.modelMisclassificationFloor;
        cell.perturbation.odometryNoiseScale =
            axis == RobustnessAxis::OdometryNoise ? level : options.misclassificationSweepNoiseScale;
        cell.perturbation.misclassification =
            axis == RobustnessAxis::Misclassification ? level : options.noiseSweepMisclassification;
        // Common random numbers: the perturbation's draws depend on the seed only, the level scales them.
        cell.perturbationSeed = options.baseSeed + static_cast<std::uint64_t>(seed);
        cells.push_back(cell);
      }
    }
  };
  add(RobustnessAxis::OdometryNoise, options.noiseScales);
  add(RobustnessAxis::Misclassification, options.misclassificationRates);
  return cells;
}

std::vector<RobustnessRow> runRobustnessCell(const MeasurementLog& log, const RobustnessStudyOptions& options,
                                             const RobustnessCell& cell, const std::function<void()>& runFinished) {
  const MeasurementLog perturbed = perturbLog(log, cell.perturbation, cell.perturbationSeed);
  std::vector<RobustnessRow> rows;
  for (AssociationStrategy strategy : options.methods) {
    RobustnessRow row;
    row.axis = cell.axis;
    row.level = cell.level;
    row.seed = cell.seed;
    row.method = strategyName(strategy);
    MethodOptions runOptions;
    runOptions.method = methodFor(strategy);
    runOptions.slam = options.slam;
    runOptions.poseCovariances = false;
    runOptions.runFolder = false;
    try {
      const MethodRun run = runMethod(perturbed, runOptions);
      const RunMetrics& m = run.evaluation.metrics;
      row.ateRmse = m.ateRmse;
      row.rotRmse = m.rotRmse;
      row.daAccuracy = m.daAccuracy;
      row.daAccuracyReal = m.daAccuracyReal;
      row.landmarksEstimated = m.landmarksEstimated;
      row.landmarksTrue = m.landmarksTrue;
      row.timeSeconds = run.result.timeSeconds;
    } catch (const std::exception& error) {
      row.ateRmse = row.rotRmse = row.daAccuracy = row.daAccuracyReal = row.timeSeconds = kNaN;
      row.error = error.what();
    }
    rows.push_back(std::move(row));
    if (runFinished) runFinished();
  }
  // Stuck: mm / mm-nh against known on this very cell.
  const RobustnessRow* known = nullptr;
  for (const RobustnessRow& row : rows) {
    if (row.method == strategyName(AssociationStrategy::Known)) known = &row;
  }
  for (RobustnessRow& row : rows) {
    if (!isMaxMixture(row.method) || known == nullptr || !std::isfinite(known->ateRmse) ||
        !std::isfinite(row.ateRmse)) {
      continue;
    }
    row.stuck = row.ateRmse > options.stuckRatio * known->ateRmse &&
                row.ateRmse > known->ateRmse + options.stuckMargin;
  }
  return rows;
}

RobustnessStudy runRobustnessStudy(const MeasurementLog& log, const RobustnessStudyOptions& options) {
  validateRobustnessOptions(options);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<RobustnessCell> cells = robustnessCells(options);
  const int totalRuns = static_cast<int>(cells.size() * options.methods.size());
  std::vector<std::vector<RobustnessRow>> results(cells.size());
  std::mutex progressMutex;  // progress counts runs, several per cell (job)
  int finished = 0;
  const auto runFinished = [&] {
    if (!options.progress) return;
    std::lock_guard<std::mutex> lock(progressMutex);
    options.progress(++finished, totalRuns);
  };

  // A log that cannot be perturbed fails the same way in every cell: the first such error stops the study.
  runParallelJobs(cells.size(), options.threads,
                  [&](std::size_t index) { results[index] = runRobustnessCell(log, options, cells[index], runFinished); });

  RobustnessStudy study;
  for (std::vector<RobustnessRow>& rows : results) {
    for (RobustnessRow& row : rows) study.rows.push_back(std::move(row));
  }
  study.layout.threads = options.threads;
  study.layout.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return study;
}

std::string robustnessCsv(const std::vector<RobustnessRow>& rows) {
  std::ostringstream out;
  out << "axis,level,seed,method,ate_rmse,rot_rmse,da_accuracy,da_accuracy_real,landmarks_estimated,landmarks_true,"
         "stuck\n";
  for (const RobustnessRow& row : rows) {
    out << robustnessAxisName(row.axis) << "," << number(row.level) << "," << row.seed << "," << row.method << ","
        << number(row.ateRmse) << "," << number(row.rotRmse) << "," << number(row.daAccuracy) << ","
        << number(row.daAccuracyReal) << ","
        << count(row.landmarksEstimated) << "," << count(row.landmarksTrue) << ","
        << (row.stuck ? (*row.stuck ? "1" : "0") : "") << "\n";
  }
  return out.str();
}

std::string robustnessTimingsCsv(const std::vector<RobustnessRow>& rows, const StudyLayout& layout,
                                 std::size_t methodsPerCell) {
  std::ostringstream out;
  out << "axis,level,seed,method,rank,time_s,threads,ranks,wall_time_s\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RobustnessRow& row = rows[i];
    out << robustnessAxisName(row.axis) << "," << number(row.level) << "," << row.seed << "," << row.method << ","
        << layout.rankOf(i / std::max<std::size_t>(methodsPerCell, 1)) << "," << number(row.timeSeconds) << ","
        << layout.threads << "," << layout.ranks << "," << number(layout.wallSeconds) << "\n";
  }
  return out.str();
}

double studentT975(int dof) {
  static constexpr double kTable[] = {  // scipy.stats.t.ppf(0.975, 1..30)
      12.706204736432095, 4.302652729911275, 3.182446305284263, 2.7764451051977987,
      2.5705818366147395, 2.4469118487916806, 2.3646242510102993, 2.3060041350333704,
      2.2621571627409915, 2.2281388519649385, 2.200985160082949, 2.1788128296634177,
      2.1603686564610127, 2.1447866879169273, 2.131449545559323, 2.1199052992210112,
      2.1098155778331806, 2.10092204024096, 2.093024054408263, 2.0859634472658364,
      2.079613844727662, 2.0738730679040147, 2.0686576104190406, 2.0638985616280205,
      2.059538552753294, 2.055529438642871, 2.0518305164802833, 2.048407141795244,
      2.045229642132703, 2.0422724563012373};
  if (dof < 1) return kNaN;
  if (dof <= 30) return kTable[dof - 1];
  const double z = 1.959963984540054, n = dof;  // Cornish–Fisher expansion in 1/ν
  return z + (z * z * z + z) / (4 * n) + (5 * std::pow(z, 5) + 16 * z * z * z + 3 * z) / (96 * n * n) +
         (3 * std::pow(z, 7) + 19 * std::pow(z, 5) + 17 * z * z * z - 15 * z) / (384 * n * n * n);
}

MeanInterval meanInterval(const std::vector<double>& values) {
  MeanInterval interval;
  double sum = 0.0;
  for (double v : values) {
    if (std::isfinite(v)) {
      sum += v;
      ++interval.n;
    }
  }
  if (interval.n == 0) {
    interval.mean = interval.low = interval.high = kNaN;
    return interval;
  }
  interval.mean = sum / interval.n;
  if (interval.n < 2) {
    interval.low = interval.high = kNaN;
    return interval;
  }
  double squares = 0.0;
  for (double v : values) {
    if (std::isfinite(v)) squares += (v - interval.mean) * (v - interval.mean);
  }
  const double halfWidth = studentT975(interval.n - 1) * std::sqrt(squares / (interval.n - 1) / interval.n);
  interval.low = interval.mean - halfWidth;
  interval.high = interval.mean + halfWidth;
  return interval;
}

std::string robustnessSummaryCsv(const std::vector<RobustnessRow>& rows) {
  struct Group {
    std::vector<double> ate, rot, da, daReal, landmarks;
    int stuck = 0, stuckDefined = 0, failed = 0;
  };
  using Key = std::tuple<int, double, std::string>;
  std::vector<Key> order;
  std::map<Key, Group> groups;
  for (const RobustnessRow& row : rows) {
    const Key key{static_cast<int>(row.axis), row.level, row.method};
    auto [it, inserted] = groups.try_emplace(key);
    if (inserted) order.push_back(key);
    Group& g = it->second;
    g.ate.push_back(row.ateRmse);
    g.rot.push_back(row.rotRmse);
    g.da.push_back(row.daAccuracy);
    g.daReal.push_back(row.daAccuracyReal);
    g.landmarks.push_back(row.landmarksEstimated ? static_cast<double>(*row.landmarksEstimated) : kNaN);
    if (row.stuck) {
      ++g.stuckDefined;
      g.stuck += *row.stuck ? 1 : 0;
    }
    g.failed += row.error.empty() ? 0 : 1;
  }
  std::ostringstream out;
  out << "axis,level,method,n,ate_mean,ate_ci_low,ate_ci_high,rot_mean,rot_ci_low,rot_ci_high,da_mean,da_ci_low,"
         "da_ci_high,da_real_mean,da_real_ci_low,da_real_ci_high,landmarks_mean,stuck_fraction,failed\n";
  for (const Key& key : order) {
    const Group& g = groups.at(key);
    const MeanInterval ate = meanInterval(g.ate), rot = meanInterval(g.rot), da = meanInterval(g.da),
                       daReal = meanInterval(g.daReal);
    out << robustnessAxisName(static_cast<RobustnessAxis>(std::get<0>(key))) << "," << number(std::get<1>(key))
        << "," << std::get<2>(key) << "," << ate.n << "," << number(ate.mean) << "," << number(ate.low) << ","
        << number(ate.high) << "," << number(rot.mean) << "," << number(rot.low) << "," << number(rot.high) << ","
        << number(da.mean) << "," << number(da.low) << "," << number(da.high) << "," << number(daReal.mean) << ","
        << number(daReal.low) << "," << number(daReal.high) << "," << number(meanInterval(g.landmarks).mean) << ","
        << (g.stuckDefined > 0 ? number(static_cast<double>(g.stuck) / g.stuckDefined) : "") << "," << g.failed
        << "\n";
  }
  return out.str();
}

}  // namespace semslam
