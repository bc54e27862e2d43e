#pragma once
// Gaussian noise model of a factor, held as its square-root information matrix.
//
// For an error e with covariance Σ, the model stores the upper-triangular R with RᵀR = Σ⁻¹ (the Cholesky factor
// of the information matrix), and whitens e ↦ r = R e, J ↦ R J, so that ‖r‖² = eᵀΣ⁻¹e is the factor's chi2.
// Diagonal models (from sigmas) keep R diagonal and whiten row by row.
//
// The negative log-density of e is ½‖R e‖² + logNormalizer(), with logNormalizer() = ½ d log(2π) − log|R|;
// mixture factors need it to compare components with different covariances.
//
// An optional robust kernel (RobustKernel.h) turns the cost ‖r‖² into ρ(‖r‖²).
//
// Invariants: R is square, upper triangular, with a strictly positive, finite diagonal. Every constructor checks
// this and throws std::invalid_argument naming the problem (not symmetric, not positive definite, NaN).

#include <memory>

#include "semslam/geometry/Matrix.h"
#include "semslam/graph/RobustKernel.h"

namespace semslam {

class NoiseModel;
using SharedNoiseModel = std::shared_ptr<const NoiseModel>;

class NoiseModel {
 public:
  /// From a symmetric positive definite covariance Σ.
  static SharedNoiseModel fromCovariance(const Matrix& covariance);
  /// From a symmetric positive definite information matrix Σ⁻¹.
  static SharedNoiseModel fromInformation(const Matrix& information);
  /// From an upper-triangular square-root information matrix R (RᵀR = Σ⁻¹), as iSAM files give it.
  static SharedNoiseModel fromSqrtInformation(const Matrix& sqrtInformation);
  /// Diagonal: independent errors with the given standard deviations.
  static SharedNoiseModel fromSigmas(const Vector& sigmas);
  /// Isotropic: every component with standard deviation sigma.
  static SharedNoiseModel isotropic(int dimension, double sigma);

  /// The same Gaussian with a robust kernel on top.
  SharedNoiseModel withRobustKernel(SharedRobustKernel kernel) const;

  int dimension() const { return static_cast<int>(sqrtInformation_.rows()); }
  bool isDiagonal() const { return diagonal_; }
  const Matrix& sqrtInformation() const { return sqrtInformation_; }
  Matrix information() const { return sqrtInformation_.transpose() * sqrtInformation_; }
  Matrix covariance() const;
  /// ½ d log(2π) − log|R|: the constant of the negative log-density.
  double logNormalizer() const { return logNormalizer_; }
  const RobustKernel* robustKernel() const { return kernel_.get(); }

  /// In place: m ← R m, for an error vector or a Jacobian with dimension() rows.
  template <class Derived>
  void whitenInPlace(Eigen::MatrixBase<Derived>& m) const {
    if (diagonal_) {
      m = sqrtInformation_.diagonal().asDiagonal() * m;
    } else {
      m = sqrtInformation_.template triangularView<Eigen::Upper>() * m;
    }
  }

  /// The largest ‖R c‖ over the box |c_i| ≤ halfWidths_i: how far the whitened error can move when each entry of
  /// the error moves by at most its half-width. ‖R c‖² is convex, so the largest is at a corner; all 2^d are tried.
  double largestWhitenedNormInBox(const Vector& halfWidths) const;
  /// How large |e_i| can be where ‖R e‖² = chi2: ‖r‖ √Σ_ii, with √Σ_ii the norm of row i of R⁻¹ (Cauchy-Schwarz on
  /// e_i = (R⁻¹ r)_i).
  double largestErrorEntry(int i, double chi2) const;

  Vector whiten(const Vector& error) const {
    Vector r = error;
    whitenInPlace(r);
    return r;
  }

 private:
  NoiseModel(Matrix sqrtInformation, bool diagonal);

  Matrix sqrtInformation_;
  bool diagonal_;
  double logNormalizer_;
  SharedRobustKernel kernel_;
};

}  // namespace semslam
