#include "RatioTable.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

namespace semslam::bench {

namespace {

double toMilliseconds(double value, benchmark::TimeUnit unit) {
  switch (unit) {
    case benchmark::kNanosecond: return value * 1e-6;
    case benchmark::kMicrosecond: return value * 1e-3;
    case benchmark::kMillisecond: return value;
    case benchmark::kSecond: return value * 1e3;
  }
  return value;
}

double counter(const benchmark::BenchmarkReporter::Run& run, const char* name) {
  const auto it = run.counters.find(name);
  return it == run.counters.end() ? std::nan("") : static_cast<double>(it->second.value);
}

}  // namespace

void RatioTable::record(const benchmark::BenchmarkReporter::Run& run) {
  const std::string& name = run.run_name.function_name;
  const auto slash = name.find('/');
  if (slash == std::string::npos) return;
  const std::string solver = name.substr(0, slash);
  const std::string dataset = name.substr(slash + 1);
  const bool median = run.run_type == benchmark::BenchmarkReporter::Run::RT_Aggregate;
  if (median && run.aggregate_name != "median") return;

  if (std::find(datasets_.begin(), datasets_.end(), dataset) == datasets_.end()) datasets_.push_back(dataset);
  Entry& entry = entries_[dataset][solver];
  if (run.error_occurred) {
    entry.error = run.error_message;
    entry.valid = false;
    return;
  }
  if (entry.fromMedian && !median) return;  // a median already summarises the repetitions
  entry.wallMs = toMilliseconds(run.GetAdjustedRealTime(), run.time_unit);
  entry.cpuMs = toMilliseconds(run.GetAdjustedCPUTime(), run.time_unit);
  entry.chi2 = counter(run, kChi2Counter);
  entry.iterations = counter(run, kIterationsCounter);
  entry.fromMedian = median;
  entry.valid = true;
}

const RatioTable::Entry* RatioTable::find(const std::string& solver, const std::string& dataset) const {
  const auto d = entries_.find(dataset);
  if (d == entries_.end()) return nullptr;
  const auto s = d->second.find(solver);
  return s == d->second.end() ? nullptr : &s->second;
}

namespace {

constexpr const char* kSolvers[] = {kOursGaussNewton, kOursLevenbergMarquardt, kCeres1Thread, kCeres2Threads,
                                    kCeresAutodiff};
constexpr const char* kColumns[] = {"GN", "LM", "C1", "C2", "AD"};

}  // namespace

void RatioTable::printTimes(std::FILE* out, bool wall) const {
  const auto time = [&](const Entry* e) { return wall ? e->wallMs : e->cpuMs; };
  std::fprintf(out, "%s\n",
               wall ? "Wall time, median over the repetitions, ms (linear solves in parentheses)"
                    : "Process CPU time (all threads), median over the repetitions, ms");
  std::fprintf(out, "%-15s", "dataset");
  for (const char* column : kColumns) std::fprintf(out, " %13s", column);
  std::fprintf(out, " %7s %7s %7s %7s\n", "C1/GN", "C1/LM", "C2/LM", "AD/LM");
  for (const std::string& dataset : datasets_) {
    std::fprintf(out, "%-15s", dataset.c_str());
    for (const char* solver : kSolvers) {
      char cell[64] = "-";
      if (const Entry* e = find(solver, dataset)) {
        if (!e->valid) {
          std::snprintf(cell, sizeof cell, "skipped");
        } else if (wall) {
          std::snprintf(cell, sizeof cell, "%.1f (%.0f)", time(e), e->iterations);
        } else {
          std::snprintf(cell, sizeof cell, "%.1f", time(e));
        }
      }
      std::fprintf(out, " %13s", cell);
    }
    for (const auto& [numerator, denominator] :
         {std::pair{kCeres1Thread, kOursGaussNewton}, std::pair{kCeres1Thread, kOursLevenbergMarquardt},
          std::pair{kCeres2Threads, kOursLevenbergMarquardt}, std::pair{kCeresAutodiff, kOursLevenbergMarquardt}}) {
      char cell[32] = "-";
      const Entry* n = find(numerator, dataset);
      const Entry* d = find(denominator, dataset);
      if (n && d && n->valid && d->valid && time(d) > 0.0) std::snprintf(cell, sizeof cell, "%.2f", time(n) / time(d));
      std::fprintf(out, " %7s", cell);
    }
    std::fprintf(out, "\n");
  }
  std::fprintf(out, "\n");
}

void RatioTable::printChi2(std::FILE* out) const {
  std::fprintf(out, "Final chi2 over the file's own edges; the others as relative difference to LM (agree: all <= %g)\n",
               kChi2Agreement);
  std::fprintf(out, "%-15s %-18s", "dataset", "LM");
  for (const char* column : kColumns) {
    if (std::string(column) != "LM") std::fprintf(out, " %9s", column);
  }
  std::fprintf(out, "  agree\n");
  for (const std::string& dataset : datasets_) {
    const Entry* lm = find(kOursLevenbergMarquardt, dataset);
    char reference[32] = "-";
    if (lm && lm->valid) std::snprintf(reference, sizeof reference, "%.10g", lm->chi2);
    std::fprintf(out, "%-15s %-18s", dataset.c_str(), reference);
    std::string verdict = lm && lm->valid ? "yes" : "-";
    for (std::size_t i = 0; i < std::size(kSolvers); ++i) {
      if (kSolvers[i] == kOursLevenbergMarquardt) continue;
      char cell[32] = "-";
      const Entry* e = find(kSolvers[i], dataset);
      if (e && e->valid && lm && lm->valid) {
        const double rel = std::abs(e->chi2 - lm->chi2) / std::max(std::abs(lm->chi2), 1e-300);
        std::snprintf(cell, sizeof cell, "%.1e", rel);
        if (!(rel <= kChi2Agreement)) verdict = verdict == "yes" ? std::string("NO: ") + kColumns[i] : verdict + "," + kColumns[i];
      }
      std::fprintf(out, " %9s", cell);
    }
    std::fprintf(out, "  %s\n", verdict.c_str());
  }
}

void RatioTable::print(std::FILE* out) const {
  std::fprintf(out,
               "\nsemslam vs Ceres on the same factors, from the file's initial values with the first pose anchored\n"
               "  GN, LM  our Gauss-Newton and Levenberg-Marquardt (semslam::optimize)\n"
               "  C1, C2  Ceres LEVENBERG_MARQUARDT, SPARSE_NORMAL_CHOLESKY with SUITE_SPARSE, 1 and 2 threads, on\n"
               "          our factors (bench/ceres/FactorCostFunction.h)\n"
               "  AD      Ceres on its own autodiff SE2 residuals (2D pose graphs only), 1 thread\n"
               "  ratios  Ceres time / our time (> 1: we are faster)\n\n");
  printTimes(out, true);
  printTimes(out, false);
  printChi2(out);
  // Skip messages, once each, so a missing file or a failed solve is explained under the table.
  for (const std::string& dataset : datasets_) {
    for (const auto& [solver, entry] : entries_.at(dataset)) {
      if (!entry.valid && !entry.error.empty()) {
        std::fprintf(out, "  %s/%s skipped: %s\n", solver.c_str(), dataset.c_str(), entry.error.c_str());
      }
    }
  }
  std::fflush(out);
}

void RatioTableReporter::ReportRuns(const std::vector<Run>& runs) {
  for (const Run& run : runs) table_.record(run);
  ConsoleReporter::ReportRuns(runs);
}

}  // namespace semslam::bench
