#include "semslam/eval/ErrorStatistics.h"

#include <algorithm>
#include <cmath>

#include "semslam/core/InputError.h"

namespace semslam {

ErrorStatistics computeErrorStatistics(const std::vector<double>& errors) {
  if (errors.empty()) throw InputError("error statistics: no errors to summarise (no poses or pairs)");
  const std::size_t n = errors.size();
  const double count = static_cast<double>(n);
  ErrorStatistics s;
  s.count = n;
  s.max = *std::max_element(errors.begin(), errors.end());
  s.min = *std::min_element(errors.begin(), errors.end());
  s.mean = pairwiseSum(errors.data(), n) / count;

  std::vector<double> squares(n);
  for (std::size_t i = 0; i < n; ++i) squares[i] = errors[i] * errors[i];
  s.sse = pairwiseSum(squares.data(), n);
  s.rmse = std::sqrt(s.sse / count);

  std::vector<double> deviations(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double d = errors[i] - s.mean;
    deviations[i] = d * d;
  }
  s.std = std::sqrt(pairwiseSum(deviations.data(), n) / count);

  std::vector<double> sorted(errors);
  const std::size_t mid = n / 2;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(mid), sorted.end());
  if (n % 2 == 1) {
    s.median = sorted[mid];
  } else {
    const double upper = sorted[mid];
    const double lower = *std::max_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(mid));
    s.median = (lower + upper) / 2.0;
  }
  return s;
}

}  // namespace semslam
