#include "semslam/study/HybridStudy.h"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

#include "semslam/core/ExactNumber.h"
#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/eval/PoseMixtureMoments.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/io/CsvField.h"
#include "semslam/io/ScenarioFile.h"
#include "semslam/run/RunMethod.h"
#include "semslam/sim/Aliased2dLayout.h"
#include "semslam/sim/Aliased2dSimulator.h"
#include "semslam/study/ParallelJobs.h"

namespace semslam {
namespace {

bool historyIsTrue(const AssociationHistory& associations, const MeasurementLog& log) {
  const std::vector<std::vector<int>> history = associations.steps();
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

/// The NEES of the moment-matched mixture of the components' poses (eval/PoseMixtureMoments.h); NaN when the
/// components spread over more than a half turn, where the mixture has no unique mean.
double mixtureNees(const std::vector<HypothesisComponent>& components, const SE2& truth) {
  std::vector<double> weights;
  std::vector<SE2> means;
  std::vector<Matrix3> covariances;
  for (const HypothesisComponent& component : components) {
    weights.push_back(component.weight);
    means.push_back(std::get<SE2>(component.pose));
    covariances.push_back(component.covariance);
  }
  try {
    const PoseGaussian2 mixture = momentMatchedPoseMixture(weights, means, covariances);
    return poseNees(mixture.mean, truth, mixture.covariance);
  } catch (const std::invalid_argument&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

HybridStudyRow runOne(const HybridStudyOptions& options, const HybridStudyRun& job) {
  Aliased2dScenario scenario = options.layouts[job.layout];
  scenario.alpha = options.alphas[job.alphaIndex];
  const MeasurementLog log = simulateAliased2dTrack(scenario, layoutTrackSeed(options.seed, job.layout), job.track,
                                                    options.steps, options.tracks);
  MethodOptions run;
  run.method = job.classifier ? Method::Hybrid : Method::HybridGeometric;
  run.hybrid = options.hybrid;
  run.hybrid.seed = layoutTrackSeed(options.seed, job.layout) * 0x9e3779b97f4a7c15ull +
                    (job.alphaIndex * 100003ull + static_cast<std::uint64_t>(job.track)) * 2 +
                    (job.classifier ? 1 : 0);
  run.runFolder = false;
  const MethodRun out = runMethod(log, run);

  HybridStudyRow row;
  row.layout = static_cast<int>(job.layout);
  row.alpha = scenario.alpha;
  row.model = job.classifier ? "classifier" : "geometric";
  row.track = job.track;
  const HybridMarginals& last = out.hybridFinal;
  const SE2& truth = std::get<SE2>(*log.steps.back().truePose);
  const HypothesisMetrics metrics = evaluateHypotheses(last.components, log.steps.back().truePose);
  row.entropy = metrics.entropy;
  row.detCov = metrics.detCovariance;
  row.errWmax = metrics.errorHeaviest;
  row.errWavg = metrics.errorWeightedAverage;
  row.ess = metrics.ess;
  row.components = static_cast<int>(last.components.size());
  // The heaviest component (the first of equal weights, as the run's trajectory, hybrid/HybridRun.h): its final
  // pose's NEES and whether its history is the true one come from the same component.
  const auto heaviest = std::max_element(
      last.components.begin(), last.components.end(),
      [](const HypothesisComponent& a, const HypothesisComponent& b) { return a.weight < b.weight; });
  row.finalNees = poseNees(std::get<SE2>(heaviest->pose), truth, heaviest->covariance);
  row.heaviestComponentCorrect = historyIsTrue(heaviest->associations, log);
  row.mixtureNees = mixtureNees(last.components, truth);
  const int step = std::min<int>(options.disambiguationStep, static_cast<int>(out.hybridReports.size()) - 1);
  row.assocWeightAtStep = out.result.heaviestAssociationWeights[step];
  row.disambiguatedAtStep = row.assocWeightAtStep > 0.9;
  row.heaviestHistoryCorrect = historyIsTrue(last.association.front().associations, log);
  double tv = 0.0;
  int tvSteps = 0;
  for (const HybridStepReport& report : out.hybridReports) {
    row.gateLostMass = std::max(row.gateLostMass, report.weights.gateLostMass);
    row.sampledCandidates += static_cast<long long>(report.weights.sampled);
    row.samplingSeconds += report.weights.samplingSeconds;
    if (report.weights.sampled > 1) {
      tv += report.weights.analyticTotalVariation;
      ++tvSteps;
    }
  }
  row.analyticTotalVariation = tvSteps > 0 ? tv / tvSteps : 0.0;
  row.seconds = out.result.timeSeconds;
  return row;
}

/// The finite NEES values of the rows selected by `keep`.
template <class Keep>
std::vector<double> finiteNees(const std::vector<const HybridStudyRow*>& rows, double HybridStudyRow::*member,
                               Keep keep) {
  std::vector<double> values;
  for (const HybridStudyRow* r : rows) {
    if (r->error.empty() && keep(*r) && std::isfinite(r->*member)) values.push_back(r->*member);
  }
  return values;
}

}  // namespace

std::vector<Aliased2dScenario> generatedHybridStudyLayouts(std::uint64_t firstSeed, int count) {
  if (count < 1) throw std::invalid_argument("hybrid study: needs at least one layout");
  std::vector<Aliased2dScenario> layouts;
  for (int i = 0; i < count; ++i) {
    layouts.push_back(generatedAliased2dScenario(firstSeed + static_cast<std::uint64_t>(i)));
  }
  return layouts;
}

std::uint64_t layoutTrackSeed(std::uint64_t seed, std::size_t layout) {
  // splitmix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014) of the pair.
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(layout) + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::vector<HybridStudyRun> hybridStudyRuns(const HybridStudyOptions& options) {
  if (options.layouts.empty() || options.tracks < 1 || options.steps < 1 || options.alphas.empty()) {
    throw std::invalid_argument("hybrid study: needs at least one layout, one track, one step and one alpha");
  }
  for (const Aliased2dScenario& layout : options.layouts) validateAliased2dScenario(layout);
  options.hybrid.validate();
  std::vector<HybridStudyRun> runs;
  for (std::size_t l = 0; l < options.layouts.size(); ++l) {
    for (std::size_t a = 0; a < options.alphas.size(); ++a) {
      for (int t = 0; t < options.tracks; ++t) {
        runs.push_back({l, a, t, true});
        if (a == 0) runs.push_back({l, a, t, false});  // the geometric run serves every alpha (header)
      }
    }
  }
  return runs;
}

std::vector<HybridStudyRow> hybridStudyTable(const HybridStudyOptions& options,
                                             const std::vector<HybridStudyRow>& executed) {
  const std::vector<HybridStudyRun> runs = hybridStudyRuns(options);
  if (executed.size() != runs.size()) {
    throw std::invalid_argument("hybrid study: " + std::to_string(executed.size()) + " rows for " +
                                std::to_string(runs.size()) + " runs");
  }
  // Index the rows by run: classifier[(layout, alpha, track)] and geometric[(layout, track)].
  std::map<std::tuple<std::size_t, std::size_t, int>, const HybridStudyRow*> classifier;
  std::map<std::pair<std::size_t, int>, const HybridStudyRow*> geometric;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const HybridStudyRun& run = runs[i];
    if (run.classifier) {
      classifier[{run.layout, run.alphaIndex, run.track}] = &executed[i];
    } else {
      geometric[{run.layout, run.track}] = &executed[i];
    }
  }
  std::vector<HybridStudyRow> table;
  table.reserve(2 * options.layouts.size() * options.alphas.size() * static_cast<std::size_t>(options.tracks));
  for (std::size_t l = 0; l < options.layouts.size(); ++l) {
    for (std::size_t a = 0; a < options.alphas.size(); ++a) {
      for (int t = 0; t < options.tracks; ++t) {
        table.push_back(*classifier.at({l, a, t}));
        table.push_back(*geometric.at({l, t}));
        table.back().alpha = options.alphas[a];
      }
    }
  }
  return table;
}

HybridStudyRow runHybridStudyRun(const HybridStudyOptions& options, const HybridStudyRun& run) {
  try {
    return runOne(options, run);
  } catch (const std::exception& error) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    HybridStudyRow row;
    row.layout = static_cast<int>(run.layout);
    row.alpha = options.alphas[run.alphaIndex];
    row.model = run.classifier ? "classifier" : "geometric";
    row.track = run.track;
    row.entropy = row.detCov = row.errWmax = row.errWavg = row.ess = row.finalNees = row.mixtureNees = nan;
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

void writeHybridStudy(const std::string& directory, const HybridStudyOptions& options,
                      const std::vector<HybridStudyRow>& executed, const StudyLayout& jobs) {
  const std::vector<HybridStudyRow> rows = hybridStudyTable(options, executed);
  std::filesystem::create_directories(directory);
  const std::filesystem::path dir(directory);
  writeFileAtomically((dir / "runs.csv").string(), [&](std::ostream& out) {
    out << "layout,alpha,model,track,entropy,det_cov,err_wmax,err_wavg,ess,components,final_nees,"
           "heaviest_component_correct,mixture_nees,assoc_weight_at_step,disambiguated_at_step,"
           "heaviest_history_correct,gate_lost_mass,analytic_total_variation,sampled_candidates\n";
    for (const HybridStudyRow& r : rows) {
      out << r.layout << ',' << seventeenDigitNumber(r.alpha) << ',' << r.model << ',' << r.track << ','
          << seventeenDigitNumber(r.entropy) << ',' << seventeenDigitNumber(r.detCov) << ','
          << seventeenDigitNumber(r.errWmax) << ',' << seventeenDigitNumber(r.errWavg) << ','
          << seventeenDigitNumber(r.ess) << ',' << r.components << ',' << seventeenDigitNumber(r.finalNees) << ','
          << (r.heaviestComponentCorrect ? 1 : 0) << ',' << seventeenDigitNumber(r.mixtureNees) << ','
          << seventeenDigitNumber(r.assocWeightAtStep) << ',' << (r.disambiguatedAtStep ? 1 : 0) << ','
          << (r.heaviestHistoryCorrect ? 1 : 0) << ',' << seventeenDigitNumber(r.gateLostMass) << ','
          << seventeenDigitNumber(r.analyticTotalVariation) << ',' << r.sampledCandidates << '\n';
    }
  });
  std::filesystem::create_directories(dir / "layouts");
  writeFileAtomically((dir / "layouts.csv").string(), [&](std::ostream& out) {
    out << "layout,name,objects\n";
    for (std::size_t l = 0; l < options.layouts.size(); ++l) {
      out << l << ',' << csvField(options.layouts[l].name) << ',' << options.layouts[l].objects.size() << '\n';
    }
  });
  for (std::size_t l = 0; l < options.layouts.size(); ++l) {
    writeAliased2dScenario((dir / "layouts" / ("layout_" + std::to_string(l) + ".json")).string(), options.layouts[l]);
  }
  writeFileAtomically((dir / "timings.csv").string(), [&](std::ostream& out) {
    out << "layout,alpha,model,track,rank,sampling_s,time_s,threads,ranks,wall_time_s\n";
    for (std::size_t i = 0; i < executed.size(); ++i) {
      const HybridStudyRow& r = executed[i];
      out << r.layout << ',' << seventeenDigitNumber(r.alpha) << ',' << r.model << ',' << r.track << ','
          << jobs.rankOf(i) << ',' << seventeenDigitNumber(r.samplingSeconds) << ','
          << seventeenDigitNumber(r.seconds) << ',' << jobs.threads << ',' << jobs.ranks << ','
          << seventeenDigitNumber(jobs.wallSeconds) << '\n';
    }
  });
  // Means over layouts and tracks, in the order of first appearance of (alpha, model); failed runs left out.
  std::vector<std::pair<double, std::string>> order;
  std::map<std::pair<double, std::string>, std::vector<const HybridStudyRow*>> groups;
  for (const HybridStudyRow& r : rows) {
    const auto key = std::make_pair(r.alpha, r.model);
    if (!groups.count(key)) order.push_back(key);
    if (r.error.empty()) groups[key].push_back(&r);
  }
  writeFileAtomically((dir / "summary.csv").string(), [&](std::ostream& out) {
    out << "alpha,model,entropy,det_cov,err_wmax,err_wavg,heaviest_correct\n";
    for (const auto& key : order) {
      const auto& group = groups[key];
      double e = 0, d = 0, m = 0, a = 0, c = 0;
      for (const HybridStudyRow* r : group) {
        e += r->entropy;
        d += r->detCov;
        m += r->errWmax;
        a += r->errWavg;
        c += r->heaviestHistoryCorrect ? 1.0 : 0.0;
      }
      const double n = static_cast<double>(group.size());
      out << seventeenDigitNumber(key.first) << ',' << key.second << ',' << seventeenDigitNumber(e / n) << ','
          << seventeenDigitNumber(d / n) << ',' << seventeenDigitNumber(m / n) << ',' << seventeenDigitNumber(a / n)
          << ',' << seventeenDigitNumber(c / n) << '\n';
    }
  });
  writeFileAtomically((dir / "nees.csv").string(), [&](std::ostream& out) {
    out << "alpha,model,subset,nees_mean,count,lower,upper\n";
    const auto all = [](const HybridStudyRow&) { return true; };
    const auto correct = [](const HybridStudyRow& r) { return r.heaviestComponentCorrect; };
    const auto wrong = [](const HybridStudyRow& r) { return !r.heaviestComponentCorrect; };
    for (const auto& key : order) {
      const auto& group = groups[key];
      const std::pair<const char*, std::vector<double>> subsets[] = {
          {"heaviest", finiteNees(group, &HybridStudyRow::finalNees, all)},
          {"heaviest_correct", finiteNees(group, &HybridStudyRow::finalNees, correct)},
          {"heaviest_wrong", finiteNees(group, &HybridStudyRow::finalNees, wrong)},
          {"mixture", finiteNees(group, &HybridStudyRow::mixtureNees, all)}};
      for (const auto& [subset, values] : subsets) {
        const NeesSummary s = summarizeNees(values, 3);
        out << seventeenDigitNumber(key.first) << ',' << key.second << ',' << subset << ','
            << seventeenDigitNumber(s.mean) << ',' << s.count << ',' << seventeenDigitNumber(s.lower) << ','
            << seventeenDigitNumber(s.upper) << '\n';
      }
    }
  });
}

}  // namespace semslam
