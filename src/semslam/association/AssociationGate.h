#pragma once
// AssociationGate: the chi-square test that decides whether a landmark is a candidate for a detection
// (paper B, sec. IV-A): a candidate passes when its innovation chi2 r̄ᵀ S⁻¹ r̄ (MarginalLikelihood.h) is at most
// the `confidence` quantile of χ²_m, m the measurement dimension.
//
// Confidence. Paper B used 0.9, which by construction rejects 10 % of correct associations of a 2D measurement
// (each starts a spurious landmark). Our default is 1 − 10⁻⁶ (χ²₂ threshold 27.6): real data is never exactly as
// noisy as its stated model (Lost in the Woods' pose NEES is 5.9 against 3 even with known association), and a
// rejected re-observation duplicates a landmark for good, while an extra candidate costs only one more mixture
// component, which the max-mixture and its null hypothesis handle. docs/max-mixtures.md has the measurements.

#include <array>

#include "semslam/association/MarginalLikelihood.h"

namespace semslam {

class AssociationGate {
 public:
  static constexpr double kDefaultConfidence = 0.999999;
  static constexpr double kPaperConfidence = 0.9;

  /// Throws std::invalid_argument unless 0 < confidence < 1.
  explicit AssociationGate(double confidence = kDefaultConfidence);

  double confidence() const { return confidence_; }
  /// The χ²_dof quantile at the gate's confidence.
  double threshold(int dof) const;
  bool accepts(const LinearizedLikelihood& likelihood) const {
    return likelihood.innovationChi2 <= threshold(likelihood.dimension);
  }

 private:
  double confidence_;
  std::array<double, 13> thresholds_{};  // by dof, precomputed for 1..12 (the gate is shared between threads)
};

}  // namespace semslam
