#include "semslam/solve/ConstrainedOrdering.h"

#include <camd.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace semslam {

std::vector<int> constrainedOrdering(const std::vector<std::vector<int>>& neighbours, const std::vector<bool>& last) {
  const int n = static_cast<int>(neighbours.size());
  if (n <= 1) return std::vector<int>(n, 0);
  // Symmetric pattern, both triangles, sorted and without duplicates or diagonal (CAMD's valid input).
  std::vector<std::vector<int>> columns(n);
  for (int i = 0; i < n; ++i) {
    for (int j : neighbours[i]) {
      if (j == i) continue;
      columns[i].push_back(j);
      columns[j].push_back(i);
    }
  }
  std::vector<int> Ap(n + 1, 0);
  std::vector<int> Ai;
  for (int i = 0; i < n; ++i) {
    auto& column = columns[i];
    std::sort(column.begin(), column.end());
    column.erase(std::unique(column.begin(), column.end()), column.end());
    Ai.insert(Ai.end(), column.begin(), column.end());
    Ap[i + 1] = static_cast<int>(Ai.size());
  }
  if (Ai.empty()) Ai.push_back(0);  // CAMD reads Ai[0] even for an empty pattern
  std::vector<int> constraint(n);
  bool anyLast = false;
  bool anyFirst = false;
  for (int i = 0; i < n; ++i) {
    constraint[i] = last[i] ? 1 : 0;
    anyLast = anyLast || last[i];
    anyFirst = anyFirst || !last[i];
  }
  std::vector<int> permutation(n);
  double control[CAMD_CONTROL];
  camd_defaults(control);
  double info[CAMD_INFO];
  const int status = camd_order(n, Ap.data(), Ai.data(), permutation.data(), control, info,
                                (anyLast && anyFirst) ? constraint.data() : nullptr);
  if (status < CAMD_OK) throw std::runtime_error("CAMD ordering failed");
  return permutation;
}

}  // namespace semslam
