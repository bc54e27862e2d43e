#pragma once
// ViewpointClassifierModel: the viewpoint-dependent Gaussian classifier model of paper A,
//     P(z_sem | c, x, x_o) = N(z_sem; h_c(θ), Σ_c(θ)),   θ = θ(x, x_o)          (A, eq. 2)
// the distribution of a classifier's output vector z_sem (scores or class probabilities, length dimension())
// when an object of class c is seen from viewpoint θ (Viewpoint.h gives θ(x, x_o) and its Jacobians).
//
// This is an interface: the analytic model of paper A's experiments (AnalyticViewpointClassifier, A eq. 18) and a
// model tabulated from a file (TabulatedViewpointClassifier, e.g. learned offline from images) both implement it,
// and so can a learned model (a GP, a network). Both the mean and the covariance may depend on θ.
//
// What an implementation provides (classes are 0-based: c ∈ [0, classes())):
//   mean(c, θ, &dh)    h_c(θ) ∈ R^d and dh_c/dθ (the viewpoint factor's Jacobian is dh_c/dθ · ∂θ/∂δ);
//   covariance(c, θ)   Σ_c(θ), d x d symmetric positive definite;
//   noiseModel(c, θ)   Σ_c(θ) as a NoiseModel (square-root information R, RᵀR = Σ⁻¹, and its log-normaliser); the
//                      default builds it from covariance(); implementations with a fixed Σ return a cached one.
// θ is any real number: models are 2π-periodic in θ.
//
// What the interface derives from them:
//   logLikelihood(z, c, θ) = log N(z; h_c(θ), Σ_c(θ)) = −½‖R (z − h_c(θ))‖² − logNormalizer(),
//                            with logNormalizer = ½ d log 2π − log|R|  (graph/NoiseModel.h);
//   sample(c, θ, rng)      = a draw of z from N(h_c(θ), Σ_c(θ)) (Sampling.h: same seed, same draw), for simulators.
// Invalid class indices, non-finite θ or measurement lengths throw std::invalid_argument.

#include <random>

#include "semslam/geometry/Matrix.h"
#include "semslam/graph/NoiseModel.h"

namespace semslam {

class ViewpointClassifierModel {
 public:
  virtual ~ViewpointClassifierModel() = default;

  /// M, the number of classes.
  virtual int classes() const = 0;
  /// d, the length of a semantic measurement z_sem.
  virtual int dimension() const = 0;

  /// h_c(θ) and, where requested, dh_c/dθ (length d).
  virtual Vector mean(int classIndex, double theta, Vector* dMeanDTheta = nullptr) const = 0;
  /// Σ_c(θ) (d x d, symmetric positive definite).
  virtual Matrix covariance(int classIndex, double theta) const = 0;
  /// Σ_c(θ) as a noise model; by default NoiseModel::fromCovariance(covariance(c, θ)).
  virtual SharedNoiseModel noiseModel(int classIndex, double theta) const;

  /// log N(z; h_c(θ), Σ_c(θ)).
  double logLikelihood(const Vector& z, int classIndex, double theta) const;
  /// A draw of z_sem for class c at viewpoint θ.
  Vector sample(int classIndex, double theta, std::mt19937& rng) const;

 protected:
  /// Throws std::invalid_argument unless 0 ≤ classIndex < classes().
  void checkClass(int classIndex) const;
  /// Throws std::invalid_argument unless θ is finite.
  static void checkTheta(double theta);
};

}  // namespace semslam
