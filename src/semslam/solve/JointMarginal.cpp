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

JointMarginal JointMarginal::restrictedTo(const std::vector<Key>& keys) const {
  std::vector<int> indices, dimensions;
  int total = 0;
  for (Key key : keys) {
    indices.push_back(indexOf(key));
    dimensions.push_back(dimensions_[indices.back()]);
    total += dimensions.back();
  }
  Matrix covariance(total, total);
  int row = 0;
  for (std::size_t a = 0; a < keys.size(); ++a) {
    int column = 0;
    for (std::size_t b = 0; b < keys.size(); ++b) {
      covariance.block(row, column, dimensions[a], dimensions[b]) =
          covariance_.block(offsets_[indices[a]], offsets_[indices[b]], dimensions[a], dimensions[b]);
      column += dimensions[b];
    }
    row += dimensions[a];
  }
  return JointMarginal(keys, std::move(dimensions), std::move(covariance));
}

}  // namespace semslam
