#pragma once
// IncrementalSmoother: the Smoother that keeps a Bayes tree of the Gauss-Newton system and, at each update,
// re-eliminates only the part the new, removed or relinearized factors touch: iSAM2 (Kaess, Johannsson, Roberts,
// Ila, Leonard and Dellaert, "iSAM2: Incremental smoothing and mapping using the Bayes tree", IJRR 31(2), 2012).
//
// State. Every variable v has a linearization point θ_v and an update Δ_v (tangent, right perturbation,
// translation first); the estimate is θ_v ⊕ Δ_v. Every factor is linearized at θ (the values of its own variables).
// The Bayes tree holds the square-root factor of the Gauss-Newton system  A Δ = b  (A = Σ JᵀJ, b = −Σ Jᵀr at θ) as
// cliques (CliqueConditional.h): clique C eliminates its frontal variables F_C given its separator S_C, the
// separator being a subset of the variables of the parent clique. A factor's contribution lives in the clique of
// its first-eliminated variable, and flows up the tree to the root only through the cached marginal factors
// (Schur complements) the cliques pass to their parents. Hence:
//
//   - a clique's conditional depends only on the factors in its subtree;
//   - a factor touching variables V affects only the cliques holding V and their ancestors (paths to the root).
//
// update(new factors, new values, removed) (iSAM2 Alg. 6):
//   1. marks the variables of new, removed and replaced factors; every relinearizeSkip updates, relinearizes each
//      variable with ‖Δ_v‖∞ > relinearizeThreshold (θ_v ← θ_v ⊕ Δ_v, Δ_v ← 0) and marks every variable of every
//      factor touching it (fluid relinearization);
//   2. removes the cliques holding marked variables and all their ancestors (the "top" of the tree); the
//      children of removed cliques that are not removed themselves are orphans, kept with their cached marginals;
//   3. gathers the factors whose variables all lie in the removed part, re-linearizes those that are stale, and
//      orders the removed part with CAMD, the variables of the new factors constrained last (ConstrainedOrdering.h);
//   4. eliminates it symbolically (column structures; cliques = fundamental supernodes, plus relaxed amalgamation
//      of small ones), then numerically, clique by clique bottom-up, adding each factor's cached information and
//      each orphan's cached marginal to the clique of its first-ordered variable (which becomes the orphan's new
//      parent);
//   5. back-substitutes top-down (partial state update): re-eliminated cliques are always solved; an untouched
//      clique only if some variable of its separator moved by more than wildfireThreshold.
// Need-based reordering: when the factor's entries per variable grow past reorderFillGrowth times their value
// after the last full ordering, an update re-orders and re-eliminates the whole tree (linearizations are reused).
//
// Mixtures (factors with a discrete choice, Factor::activeComponent ≥ 0: paper B's max-mixtures, sec. IV-C). A
// mixture is linearized with the component c_f(θ) active at θ, so one Gauss-Newton step at θ cannot take it to
// another component's basin. Each update therefore re-chooses, as the batch smoother does at every Gauss-Newton
// iterate (docs/incremental-smoother.md, "Mixtures"; docs/association-front-end.md §6):
//   0. before the solve, a mixture entering the graph (new, or replacing a factor) with c_f(θ) ≠ c_f(θ ⊕ Δ) has
//      its variables relinearized at the estimate (θ_v ← θ_v ⊕ Δ_v, Δ_v ← 0, fluid: every factor touching them
//      re-linearized and re-eliminated): it chooses where the batch smoother's first iterate would;
//   1. after the solve, every mixture the update touched is checked: linearized in it, or touching a variable v
//      whose Δ_v has moved by more than wildfireThreshold (∞-norm) since v's mixtures were last checked (the
//      partial state update's own measure of a negligible move; exact with a threshold of 0). If its linearized
//      component differs from c_f(θ ⊕ Δ) at the new estimate, its variables are relinearized there and steps 2–5
//      run again on what that marks;
//   2. repeat 1 until no touched mixture switches, at most maxSwitchRounds extra solves
//      (IncrementalSmootherParams.h). Mixtures still switching then are checked first at the next update.
// Opt-in: maxSwitchRounds is 0 by default (steps 0–2 skipped), for the measured reasons in its comment.
// Invariant after an update (unless the round limit stopped it): every mixture's linearized component is the one
// active at the estimate up to the check threshold, i.e. at a point θ ⊕ Δ' with ‖Δ'_v − Δ_v‖∞ ≤ 2 wildfireThreshold
// on each of its variables (each is within the threshold of its value at its own last check, and the mixture was
// checked at or after that), and the estimate is the exact Gauss-Newton step at θ with those components: a fixed
// point of "choose at the estimate, solve", which is what a converged batch solve also satisfies (exactly so with
// wildfireThreshold 0). The check costs what moved, not the graph: a landmark that every detection touches moves a
// little at every update, and checking all its mixtures each time made the check grow with the landmark's history
// (docs/incremental-smoother.md, "Mixtures"). A graph without
// mixtures does exactly the work, and gets exactly the numbers, it did without this rule.
//
// Exactness: with wildfireThreshold = 0 every update's Δ solves the Gauss-Newton system at θ exactly (the tree is
// the Cholesky factor of A under its ordering); with the default, the cliques below separators that moved less
// than the threshold keep their previous Δ. An intermediate estimate is thus one Gauss-Newton step from θ, which
// lies within the relinearization threshold of it; convergeAll() iterates to the batch optimum.
//
// Marginals: jointMarginal(keys) is the covariance of the Gaussian at the linearization point θ (A⁻¹ restricted to
// the keys), computed by two triangular solves per scalar column that touch only the cliques on the paths from
// the keys to the root: cheap for recent variables, which iSAM2's ordering keeps near the root; never a dense
// inverse. It equals Marginals(factors(), linearizationPoint()); after convergeAll(), θ is the optimum.
//
// replaceFactor(index, factor) takes effect at the next update (both the old and the new factor's variables are
// marked then). Variables are never removed; a variable no factor touches is left out of the tree, at its value.
//
// fork(): copies the tree topology and the per-variable and per-factor records, O(variables + factors + cliques)
// small copies, and shares the immutable parts: factors, their linearizations and every clique's conditional
// (the dense matrices, the bulk of the memory). Measured in bench/IncrementalReplayBenchmark.
//
// An update that throws std::invalid_argument leaves the smoother unchanged; one that throws std::runtime_error
// (a variable the factors do not constrain) leaves it unusable.

