#include "semslam/eval/Umeyama.h"

#include <limits>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "semslam/core/InputError.h"

namespace semslam {

SimilarityTransform umeyamaAlignment(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& y, bool withScale) {
  if (x.cols() != y.cols()) throw InputError("Umeyama alignment: the point sets differ in size");
  if (x.cols() == 0) throw InputError("Umeyama alignment: no points");
  const double n = static_cast<double>(x.cols());

  const Vector3 meanX = x.rowwise().mean();
  const Vector3 meanY = y.rowwise().mean();
  const Eigen::Matrix3Xd cx = x.colwise() - meanX;
  const Eigen::Matrix3Xd cy = y.colwise() - meanY;
  const double sigmaX = cx.squaredNorm() / n;
  const Matrix3 covariance = (cy * cx.transpose()) / n;

  const Eigen::JacobiSVD<Matrix3> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Vector3 d = svd.singularValues();
  const Eigen::Index rank = (d.array() > std::numeric_limits<double>::epsilon()).count();
  if (rank < 2) throw InputError("Umeyama alignment: degenerate covariance rank (points on a line or a single point)");

  Matrix3 s = Matrix3::Identity();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) s(2, 2) = -1.0;

  SimilarityTransform result;
  result.rotation = svd.matrixU() * s * svd.matrixV().transpose();
  result.scale = withScale ? (d.asDiagonal() * s).trace() / sigmaX : 1.0;
  result.translation = meanY - result.scale * (result.rotation * meanX);
  return result;
}

}  // namespace semslam
