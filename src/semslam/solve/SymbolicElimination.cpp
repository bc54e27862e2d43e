#include "semslam/solve/SymbolicElimination.h"

#include <algorithm>

namespace semslam {

namespace {

/// `lists` resized to `count` empty lists, keeping the storage of those that existed.
void reuse(std::vector<std::vector<int>>& lists, int count) {
  lists.resize(count);
  for (auto& list : lists) list.clear();
}

}  // namespace

void SymbolicElimination::eliminate(const std::vector<std::vector<int>>& later, int relaxedFrontals,
                                    double relaxedZeros) {
  const int n = static_cast<int>(later.size());
  reuse(columns_, n);
  reuse(treeChildren_, n);
  treeParent_.assign(n, -1);
  marker_.assign(n, -1);
  // Columns and elimination tree, in elimination order.
  for (int k = 0; k < n; ++k) {
    std::vector<int>& column = columns_[k];
    marker_[k] = k;
    const auto add = [&](int j) {
      if (marker_[j] != k) {
        marker_[j] = k;
        column.push_back(j);
      }
    };
    for (int j : later[k]) add(j);
    for (int child : treeChildren_[k]) {
      for (int j : columns_[child]) add(j);
    }
    std::sort(column.begin(), column.end());
    if (!column.empty()) {
      treeParent_[k] = column.front();
      treeChildren_[column.front()].push_back(k);
    }
  }
  // Supernodes, from the root down.
  cliqueOf_.assign(n, -1);
  head_.clear();
  cliqueSize_.clear();
  reuse(frontals_, n);
  for (int k = n - 1; k >= 0; --k) {
    const int p = treeParent_[k];
    bool join = false;
    if (p >= 0) {
      const int c = cliqueOf_[p];
      const int zeros = cliqueSize_[c] - static_cast<int>(columns_[k].size());
      join = (head_[c] == p && zeros == 0) ||
             (static_cast<int>(frontals_[c].size()) < relaxedFrontals && zeros <= relaxedZeros * cliqueSize_[c]);
    }
    if (join) {
      const int c = cliqueOf_[p];
      cliqueOf_[k] = c;
      head_[c] = k;
      ++cliqueSize_[c];
      frontals_[c].push_back(k);
    } else {
      cliqueOf_[k] = static_cast<int>(head_.size());
      frontals_[head_.size()].push_back(k);
      head_.push_back(k);
      cliqueSize_.push_back(1 + static_cast<int>(columns_[k].size()));
    }
  }
  cliqueCount_ = static_cast<int>(head_.size());
  frontals_.resize(cliqueCount_);
  reuse(separators_, cliqueCount_);
  parents_.assign(cliqueCount_, -1);
  for (int c = 0; c < cliqueCount_; ++c) {
    std::vector<int>& frontals = frontals_[c];
    std::reverse(frontals.begin(), frontals.end());  // built from the root down
    std::vector<int>& separator = separators_[c];
    const int stamp = -2 - c;  // distinct from the column pass's markers
    for (int f : frontals) {
      for (int j : columns_[f]) {
        if (cliqueOf_[j] != c && marker_[j] != stamp) {
          marker_[j] = stamp;
          separator.push_back(j);
        }
      }
    }
    std::sort(separator.begin(), separator.end());
    if (!separator.empty()) parents_[c] = cliqueOf_[separator.front()];
  }
}

}  // namespace semslam