#include <memory>
#include <unordered_map>
#include <vector>

#include "semslam/solve/CliqueConditional.h"
#include "semslam/solve/IncrementalSmootherParams.h"
#include "semslam/solve/Optimizer.h"
#include "semslam/solve/Smoother.h"
#include "semslam/solve/SymbolicElimination.h"

namespace semslam {

class IncrementalSmoother final : public Smoother {
 public:
  /// What the last update() did, for benchmarks and tests.
  struct UpdateStatistics {
    int relinearizedVariables = 0;
    int reeliminatedVariables = 0;
    int reeliminatedCliques = 0;
    int solvedCliques = 0;
    bool fullReordering = false;
    int checkedMixtures = 0;    // mixtures whose component was compared with the one active at the estimate
    int componentSwitches = 0;  // mixtures relinearized because their active component changed (steps 0–1)
    int switchRounds = 0;       // extra solves for them (≤ maxSwitchRounds)
  };

  explicit IncrementalSmoother(IncrementalSmootherParams params = {});

  std::vector<FactorIndex> update(const FactorGraph& newFactors = {}, const Values& newValues = {},
                                  const std::vector<FactorIndex>& removed = {}) override;
  void replaceFactor(FactorIndex index, FactorPtr factor) override;
  using Smoother::estimate;
  const Values& estimate() const override;
  JointMarginal jointMarginal(const std::vector<Key>& keys) const override;
  FactorGraph factors() const override;
  FactorPtr factor(FactorIndex index) const override;
  std::unique_ptr<Smoother> fork() const override;
  std::size_t memoryBytes() const override;

  /// Gauss-Newton to convergence on the whole graph: the batch optimizer (Optimizer.h, same stopping rules) from
  /// the current estimate, then the tree rebuilt at its result: θ ← the optimum, every factor relinearized, the
  /// whole tree re-ordered, re-eliminated and solved exactly. Pending replacements take effect. Afterwards the
  /// linearization point is the optimum and the estimate is one (vanishing) Gauss-Newton step from it. Returns
  /// the batch optimizer's result.
  OptimizationResult convergeAll(const OptimizerParams& params = {});
  void converge() override { convergeAll(); }

