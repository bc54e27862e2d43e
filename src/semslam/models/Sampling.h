#pragma once
// Sampling: the random draws that models and simulators take from a caller's std::mt19937.
//
// The standard library's distributions (std::uniform_real_distribution, std::normal_distribution, ...) are
// implementation-defined, so the same seed may give different numbers with another standard library. These
// helpers use only the engine's raw 32-bit outputs, whose sequence the standard fixes, so a seed gives the same
// draws everywhere (up to the last bit of libm's log/cos/sqrt):
//   uniform01:       u = (a · 2²¹ + b) / 2⁵³ from two raw outputs (a: top 32 bits, b: top 21 bits of the second),
//                    u ∈ [0, 1) with 53 random bits;
//   standardNormal:  Box–Muller, n = sqrt(−2 log(1 − u₁)) cos(2π u₂) (one normal per two uniforms; 1 − u₁ ∈ (0, 1]);
//   standardNormalMatrix: Box–Muller in pairs, n = ρ cos(2π u₂) and n' = ρ sin(2π u₂), ρ = sqrt(−2 log(1 − u₁)):
//                    two independent normals per two uniforms, for bulk draws (Monte Carlo integration) where half
//                    the engine outputs and logarithms matter; the entries fill the matrix in storage order (column
//                    by column), pair by pair, the second normal of an odd count's last pair discarded. The
//                    simulators keep standardNormal, so their streams (and the committed logs drawn from them)
//                    are unchanged;
//   sampleGaussian:  μ + L n with L Lᵀ = Σ (Cholesky); for a positive semi-definite Σ (rank-deficient, e.g. an
//                    odometry covariance without its floor) L = V sqrt(max(Λ, 0)) from the symmetric eigen
//                    decomposition Σ = V Λ Vᵀ.
// Each call consumes a fixed number of engine outputs: uniform01 2, standardNormal 4, sampleGaussian 4·d,
// standardNormalMatrix 4·⌈rows·cols / 2⌉.
//
// Invariants: sampleGaussian requires a square, finite, symmetric Σ of the mean's size whose eigenvalues are
// ≥ −1e-12 · max|Σ| (else std::invalid_argument).

#include <random>

#include "semslam/geometry/Matrix.h"

namespace semslam {

/// Uniform on [0, 1) with 53 random bits.
double uniform01(std::mt19937& rng);

/// A standard normal draw (Box–Muller).
double standardNormal(std::mt19937& rng);

/// A rows × cols matrix of independent standard normal draws (paired Box–Muller, above).
Matrix standardNormalMatrix(Eigen::Index rows, Eigen::Index cols, std::mt19937& rng);

/// L with L Lᵀ = Σ (Cholesky, or the eigen form above for a semi-definite Σ), for drawing many samples of one
/// Gaussian: x = μ + L n with n of standardNormal() draws.
Matrix gaussianSquareRoot(const Matrix& covariance);

/// A draw from N(mean, covariance); covariance may be positive semi-definite.
Vector sampleGaussian(const Vector& mean, const Matrix& covariance, std::mt19937& rng);

}  // namespace semslam
