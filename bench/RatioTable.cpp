#include "RatioTable.h"

#include <algorithm>
#include <cmath>

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
  entry.milliseconds = toMilliseconds(run.GetAdjustedRealTime(), run.time_unit);
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

void RatioTable::print(std::FILE* out) const {
  const auto time = [&](const char* solver, const std::string& dataset) {
    char cell[64];
    const Entry* e = find(solver, dataset);
    if (e == nullptr) {
      std::snprintf(cell, sizeof cell, "-");
    } else if (!e->valid) {
      std::snprintf(cell, sizeof cell, "skipped");
    } else {
      std::snprintf(cell, sizeof cell, "%.1f (%.0f)", e->milliseconds, e->iterations);
    }
    return std::string(cell);
  };
  const auto ratio = [&](const char* numerator, const char* denominator, const std::string& dataset) {
    char cell[32];
    const Entry* n = find(numerator, dataset);
    const Entry* d = find(denominator, dataset);
    if (n && d && n->valid && d->valid && d->milliseconds > 0.0) {
      std::snprintf(cell, sizeof cell, "%.2f", n->milliseconds / d->milliseconds);
    } else {
      std::snprintf(cell, sizeof cell, "-");
    }
    return std::string(cell);
  };

  std::fprintf(out,
               "\nsemslam vs Ceres: median wall time over the repetitions in ms (linear solves in parentheses)\n"
               "  GN, LM: our Gauss-Newton and Levenberg-Marquardt (semslam::optimize)\n"
               "  C1, C2: Ceres LEVENBERG_MARQUARDT, SPARSE_NORMAL_CHOLESKY/SUITE_SPARSE, 1 and 2 threads, on our "
               "factors\n"
               "  AD:     Ceres on its own autodiff SE2 cost (2D pose graphs only), 1 thread\n"
               "  ratios are Ceres time / our time; chi2 over the file's edges, rel = |chi2_C1 - chi2_LM| / "
               "chi2_LM\n\n");
  std::fprintf(out, "%-15s %14s %14s %14s %14s %14s %7s %7s %7s %7s  %-16s %-16s %-9s %s\n", "dataset", "GN",
               "LM", "C1", "C2", "AD", "C1/GN", "C1/LM", "C2/LM", "AD/LM", "chi2 LM", "chi2 C1", "rel",
               "agree");
  for (const std::string& dataset : datasets_) {
    const Entry* lm = find(kOursLevenbergMarquardt, dataset);
    const Entry* c1 = find(kCeres1Thread, dataset);
    char chi2Ours[32] = "-", chi2Ceres[32] = "-", relative[32] = "-";
    const char* agree = "-";
    if (lm && lm->valid) std::snprintf(chi2Ours, sizeof chi2Ours, "%.10g", lm->chi2);
    if (c1 && c1->valid) std::snprintf(chi2Ceres, sizeof chi2Ceres, "%.10g", c1->chi2);
    if (lm && lm->valid && c1 && c1->valid) {
      const double rel = std::abs(c1->chi2 - lm->chi2) / std::max(std::abs(lm->chi2), 1e-300);
      std::snprintf(relative, sizeof relative, "%.1e", rel);
      agree = rel <= kChi2Agreement ? "yes" : "NO";
    }
    std::fprintf(out, "%-15s %14s %14s %14s %14s %14s %7s %7s %7s %7s  %-16s %-16s %-9s %s\n", dataset.c_str(),
                 time(kOursGaussNewton, dataset).c_str(), time(kOursLevenbergMarquardt, dataset).c_str(),
                 time(kCeres1Thread, dataset).c_str(), time(kCeres2Threads, dataset).c_str(),
                 time(kCeresAutodiff, dataset).c_str(), ratio(kCeres1Thread, kOursGaussNewton, dataset).c_str(),
                 ratio(kCeres1Thread, kOursLevenbergMarquardt, dataset).c_str(),
                 ratio(kCeres2Threads, kOursLevenbergMarquardt, dataset).c_str(),
                 ratio(kCeresAutodiff, kOursLevenbergMarquardt, dataset).c_str(), chi2Ours, chi2Ceres, relative,
                 agree);
  }
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
