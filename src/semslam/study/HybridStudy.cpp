#include "semslam/study/HybridStudy.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>

#include "semslam/core/ExactNumber.h"
#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/run/RunMethod.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/sim/Aliased2dSimulator.h"
#include "semslam/study/ParallelJobs.h"

namespace semslam {
namespace {

bool historyIsTrue(const AssociationHistory& history, const MeasurementLog& log) {
  if (history.size() != log.steps.size()) return false;
  for (std::size_t k = 0; k < history.size(); ++k) {
    const auto& detections = log.steps[k].detections;
    if (history[k].size() != detections.size()) return false;
    for (std::size_t i = 0; i < detections.size(); ++i) {
      if (!detections[i].truthId || *detections[i].truthId != history[k][i]) return false;
    }
  }
  return true;
}

HybridStudyRow runOne(const HybridStudyOptions& options, std::size_t alphaIndex, int track, bool classifier) {
  Aliased2dScenario scenario = options.scenario;
  scenario.alpha = options.alphas[alphaIndex];
  const MeasurementLog log = simulateAliased2dTrack(scenario, options.seed, track, options.steps, options.tracks);
  MethodOptions run;
  run.method = classifier ? Method::Hybrid : Method::HybridGeometric;
  run.hybrid = options.hybrid;
  run.hybrid.seed = options.seed * 0x9e3779b97f4a7c15ull +
                    (alphaIndex * 100003ull + static_cast<std::uint64_t>(track)) * 2 + (classifier ? 1 : 0);
  run.runFolder = false;
  const MethodRun out = runMethod(log, run);

  HybridStudyRow row;
  row.alpha = scenario.alpha;
  row.model = classifier ? "classifier" : "geometric";
  row.track = track;
  const HybridMarginals& last = out.hybridSteps.back().marginals;
  const HypothesisMetrics metrics = evaluateHypotheses(last.components, log.steps.back().truePose);
  row.entropy = metrics.entropy;
  row.detCov = metrics.detCovariance;
  row.errWmax = metrics.errorHeaviest;
  row.errWavg = metrics.errorWeightedAverage;
  row.ess = metrics.ess;
  row.components = static_cast<int>(last.components.size());
  row.finalNees = poseNees(std::get<SE2>(out.result.poses.back()), std::get<SE2>(*log.steps.back().truePose),
                           out.result.poseCovariances.back());
  const int step = std::min<int>(options.disambiguationStep, static_cast<int>(out.hybridSteps.size()) - 1);
  row.assocWeightAtStep = out.result.heaviestAssociationWeights[step];
  row.disambiguatedAtStep = row.assocWeightAtStep > 0.9;
  row.heaviestHistoryCorrect = historyIsTrue(last.association.front().associations, log);
  double tv = 0.0;
  int tvSteps = 0;
  for (const HybridStepRecord& s : out.hybridSteps) {
    row.gateLostMass = std::max(row.gateLostMass, s.report.weights.gateLostMass);
    row.sampledCandidates += static_cast<long long>(s.report.weights.sampled);
    row.samplingSeconds += s.report.weights.samplingSeconds;
    if (s.report.weights.sampled > 1) {
      tv += s.report.weights.analyticTotalVariation;
      ++tvSteps;
    }
  }
  row.analyticTotalVariation = tvSteps > 0 ? tv / tvSteps : 0.0;
  row.seconds = out.result.timeSeconds;
  return row;
}

}  // namespace

std::vector<HybridStudyRun> hybridStudyRuns(const HybridStudyOptions& options) {
  if (options.tracks < 1 || options.steps < 1 || options.alphas.empty()) {
    throw std::invalid_argument("hybrid study: needs at least one track, one step and one alpha");
  }
  validateAliased2dScenario(options.scenario);
  options.hybrid.validate();
  std::vector<HybridStudyRun> runs;
  for (std::size_t a = 0; a < options.alphas.size(); ++a) {
    for (int t = 0; t < options.tracks; ++t) {
      runs.push_back({a, t, true});
      runs.push_back({a, t, false});
    }
  }
  return runs;
}

HybridStudyRow runHybridStudyRun(const HybridStudyOptions& options, const HybridStudyRun& run) {
  try {
    return runOne(options, run.alphaIndex, run.track, run.classifier);
  } catch (const std::exception& error) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    HybridStudyRow row;
    row.alpha = options.alphas[run.alphaIndex];
    row.model = run.classifier ? "classifier" : "geometric";
    row.track = run.track;
    row.entropy = row.detCov = row.errWmax = row.errWavg = row.ess = row.finalNees = nan;
    row.assocWeightAtStep = row.gateLostMass = row.analyticTotalVariation = row.samplingSeconds = row.seconds = nan;
    row.error = error.what();
    return row;
  }
}

