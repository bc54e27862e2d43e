#pragma once
// numpy's pairwise summation (numpy/core/src/umath/loops_utils.h.src, pairwise_sum): eight accumulators over
// blocks of at most 128 values, halving above that (halves rounded down to a multiple of 8). The same blocking gives
// the same rounding, so sums agree with numpy's (and evo's statistics) to the last bits rather than to the error of
// a naive left-to-right sum, whose error grows as O(n ε) against O(log n ε) here.

#include <cstddef>

namespace semslam {

/// numpy's pairwise sum of `values` (np.sum / np.add.reduce on a contiguous float64 array).
double pairwiseSum(const double* values, std::size_t n);

}  // namespace semslam
