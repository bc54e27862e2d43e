#include "semslam/solve/JointMarginal.h"

#include <algorithm>
#include <stdexcept>

namespace semslam {

JointMarginal::JointMarginal(std::vector<Key> keys, std::vector<int> dimensions, Matrix covariance)
    : keys_(std::move(keys)), dimensions_(std::move(dimensions)), covariance_(std::move(covariance)) {
  int offset = 0;
  for (int d : dimensions_) {
    offsets_.push_back(offset);
    offset += d;
  }
  if (keys_.size() != dimensions_.size() || offset != covariance_.rows() || offset != covariance_.cols()) {
    throw std::invalid_argument("JointMarginal: keys, dimensions and covariance disagree");
  }
}

int JointMarginal::indexOf(Key key) const {
  const auto it = std::find(keys_.begin(), keys_.end(), key);
  if (it == keys_.end()) throw std::out_of_range("variable " + keyToString(key) + " is not in this joint marginal");
  return static_cast<int>(it - keys_.begin());
}

Matrix JointMarginal::block(Key row, Key column) const {
  const int i = indexOf(row);
  const int j = indexOf(column);
  return covariance_.block(offsets_[i], offsets_[j], dimensions_[i], dimensions_[j]);
}

}  // namespace semslam
