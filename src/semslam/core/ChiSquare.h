#pragma once
// The chi-square distribution with k > 0 degrees of freedom (k real), through the regularized incomplete gamma
// functions, for consistency tests (NEES bands) and gates. Computed by Boost.Math (ChiSquare.cpp cites the pages).
//
//   P(a, x) = γ(a, x) / Γ(a) = 1/Γ(a) ∫_0^x s^{a−1} e^{−s} ds,   Q(a, x) = 1 − P(a, x)
//   chi-square CDF:  F_k(x) = P(k/2, x/2);  survival 1 − F_k(x) = Q(k/2, x/2);
//   density          f_k(x) = (x/2)^{k/2} e^{−x/2} / (Γ(k/2) x)
//
// Each tail is computed directly, never as 1 − the other, so the relative error stays near machine precision in
// both tails and for hundreds of thousands of degrees of freedom (a NEES band over n poses of dimension d uses
// k = n d). The quantile F_k⁻¹(p) inverts the lower tail for p ≤ ½ and the upper tail (1 − p) otherwise.
// Checked against tables: F_3⁻¹(0.975) = 9.3484, F_3⁻¹(0.025) = 0.21580.
//
// Invalid arguments (k ≤ 0 or not finite, p outside [0, 1], negative or NaN x, a ≤ 0) throw InputError.

namespace semslam {

/// Regularized lower incomplete gamma P(a, x), a > 0, x ≥ 0.
double regularizedGammaP(double a, double x);
/// Regularized upper incomplete gamma Q(a, x) = 1 − P(a, x), computed without cancellation.
double regularizedGammaQ(double a, double x);

/// F_k(x) = P(k/2, x/2); 0 for x = 0.
double chiSquareCdf(double x, double dof);
/// 1 − F_k(x) = Q(k/2, x/2).
double chiSquareSurvival(double x, double dof);
/// f_k(x).
double chiSquareDensity(double x, double dof);
/// F_k⁻¹(p): 0 for p = 0, +∞ for p = 1.
double chiSquareQuantile(double p, double dof);

}  // namespace semslam