  /// θ: the point every factor is linearized at.
  const Values& linearizationPoint() const { return theta_; }
  const UpdateStatistics& lastUpdate() const { return lastUpdate_; }
  std::size_t cliqueCount() const { return cliques_.size() - freeCliques_.size(); }
  /// Stored entries of the square-root factor (Σ over cliques of nf(nf+1)/2 + nf·ns).
  std::size_t factorEntries() const { return factorEntries_; }

 private:
  // Copies only through fork(), which rebinds the estimate's slots.
  IncrementalSmoother(const IncrementalSmoother&) = default;
  IncrementalSmoother& operator=(const IncrementalSmoother&) = delete;

  struct Variable {
    Key key = 0;
    int dimension = 0;
    int offset = 0;            // of Δ_v in delta_
    std::vector<int> factors;  // slots in force touching it
    // Beside each slot of `factors`, the variable it joins this one to: the other one of a binary factor, this one
    // of a unary factor, −1 for a factor of more variables. It spares the gathering of step 3 a visit to every slot
    // of a landmark seen many times (gatherFactorsInside).
    std::vector<int> partners;
    int clique = -1;           // the clique holding it as a frontal, −1 when it is not in the tree
  };
  /// A factor linearized at θ, in information form over its variables: JᵀJ and −Jᵀr (whitened), computed once per
  /// linearization and added into every clique elimination that gathers the factor.
  struct FactorContribution {
    Matrix information;
    Vector vector;
    std::vector<int> offsets;  // of each variable's block
  };
  struct Slot {
    FactorPtr factor;  // null once removed
    std::vector<int> variables;
    std::shared_ptr<const FactorContribution> linearization;  // at θ; null when stale
    int component = -1;  // Factor::activeComponent at θ when linearized (rule on): −1 for none
  };
  struct Clique {
    std::vector<int> frontals;   // in elimination order
    std::vector<int> separator;  // in elimination order
    int parent = -1;
    std::vector<int> children;
    std::shared_ptr<const CliqueConditional> conditional;
  };

  void validate(const FactorGraph& newFactors, const Values& newValues, const std::vector<FactorIndex>& removed) const;
  int addVariable(Key key, const Value& value);
  void attach(int slot);
  void detach(int slot);
  void relinearize(int variable);
  /// The variables an update re-eliminates, each once, in order of marking.
  struct MarkedVariables {
    std::vector<int> list;
    std::vector<char> isMarked;
    void mark(int v) {
      if (!isMarked[v]) {
        isMarked[v] = 1;
        list.push_back(v);
      }
    }
  };
  /// Fluid relinearization of one variable: relinearize(v), then mark every variable of every factor touching it.
  void relinearizeAndMark(int variable, MarkedVariables& marked);
  // Mixtures (class comment, steps 0–2; IncrementalSmootherMixtures.cpp).
  /// The mixtures among `slots` whose linearized component (or, when `atTheta`, the one active at θ) differs from
  /// the one active at the estimate θ ⊕ Δ.
  std::vector<int> switchedMixtures(const std::vector<int>& slots, bool atTheta);
  /// Relinearizes at the estimate every variable of each of `mixtures` whose Δ is not zero, marking as fluid
  /// relinearization does.
  void relinearizeMixtures(const std::vector<int>& mixtures, MarkedVariables& marked);
  /// The mixtures the last solve touched: linearized in it (scratch_.linearizedMixtures), touching a variable whose
  /// Δ it changed (scratch_.changedVariables) by more than `threshold` since the variable's last check
  /// (movedSinceMixtureCheck), or left unsettled by the previous update.
  std::vector<int> touchedMixtures(double threshold);
  /// Whether variable v's Δ has moved by more than `threshold` (∞-norm) since its mixtures were last checked; if
  /// so, records Δ_v as checked now.
  bool movedSinceMixtureCheck(int variable, double threshold);
  /// Steps 1–2: check (the mixtures of variables moved by more than `wildfireThreshold`), relinearize, re-solve
  /// (back-substituting with it) until settled or maxSwitchRounds.
  void settleMixtures(const std::vector<bool>& constrainedLast, double wildfireThreshold);
  /// The part of the tree being re-eliminated: its variables (local index i ↔ variables[i]) and the orphans, the
  /// subtrees left below it with their cached marginals.
  struct ReeliminatedPart {
    std::vector<int> variables;
    std::vector<int> orphans;
  };
  /// Steps 2–4 of the class comment for the marked variables; returns the new cliques.
  std::vector<int> reeliminate(const std::vector<int>& marked, const std::vector<bool>& constrainedLast);
  // The phases of reeliminate, in order (comments in the .cpp). Those after detachTop need the local numbering of
  // the part's variables in scratch_.localIndex.
  ReeliminatedPart detachTop(const std::vector<int>& marked);
  std::vector<int> gatherFactorsInside(const std::vector<int>& eliminated);
  void linearizeStale(const std::vector<int>& slots);
  std::vector<int> orderPart(const ReeliminatedPart& part, const std::vector<int>& gathered,
                             const std::vector<bool>& constrainedLast);
  std::vector<int> buildCliques(const ReeliminatedPart& part, const std::vector<int>& order,
                                const std::vector<int>& rank);
  void eliminateCliques(const std::vector<int>& cliqueIds, const std::vector<int>& gathered,
                        const std::vector<int>& rank);
  /// Position of variable v in the part being re-eliminated, −1 outside it.
  int localIndexOf(int v) const { return scratch_.localIndex[v]; }
  void backSubstitute(const std::vector<int>& newCliques, double wildfireThreshold);
  int allocateClique();
  void freeClique(int id);
  std::size_t entries(const Clique& clique) const;
  double deltaNorm(int variable) const;
  void markStale(int variable) const;

