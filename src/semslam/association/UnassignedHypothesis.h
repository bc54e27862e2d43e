#pragma once
// UnassignedHypothesis: the likelihood that a detection comes from no mapped landmark — a landmark not yet in the
// map (birth) or nothing static (clutter) — as a density in the detection's measurement space, the same space and
// units as the normaliser of MarginalLikelihood.h (docs/association-front-end.md, §1):
//
//   p(z | unassigned) = λ(z_g) · P₀(s),   λ = ρ · J(z_g),   ρ = μ / V,
//
//   μ      expected unassigned detections (births + clutter) per step: the constant `rate` (default 1), or, with a
//          prior weight w (`rateWeight`), estimated from the run as trackers estimate an unknown clutter rate,
//            μ̂ = (w μ₀ + n) / (w + T),
//          the posterior mean of a Poisson rate under a Gamma(w μ₀, w) prior: μ₀ = `rate` counted as w steps of
//          prior data, n the detections the run decided unassigned over its T steps so far (countStep(); a
//          decision at step k counts from step k + 1 on). docs/association-front-end.md §10, "μ from the run".
//          With a memory of M steps (`rateMemory`) the counts are discounted, as for a rate that drifts (West
//          and Harrison's discount factor for a Poisson level): each step multiplies n and T by γ = 1 − 1/M
//          before adding its own, so μ̂ = (w μ₀ + Σ_i γ^(T−i) n_i) / (w + Σ_i γ^(T−i)) weighs the last ~M steps
//          (Σ γ^i < M) while the prior w is kept whole, so a long stretch without births cannot drive μ̂ to 0;
//   V      the sensor field's area (2D) or volume (3D) in the world: a sector of radius r_max and opening Φ,
//          V = Φ r_max² / 2; in 3D a spherical sector, V = (r_max³ / 3) · Φ · 2 sin(Ψ / 2) with Ψ the elevation span;
//   J      the Jacobian of the back-projection, since births are uniform in the world, not in the sensor's
//          coordinates: range-bearing r (per m·rad), range-bearing-elevation r² cos φ (per m·rad²), relative
//          position 1 (per m² or m³); a relative pose adds a uniform orientation (÷ 2π in 2D, ÷ 8π² in 3D);
//   P₀(s)  the label's predictive under the uniform class prior, Σ_c P(s | c) / M (1 without semantics).
//
// r_max and Φ are the sensor specification's (maxRange, fieldOfView) where they are positive; a 0 in the log
// ("unlimited", "all around", or simply not stated by a converter) falls back to the largest range and the bearing
// span of the detections seen so far (observe()), i.e. to the data, online, never a per-log constant (an all-around
// sensor's detections span close to 2π). Ψ always comes from the data. logDensity throws std::logic_error while
// something it needs is undefined: before the first detection, unless the specification gives both r_max and Φ
// (2D only). Ranges below 1 mm count as 1 mm (a detection at the sensor has no bearing).
//
// The switch point (§2): a landmark with predicted measurement ẑ and innovation covariance S beats this
// hypothesis exactly when d² = (z − ẑ)ᵀ S⁻¹ (z − ẑ) < d*², d*² = −2 ln(λ (2π)^{m/2} |S|^{1/2} P₀(s) / P(s | j)).

#include <optional>

#include "semslam/models/MeasurementLog.h"

namespace semslam {

class UnassignedHypothesis {
 public:
  static constexpr double kDefaultRate = 1.0;

  /// `rate` is μ, or μ₀ when `rateWeight` (w, in steps) is given: μ is then estimated from countStep() as above,
  /// over the last ~`rateMemory` (M) steps where that is given. Throws std::invalid_argument for a rate or a weight
  /// that is not positive and finite, a memory that is not finite and ≥ 1, or a memory without a weight.
  UnassignedHypothesis(const LogHeader& header, double rate = kDefaultRate,
                       std::optional<double> rateWeight = std::nullopt,
                       std::optional<double> rateMemory = std::nullopt);

  /// The μ in use: the constant rate, or the estimate μ̂ from the steps counted so far.
  double rate() const;
  /// Counts one completed step whose joint assignment left `unassignedDetections` detections unassigned (no-op for
  /// a constant rate). Throws std::invalid_argument for a negative count.
  void countStep(int unassignedDetections);
  /// A copy whose μ is the constant `rate` (the field's extents as they stand): two branches of a split are scored
  /// with the rate of the history they share (slam/BranchScore.h). Throws as the constructor does.
  UnassignedHypothesis withRate(double rate) const;

  /// Widens the data-defined extents (range, bearing, elevation) by one detection's geometry.
  void observe(const Detection& detection);

  /// ln λ(z_g) of a detection's geometry (not its label): logLandmarkDensity() + logBackProjectionJacobian.
  double logDensity(const Detection& detection) const;
  /// ln J of a detection's geometry: the Jacobian determinant of the back-projection of its position part to the
  /// world (r, r² cos φ, or 1 for relative positions and poses), so that a position covariance R in the sensor's
  /// coordinates is J R Jᵀ in the world with ½ ln det(J R Jᵀ) = ½ ln det R + ln J.
  double logBackProjectionJacobian(const Detection& detection) const;
  /// ln ρ = ln(μ / V): the density of unassigned landmarks per m² (2D) or m³ (3D) of the world, the prior of a
  /// provisional landmark's merge test (docs/association-front-end.md §5).
  double logCartesianDensity() const;
  /// ln of the same density over a landmark's variable as the sensor observes it: ρ, times the uniform orientation
  /// density (1 / 2π in 2D, 1 / 8π² in 3D) when the sensor measures relative poses; the prior of an unassigned
  /// landmark in a branch's evidence (slam/BranchScore.h).
  double logLandmarkDensity() const;
  /// Whether a point at `position` in the sensor frame (2 or 3 numbers) lies in the field: range ≤ r_max and
  /// |bearing| ≤ Φ / 2 (and |elevation| ≤ Ψ / 2 in 3D).
  bool inField(const Vector& position) const;

  /// The field's extents in use: r_max, Φ and (3D) Ψ.
  double maxRange() const;
  double bearingSpan() const;
  double elevationSpan() const;

 private:
  struct Polar {
    double range = 0.0, bearing = 0.0, elevation = 0.0;
  };
  Polar polarOf(const Detection& detection) const;
  Polar polarOfPosition(const Vector& position) const;
  void requireField() const;

  SensorKind kind_;
  int dimension_;
  double rate_;                        // μ, or μ₀ with a weight
  std::optional<double> rateWeight_;   // w: set where μ is estimated
  double countDiscount_ = 1.0;         // γ = 1 − 1/M; 1 without a memory
  double unassignedCounted_ = 0.0;     // n
  double stepsCounted_ = 0.0;          // T
  double specRange_, specFieldOfView_;
  double observedRange_ = 0.0, observedBearing_ = 0.0, observedElevation_ = 0.0;  // largest |.| seen
  bool observedAny_ = false;
};

/// d*², the squared Mahalanobis distance below which a landmark beats the unassigned hypothesis (see above):
/// −2 (logDensity + (m/2) ln 2π + ½ ln|S| + ln P₀(s) − ln P(s | j)). Negative: the unassigned hypothesis always wins.
double switchDistanceSquared(double logDensity, int measurementDimension, double logDeterminantS,
                             double logLabelPredictiveRatio = 0.0);

}  // namespace semslam
