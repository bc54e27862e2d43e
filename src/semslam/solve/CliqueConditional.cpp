#include "semslam/solve/CliqueConditional.h"

#include <Eigen/Cholesky>
#include <new>

namespace semslam {

bool CliqueConditional::eliminate(Eigen::Ref<Matrix> A, Eigen::Ref<const Vector> b, int frontalDimension,
                                  CliqueConditional& out) {
  const int nf = frontalDimension;
  const int ns = static_cast<int>(A.rows()) - nf;
  Eigen::Ref<Matrix> frontalBlock = A.topLeftCorner(nf, nf);
  Eigen::LLT<Eigen::Ref<Matrix>, Eigen::Lower> llt(frontalBlock);  // in place: L in the lower triangle
  if (llt.info() != Eigen::Success) return false;
  const auto L = A.topLeftCorner(nf, nf).triangularView<Eigen::Lower>();
  for (int i = 0; i < nf; ++i) {
    if (!(A(i, i) > 0.0)) return false;
  }
  out.allocate(nf, ns);
  out.R.setZero();
  out.R.triangularView<Eigen::Upper>() = A.topLeftCorner(nf, nf).transpose();
  out.T = A.topRightCorner(nf, ns);
  L.solveInPlace(out.T);
  out.z = b.head(nf);
  L.solveInPlace(out.z);
  // Ā = A_SS − TᵀT: a symmetric rank-nf update of the lower triangle, then mirrored.
  out.marginalInformation = A.bottomRightCorner(ns, ns);
  out.marginalInformation.selfadjointView<Eigen::Lower>().rankUpdate(out.T.transpose(), -1.0);
  out.marginalInformation.triangularView<Eigen::StrictlyUpper>() = out.marginalInformation.transpose();
  out.marginalVector = b.tail(ns);
  out.marginalVector.noalias() -= out.T.transpose() * out.z;
  return true;
}

void CliqueConditional::allocate(int nf, int ns) {
  storage_.resize(static_cast<std::size_t>(nf) * nf + static_cast<std::size_t>(nf) * ns + nf +
                  static_cast<std::size_t>(ns) * ns + ns);
  double* p = storage_.data();
  new (&R) Eigen::Map<Matrix>(p, nf, nf);  // re-seating a Map, as Eigen documents
  p += static_cast<std::ptrdiff_t>(nf) * nf;
  new (&T) Eigen::Map<Matrix>(p, nf, ns);
  p += static_cast<std::ptrdiff_t>(nf) * ns;
  new (&z) Eigen::Map<Vector>(p, nf);
  p += nf;
  new (&marginalInformation) Eigen::Map<Matrix>(p, ns, ns);
  p += static_cast<std::ptrdiff_t>(ns) * ns;
  new (&marginalVector) Eigen::Map<Vector>(p, ns);
}

void CliqueConditional::solve(Eigen::Ref<const Vector> separatorDelta, Eigen::Ref<Vector> frontalDelta) const {
  // Column-oriented loops: cliques are small, and Eigen's blocked kernels cost more than they save at these sizes.
  const Eigen::Index nf = R.rows();
  const Eigen::Index ns = T.cols();
  double* x = frontalDelta.data();
  for (Eigen::Index i = 0; i < nf; ++i) x[i] = z[i];
  for (Eigen::Index j = 0; j < ns; ++j) {
    const double s = separatorDelta[j];
    const double* column = T.data() + j * nf;
    for (Eigen::Index i = 0; i < nf; ++i) x[i] -= column[i] * s;
  }
  for (Eigen::Index j = nf - 1; j >= 0; --j) {
    const double* column = R.data() + j * nf;
    x[j] /= column[j];
    const double xj = x[j];
    for (Eigen::Index i = 0; i < j; ++i) x[i] -= column[i] * xj;
  }
}

}  // namespace semslam
