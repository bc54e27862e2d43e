#pragma once
// JointMarginal: the joint Gaussian marginal covariance of a set of variables, in the order they were asked for,
// each block in the variable's own tangent (right perturbation, translation first).

#include <vector>

#include "semslam/geometry/Matrix.h"
#include "semslam/graph/Key.h"

namespace semslam {

class JointMarginal {
 public:
  JointMarginal() = default;
  JointMarginal(std::vector<Key> keys, std::vector<int> dimensions, Matrix covariance);

  const std::vector<Key>& keys() const { return keys_; }
  /// The full joint covariance, blocks in keys() order.
  const Matrix& covariance() const { return covariance_; }
  /// The block Cov(δ_row, δ_column); throws std::out_of_range if a key was not asked for.
  Matrix block(Key row, Key column) const;
  /// The marginal covariance of one variable.
  Matrix at(Key key) const { return block(key, key); }
  /// The joint marginal of a subset of the keys, in the order given (a marginal of a Gaussian is its sub-block);
  /// throws std::out_of_range for a key not asked for.
  JointMarginal restrictedTo(const std::vector<Key>& keys) const;

 private:
  int indexOf(Key key) const;

  std::vector<Key> keys_;
  std::vector<int> dimensions_;
  std::vector<int> offsets_;
  Matrix covariance_;
};

}  // namespace semslam
