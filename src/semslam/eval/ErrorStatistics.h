#pragma once
// Summary statistics of an error vector e_1..e_n, exactly as evo's PE.get_statistic computes them with numpy
// (evo/core/metrics.py):
//   max    = max_i e_i                          np.max
//   min    = min_i e_i                          np.min
//   mean   = (Σ e_i) / n                        np.mean
//   median = middle value of the sorted e; for even n the mean of the two middle values      np.median
//   sse    = Σ e_i²                             np.sum(np.power(e, 2))
//   rmse   = sqrt(sse / n)                      math.sqrt(np.mean(np.power(e, 2)))
//   std    = sqrt(Σ (e_i − mean)² / n)          np.std: the POPULATION standard deviation (ddof = 0)
// Sums use numpy's pairwise summation (blocks of 8 accumulators, halving above 128 elements), in the same order as
// numpy, so the results agree with evo's to a few units in the last place rather than to the error of a naive sum.

#include <cstddef>
#include <vector>

#include "semslam/core/PairwiseSum.h"

namespace semslam {

struct ErrorStatistics {
  double max = 0.0;
  double mean = 0.0;
  double median = 0.0;
  double min = 0.0;
  double rmse = 0.0;
  double sse = 0.0;
  double std = 0.0;
  std::size_t count = 0;  ///< n, the number of errors (poses for APE, pairs for RPE)
};

/// The statistics of `errors`; throws InputError when it is empty (evo raises there too).
ErrorStatistics computeErrorStatistics(const std::vector<double>& errors);

}  // namespace semslam
