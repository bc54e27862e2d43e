#include "semslam/solve/ConstrainedOrdering.h"

#include <camd.h>

#include <stdexcept>

namespace semslam {

std::vector<int> constrainedOrdering(const std::vector<std::vector<int>>& neighbours, const std::vector<bool>& last) {
  const int n = static_cast<int>(neighbours.size());
  if (n <= 1) return std::vector<int>(n, 0);
  // Symmetric pattern, both triangles, without duplicates or diagonal, built by counting; columns are left
  // unsorted (CAMD sorts them itself, in linear time, when it finds them so).
  std::vector<int> Ap(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    for (int j : neighbours[i]) {
      if (j == i) continue;
      ++Ap[i + 1];
      ++Ap[j + 1];
    }
  }
  for (int i = 0; i < n; ++i) Ap[i + 1] += Ap[i];
  std::vector<int> Ai(Ap[n]);
  std::vector<int> fill(Ap.begin(), Ap.end() - 1);
  for (int i = 0; i < n; ++i) {
    for (int j : neighbours[i]) {
      if (j == i) continue;
      Ai[fill[i]++] = j;
      Ai[fill[j]++] = i;
    }
  }
  // Remove duplicates column by column, compacting in place.
  std::vector<int> marker(n, -1);
  int write = 0;
  for (int i = 0; i < n; ++i) {
    const int begin = Ap[i];
    const int end = Ap[i + 1];
    Ap[i] = write;
    for (int p = begin; p < end; ++p) {
      const int j = Ai[p];
      if (marker[j] != i) {
        marker[j] = i;
        Ai[write++] = j;
      }
    }
  }
  Ap[n] = write;
  Ai.resize(write);
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
