#include "semslam/core/ChiSquare.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "semslam/core/InputError.h"

namespace semslam {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kMaxIterations = 10'000'000;

void checkShape(double a) {
  if (!(a > 0.0) || !std::isfinite(a)) {
    throw InputError("incomplete gamma: the shape must be positive and finite, got " + std::to_string(a));
  }
}

void checkArgument(double x) {
  if (!(x >= 0.0)) throw InputError("incomplete gamma: the argument must be >= 0, got " + std::to_string(x));
}

// log(1 + t) − t without cancellation for small |t|.
double log1pmx(double t) {
  if (std::abs(t) > 0.1) return std::log1p(t) - t;
  double power = t * t, sum = 0.0;
  for (int k = 2; k < 60; ++k) {
    const double term = (k % 2 == 0 ? -power : power) / k;
    sum += term;
    if (std::abs(term) <= kEpsilon * std::abs(sum)) break;
    power *= t;
  }
  return sum;
}

// log Γ(a) − ((a − ½) log a − a + ½ log 2π): the error of Stirling's approximation.
double stirlingError(double a) {
  if (a < 15.0) return std::lgamma(a) - ((a - 0.5) * std::log(a) - a + 0.5 * std::log(2.0 * std::numbers::pi));
  const double r = 1.0 / a, r2 = r * r;
  return r * (1.0 / 12.0 - r2 * (1.0 / 360.0 - r2 * (1.0 / 1260.0 - r2 * (1.0 / 1680.0 - r2 / 1188.0))));
}

// log D(a, x) = log(x^a e^{−x} / Γ(a)), arranged so that no a·log a terms cancel.
double logPrefactor(double a, double x) {
  if (x == 0.0) return -kInfinity;
  if (std::isinf(x)) return -kInfinity;
  const double t = (x - a) / a;
  // a log(x/a) − (x − a): through log1pmx near x = a, where its two terms cancel; directly elsewhere (x ≪ a
  // would round t to −1).
  const double core = t > -0.5 ? a * log1pmx(t) : a * (std::log(x) - std::log(a)) - (x - a);
  return core + 0.5 * std::log(a / (2.0 * std::numbers::pi)) - stirlingError(a);
}

double lowerSeries(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < kMaxIterations; ++n) {
    term *= x / (a + n);
    sum += term;
    if (term <= sum * kEpsilon) return std::exp(logPrefactor(a, x)) * sum;
  }
  throw std::runtime_error("incomplete gamma: the series did not converge");
}

double upperContinuedFraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a;
  double c = 1.0 / kTiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < kMaxIterations; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) <= kEpsilon) return std::exp(logPrefactor(a, x)) * h;
  }
  throw std::runtime_error("incomplete gamma: the continued fraction did not converge");
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
  if (x == 0.0) return 0.0;
  if (std::isinf(x)) return 1.0;
  if (x < a + 1.0) return lowerSeries(a, x);
  return 1.0 - upperContinuedFraction(a, x);
}

double regularizedGammaQ(double a, double x) {
  checkShape(a);
  checkArgument(x);
  if (x == 0.0) return 1.0;
  if (std::isinf(x)) return 0.0;
  if (x < a + 1.0) return 1.0 - lowerSeries(a, x);
  return upperContinuedFraction(a, x);
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
  return std::exp(logPrefactor(0.5 * dof, 0.5 * x)) / x;
}

double chiSquareQuantile(double p, double dof) {
  checkDof(dof);
  if (!(p >= 0.0 && p <= 1.0)) throw InputError("chi-square quantile: p must be in [0, 1], got " + std::to_string(p));
  if (p == 0.0) return 0.0;
  if (p == 1.0) return kInfinity;

  // g(x) increases with x and vanishes at the quantile; each tail is evaluated where it is accurate.
  const bool lowerTail = p <= 0.5;
  const double q = 1.0 - p;
  const auto g = [&](double x) { return lowerTail ? chiSquareCdf(x, dof) - p : q - chiSquareSurvival(x, dof); };

  double lo = 0.0, hi = std::max(dof, 1.0);
  while (g(hi) < 0.0) {
    lo = hi;
    hi *= 2.0;
  }
  // Start: for a small lower-tail probability, F_k(x) ≈ (x/2)^{k/2} / Γ(k/2 + 1); otherwise the bracket's middle.
  const double a = 0.5 * dof;
  double x = 0.5 * (lo + hi);
  if (lowerTail && p < 0.1) {
    const double guess = 2.0 * std::exp((std::log(p) + std::lgamma(a + 1.0)) / a);
    if (guess > lo && guess < hi) x = guess;
  }
  for (int iteration = 0; iteration < 1000; ++iteration) {
    const double value = g(x);
    if (value == 0.0) return x;
    if (value < 0.0) {
      lo = x;
    } else {
      hi = x;
    }
    const double density = chiSquareDensity(x, dof);
    double next = x - value / density;
    if (!(density > 0.0) || !std::isfinite(next) || !(next > lo && next < hi)) {
      next = (lo > 0.0 && hi > 4.0 * lo) ? std::sqrt(lo * hi) : 0.5 * (lo + hi);  // geometric for wide brackets
    }
    if (std::abs(next - x) <= 1e-15 * next || hi - lo <= 4.0 * kEpsilon * hi) return next;
    x = next;
  }
  return x;
}

}  // namespace semslam
