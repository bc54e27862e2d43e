#pragma once
// RatioTable: collects the median of every benchmark as the console reporter prints it, and at the end prints
// our Gauss-Newton, our Levenberg-Marquardt and Ceres times per dataset with the ratios Ceres/ours, by wall time
// and by process CPU time (all threads: the wall time of a loaded machine says little), then the final chi2 of
// every solver and whether they agree.
//
// Benchmarks are named "<solver>/<dataset>" with <solver> one of the k* names below.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace semslam::bench {

inline constexpr const char* kOursGaussNewton = "semslam_GN";
inline constexpr const char* kOursLevenbergMarquardt = "semslam_LM";
inline constexpr const char* kCeres1Thread = "ceres_LM_1t";
inline constexpr const char* kCeres2Threads = "ceres_LM_2t";
inline constexpr const char* kCeresAutodiff = "ceres_autodiff_LM_1t";

// Counter names every solver benchmark reports.
inline constexpr const char* kChi2Counter = "chi2";             // final chi2 over the file's own edges
inline constexpr const char* kIterationsCounter = "linsolves";  // linear solves (accepted + rejected steps)

/// Relative chi2 difference above which the table flags a disagreement.
inline constexpr double kChi2Agreement = 1e-6;

class RatioTable {
 public:
  /// Records one reported run: the median aggregate, or a plain run when there are no aggregates.
  void record(const benchmark::BenchmarkReporter::Run& run);
  /// Prints the table (datasets in first-seen order).
  void print(std::FILE* out) const;

 private:
  struct Entry {
    double wallMs = 0.0, cpuMs = 0.0;  ///< the run's time per iteration
    double chi2 = 0.0, iterations = 0.0;  ///< the run's counters
    bool fromMedian = false, valid = false;
    std::string error;
  };
  const Entry* find(const std::string& solver, const std::string& dataset) const;
  void printTimes(std::FILE* out, bool wall) const;
  void printChi2(std::FILE* out) const;

  std::vector<std::string> datasets_;
  std::map<std::string, std::map<std::string, Entry>> entries_;  // dataset -> solver -> entry
};

/// The console reporter, also feeding a RatioTable.
class RatioTableReporter : public benchmark::ConsoleReporter {
 public:
  explicit RatioTableReporter(RatioTable& table) : table_(table) {}
  void ReportRuns(const std::vector<Run>& runs) override;

 private:
  RatioTable& table_;
};

}  // namespace semslam::bench
