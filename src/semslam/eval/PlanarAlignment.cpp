#include "semslam/eval/PlanarAlignment.h"

#include <cmath>

#include "semslam/core/InputError.h"

namespace semslam {

SimilarityTransform planarRigidAlignment(const Eigen::Matrix2Xd& x, const Eigen::Matrix2Xd& y) {
  if (x.cols() != y.cols()) throw InputError("SE(2) alignment: the point sets differ in size");
  if (x.cols() == 0) throw InputError("SE(2) alignment: no points");

  const Vector2 meanX = x.rowwise().mean();
  const Vector2 meanY = y.rowwise().mean();
  const Eigen::Matrix2Xd cx = x.colwise() - meanX;
  const Eigen::Matrix2Xd cy = y.colwise() - meanY;
  double a = 0.0, b = 0.0;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    a += cx(0, i) * cy(0, i) + cx(1, i) * cy(1, i);
    b += cx(0, i) * cy(1, i) - cx(1, i) * cy(0, i);
  }
  const double spread = std::sqrt(cx.squaredNorm() * cy.squaredNorm());
  if (!(std::hypot(a, b) > 1e-12 * spread) || spread == 0.0) {
    throw InputError("SE(2) alignment: degenerate point sets (fewer than two distinct points, or no rotation "
                     "fits better than another)");
  }

  const double phi = std::atan2(b, a);
  const double c = std::cos(phi), s = std::sin(phi);
  SimilarityTransform result;
  result.rotation << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  const Vector2 t = meanY - Vector2(c * meanX.x() - s * meanX.y(), s * meanX.x() + c * meanX.y());
  result.translation = Vector3(t.x(), t.y(), 0.0);
  result.scale = 1.0;
  return result;
}

}  // namespace semslam