std::vector<HybridStudyRow> runHybridStudy(const HybridStudyOptions& options,
                                           const std::function<void(int, int)>& progress) {
  const std::vector<HybridStudyRun> runs = hybridStudyRuns(options);
  std::vector<HybridStudyRow> rows(runs.size());
  runParallelJobs(
      runs.size(), options.threads, [&](std::size_t i) { rows[i] = runHybridStudyRun(options, runs[i]); },
      progress);
  return rows;
}

int failedHybridRuns(const std::vector<HybridStudyRow>& rows) {
  return static_cast<int>(
      std::count_if(rows.begin(), rows.end(), [](const HybridStudyRow& row) { return !row.error.empty(); }));
}

void writeHybridStudy(const std::string& directory, const std::vector<HybridStudyRow>& rows,
                      const StudyLayout& layout) {
  std::filesystem::create_directories(directory);
  const std::filesystem::path dir(directory);
  writeFileAtomically((dir / "runs.csv").string(), [&](std::ostream& out) {
    out << "alpha,model,track,entropy,det_cov,err_wmax,err_wavg,ess,components,final_nees,assoc_weight_at_step,"
           "disambiguated_at_step,heaviest_history_correct,gate_lost_mass,analytic_total_variation,"
           "sampled_candidates\n";
    for (const HybridStudyRow& r : rows) {
      out << seventeenDigitNumber(r.alpha) << ',' << r.model << ',' << r.track << ',' << seventeenDigitNumber(r.entropy) << ','
          << seventeenDigitNumber(r.detCov) << ',' << seventeenDigitNumber(r.errWmax) << ',' << seventeenDigitNumber(r.errWavg) << ','
          << seventeenDigitNumber(r.ess) << ',' << r.components << ',' << seventeenDigitNumber(r.finalNees) << ','
          << seventeenDigitNumber(r.assocWeightAtStep) << ',' << (r.disambiguatedAtStep ? 1 : 0) << ','
          << (r.heaviestHistoryCorrect ? 1 : 0) << ',' << seventeenDigitNumber(r.gateLostMass) << ','
          << seventeenDigitNumber(r.analyticTotalVariation) << ',' << r.sampledCandidates << '\n';
    }
  });
  writeFileAtomically((dir / "timings.csv").string(), [&](std::ostream& out) {
    out << "alpha,model,track,rank,sampling_s,time_s,threads,ranks,wall_time_s\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const HybridStudyRow& r = rows[i];
      out << seventeenDigitNumber(r.alpha) << ',' << r.model << ',' << r.track << ',' << layout.rankOf(i) << ','
          << seventeenDigitNumber(r.samplingSeconds) << ',' << seventeenDigitNumber(r.seconds) << ','
          << layout.threads << ',' << layout.ranks << ',' << seventeenDigitNumber(layout.wallSeconds) << '\n';
    }
  });
  // Means over tracks, in the order of first appearance of (alpha, model).
  std::vector<std::pair<double, std::string>> order;
  std::map<std::pair<double, std::string>, std::vector<const HybridStudyRow*>> groups;
  for (const HybridStudyRow& r : rows) {
    const auto key = std::make_pair(r.alpha, r.model);
    if (!groups.count(key)) order.push_back(key);
    groups[key].push_back(&r);
  }
  writeFileAtomically((dir / "summary.csv").string(), [&](std::ostream& out) {
    out << "alpha,model,entropy,det_cov,err_wmax,err_wavg\n";
    for (const auto& key : order) {
      const auto& group = groups[key];
      double e = 0, d = 0, m = 0, a = 0;
      for (const HybridStudyRow* r : group) {
        e += r->entropy;
        d += r->detCov;
        m += r->errWmax;
        a += r->errWavg;
      }
      const double n = static_cast<double>(group.size());
      out << seventeenDigitNumber(key.first) << ',' << key.second << ',' << seventeenDigitNumber(e / n) << ',' << seventeenDigitNumber(d / n)
          << ',' << seventeenDigitNumber(m / n) << ',' << seventeenDigitNumber(a / n) << '\n';
    }
  });
  writeFileAtomically((dir / "nees.csv").string(), [&](std::ostream& out) {
    out << "alpha,model,nees_mean,count,lower,upper\n";
    for (const auto& key : order) {
      std::vector<double> values;
      for (const HybridStudyRow* r : groups[key]) values.push_back(r->finalNees);
      const NeesSummary s = summarizeNees(values, 3);
      out << seventeenDigitNumber(key.first) << ',' << key.second << ',' << seventeenDigitNumber(s.mean) << ',' << s.count << ','
          << seventeenDigitNumber(s.lower) << ',' << seventeenDigitNumber(s.upper) << '\n';
    }
  });
}

}  // namespace semslam
