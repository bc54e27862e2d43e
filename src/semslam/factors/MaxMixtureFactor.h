#pragma once
// MaxMixtureFactor: a max-mixture of Gaussian factors (Olson & Agarwal, "Inference on networks of mixtures for
// robust robot mapping", IJRR 2013), used by paper B (sec. IV-C) to max-marginalise a detection's data association:
// one component per candidate landmark, plus an optional broad null-hypothesis component.
//
// Math. Component i is a Gaussian factor f_i with weight w_i > 0, whitened error r_i (dimension m_i) and
// log-normaliser n_i (Factor::logNormalizer). The mixture's negative log-likelihood is approximated by its
// largest term:
//     −log Σ_i w_i p_i(z | X)  ≈  min_i [ ½‖r_i(X)‖² + c_i ],   c_i = n_i − log w_i.
// At every linearisation the factor picks the component i* attaining the minimum (ties: the lowest index) and
// reports the whitened error
//     r(X) = [ r_i*(X) ; 0 (padding to m_max) ; sqrt(2 (c_i* − c_min)) ],   c_min = min_j c_j,
// so that ‖r‖² = 2 (min_i [½‖r_i‖² + c_i] − c_min): the cost is the max-mixture's negative log-likelihood up to
// a constant, with every component's normalisation explicit (a broad null hypothesis pays for its width), and it
// is continuous in X where the choice switches (a minimum of continuous functions). The last entry is constant in
// X, so the Jacobians are those of r_i* (zero columns for keys the chosen component does not touch). The error
// dimension is m_max + 1.
//
// Keys: the union of the components' keys, in first-appearance order. The factor is immutable: re-weighting
// means building a new one (Smoother::replaceFactor).
//
// A component may be declared a *widening* of an earlier one j: the same factor with every standard deviation
// scaled by s ≥ 1 (paper B's null hypothesis is the best candidate's detection factor widened), so that
// ‖r_i‖² = ‖r_j‖² / s² and n_i = n_j + m ln s. The choice then evaluates factor j once for both (in mm-nh with one
// candidate, half the work of `activeComponent`, which the front end calls for every detection of every landmark it
// sees, docs/association-front-end.md §6b). The declaration is checked where it can be: same keys, same error
// dimension, and the log-normalisers differing by m ln s (to 1e-9).
//
// How far a choice holds (`chooseAt`), for a mixture of detections of one landmark from one pose (paper B's
// candidate and its null): each component's whitened error moves by at most δ_i(ε) wherever the landmark seen from
// the robot has moved by at most ε (Factor::whitenedErrorBoundForSeenMove; δ_j(ε) / s for a widening of j), so its
// cost ‖r_i‖² + 2 (c_i − c_min) there lies within (√chi2_i ∓ δ_i)² + 2 (c_i − c_min) of what it is at the choice,
// and the choice holds while the chosen component's largest cost stays below every other's smallest. The front end
// asks, for every detection of every landmark it sees, whether its mixture is on the null hypothesis
// (docs/association-front-end.md §6b); the landmark has moved a millimetre, and the reach answers nearly all of them.
//
// Invariants: at least one component; weights finite and > 0; every component a normalised Gaussian factor
// (logNormalizer present); a widening refers to an earlier component that is not itself a widening, with the checks
// above; otherwise std::invalid_argument.

#include <optional>
#include <vector>

#include "semslam/graph/Factor.h"

namespace semslam {

class MaxMixtureFactor final : public Factor {
 public:
  /// `factor` is component `of` with every standard deviation times `sigmaScale` (see the header comment).
  struct Widening {
    int of = 0;
    double sigmaScale = 1.0;
  };

  struct Component {
    FactorPtr factor;
    double weight = 1.0;
    std::optional<Widening> widens;
  };

  explicit MaxMixtureFactor(std::vector<Component> components);

  const std::vector<Component>& components() const { return components_; }
  int errorDimension() const override { return maxComponentDimension_ + 1; }

  /// The index of the component the mixture uses at `values` (the argmin above; Factor::activeComponent).
  int activeComponent(const Values& values) const override;

  /// A choice and how far it holds.
  struct Choice {
    int component = 0;   ///< activeComponent at the point of the choice
    double reach = 0.0;  ///< the choice holds wherever the landmark seen from the robot moved by at most this
  };
  /// activeComponent at `values` and its reach (the header comment): for a mixture whose keys are one robot pose
  /// and one landmark, the largest ε found (doubling, then bisection) at which the bounds still certify the choice
  /// with a margin of 1e-9 × (1 + its cost), which round-off cannot close; 0 for other mixtures, where a component
  /// gives no bound, or where no ε > 0 is certain.
  Choice chooseAt(const Values& values) const;

  void linearize(const Values& values, LinearizedFactor& out) const override;
  double chi2(const Values& values) const override;

 private:
  static std::vector<Key> unionOfKeys(const std::vector<Component>& components);
  /// Throws std::invalid_argument where component i's widening (if any) breaks the header's invariants.
  void checkWidening(std::size_t i) const;
  /// Mixtures of up to this many components keep per-component scratch on the stack.
  static constexpr std::size_t kInlineComponents = 8;
  /// The chosen component and its chi2 (‖r_i‖²); every component's chi2 into `chi2s[0..n)` where given.
  std::pair<int, double> choose(const Values& values, double* chi2s = nullptr) const;
  /// Whether the bounds certify `chosen` at every point where the landmark seen moved by at most `epsilon`, given
  /// every component's chi2 at `values`.
  bool certifiedWithin(const Values& values, const double* chi2s, int chosen, double epsilon) const;

  std::vector<Component> components_;
  std::vector<double> constants_;  // c_i − c_min ≥ 0
  int maxComponentDimension_ = 0;
  std::vector<std::vector<int>> keySlots_;  // [component][its key] → index in keys()
};

}  // namespace semslam
