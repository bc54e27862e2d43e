// The chi-square distribution through Boost.Math (Debian's libboost-dev, header-only):
//   boost::math::gamma_p / gamma_q   regularized incomplete gamma functions, each tail computed directly
//     (https://www.boost.org/doc/libs/1_74_0/libs/math/doc/html/math_toolkit/sf_gamma/igamma.html);
//   boost::math::chi_squared_distribution   cdf, complement (survival), pdf and quantile
//     (https://www.boost.org/doc/libs/1_74_0/libs/math/doc/html/math_toolkit/dist_ref/dists/chi_squared_dist.html).
// Arguments are checked here first, so a bad one is an InputError with its value, never a Boost exception; the
// quantile takes the complement form for p > ½ so the upper tail keeps its relative accuracy.

#include "semslam/core/ChiSquare.h"

#include <cmath>
#include <limits>
#include <string>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include "semslam/core/InputError.h"

namespace semslam {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void checkShape(double a) {
  if (!(a > 0.0) || !std::isfinite(a)) {
    throw InputError("incomplete gamma: the shape must be positive and finite, got " + std::to_string(a));
  }
}

void checkArgument(double x) {
  if (!(x >= 0.0)) throw InputError("incomplete gamma: the argument must be >= 0, got " + std::to_string(x));
}

void checkDof(double dof) {
  if (!(dof > 0.0) || !std::isfinite(dof)) {
    throw InputError("chi-square: the degrees of freedom must be positive and finite, got " + std::to_string(dof));
  }
}

}  // namespace

double regularizedGammaP(double a, double x) {
  checkShape(a);
  checkArgument(x);
  if (std::isinf(x)) return 1.0;
  return boost::math::gamma_p(a, x);
}

double regularizedGammaQ(double a, double x) {
  checkShape(a);
  checkArgument(x);
  if (std::isinf(x)) return 0.0;
  return boost::math::gamma_q(a, x);
}

double chiSquareCdf(double x, double dof) {
  checkDof(dof);
  return regularizedGammaP(0.5 * dof, 0.5 * x);
}

double chiSquareSurvival(double x, double dof) {
  checkDof(dof);
  return regularizedGammaQ(0.5 * dof, 0.5 * x);
}

double chiSquareDensity(double x, double dof) {
  checkDof(dof);
  checkArgument(x);
  if (x == 0.0) return dof < 2.0 ? kInfinity : (dof == 2.0 ? 0.5 : 0.0);
  if (std::isinf(x)) return 0.0;
  return boost::math::pdf(boost::math::chi_squared_distribution<double>(dof), x);
}

double chiSquareQuantile(double p, double dof) {
  checkDof(dof);
  if (!(p >= 0.0 && p <= 1.0)) throw InputError("chi-square quantile: p must be in [0, 1], got " + std::to_string(p));
  if (p == 0.0) return 0.0;
  if (p == 1.0) return kInfinity;
  const boost::math::chi_squared_distribution<double> distribution(dof);
  if (p <= 0.5) return boost::math::quantile(distribution, p);
  return boost::math::quantile(boost::math::complement(distribution, 1.0 - p));
}

}  // namespace semslam