  IncrementalSmootherParams params_;
  std::vector<Variable> variables_;
  std::unordered_map<Key, int> variableIds_;
  Values theta_;
  std::vector<Value> thetaById_;  // θ again, by variable id, for the estimate's refresh
  std::vector<double> delta_;
  std::vector<double> deltaAtMixtureCheck_;  // Δ_v when v's mixtures were last checked (same layout as delta_)
  std::vector<Slot> slots_;
  std::vector<int> pendingMarked_;  // variables of factors replaced since the last update
  std::vector<int> pendingReplaced_;  // slots replaced since the last update (mixtures among them: step 0)
  std::vector<int> unsettledMixtures_;  // mixtures still switching when the last update hit maxSwitchRounds
  std::vector<Clique> cliques_;
  std::vector<int> freeCliques_;
  std::vector<int> roots_;
  std::size_t factorEntries_ = 0;
  double entriesPerVariableAtReorder_ = 0.0;
  int updates_ = 0;
  bool forceFull_ = false;  // convergeAll: relinearize everything, re-eliminate everything, solve exactly
  UpdateStatistics lastUpdate_;

  std::vector<int> relinearizationCandidates_;  // variables whose Δ changed since their last relinearization check
  std::vector<char> isCandidate_;

  // Scratch of update(), indexed by variable: position in the re-eliminated part (−1 outside it) and scalar offset
  // in the clique being eliminated. Not state: a fork starts with its own.
  struct Scratch {
    Scratch() = default;
    Scratch(const Scratch&) {}
    Scratch& operator=(const Scratch&) { return *this; }
    std::vector<int> localIndex;
    std::vector<int> scalarOffset;
    std::vector<int> slotStamp;
    std::vector<int> positions;
    std::vector<double> cliqueSystem;  // the dense (A, b) of the clique being eliminated
    std::vector<std::vector<int>> neighbours, later, factorsOfClique;
    SymbolicElimination symbolic;
    int stamp = 0;
    LinearizedFactor linearized;
    std::vector<double> solveBuffer;  // one clique's frontal and separator Δ in back-substitution
    std::vector<int> changedVariables;    // variables whose Δ the last back-substitution changed
    std::vector<int> linearizedMixtures;  // mixture slots linearized by the last re-elimination
  };
  Scratch scratch_;

  mutable Values estimate_;
  mutable std::vector<int> staleEstimates_;
  mutable std::vector<char> isStale_;
  std::vector<Value*> estimateSlots_;  // by variable: its node in estimate_ (rebound by fork())
};

}  // namespace semslam
