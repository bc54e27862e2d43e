#pragma once
// HybridOptions: every switch of paper A's hybrid belief (Algorithm 1) as implemented here; docs/hybrid-belief.md
// explains each choice where the paper is silent.
//
//   useSemantics        false: the geometric-only mode (passive DA-BSP, A sec. V): semantic parts are ignored and
//                       class realizations are not enumerated; true: semantic factors (eq. 10, 18) or categorical
//                       likelihoods enter weights and beliefs, and each component carries a class realization.
//   weights             Sampled: eq. 16-17 by Monte Carlo over the joint marginal of x_k and the associated objects
//                       with `samples` draws, times the visibility model; Importance: the same integral by
//                       importance sampling with `samples` draws from the linearised posterior of the joint variables
//                       given the candidate's detections (association/ImportanceSampledLikelihood.h), times the
//                       visibility model; Analytic: the linearised marginal likelihood
//                       (association/MarginalLikelihood.h, the weight of paper B), without visibility.
//   importanceIterations  linearisations of the importance proposal's update: 1 at the mean (the linearised
//                       update), > 1 iterated (ImportanceSampledLikelihood.h).
//   pruneRatio          prune components with w < w_max / pruneRatio (A sec. V: 150); ≤ 1 disables pruning.
//   gateRatio           before sampling, skip candidates whose linearised weight is below w_max,lin / gateRatio
//                       (the weight they could carry is reported as the gate's lost mass); ≤ 1 disables the gate.
//   branching           WholeAssociation: every β_k of the step (each detection to a distinct object) as in
//                       Algorithm 1; OneDetectionAtATime: branch detection by detection, keeping only partial
//                       associations whose stacked innovation passes a joint-compatibility χ² test at
//                       `jointCompatibility` and pruning partial hypotheses between detections.
//   maxComponents       after pruning keep at most this many (heaviest); 0: no cap. With maxCandidates, what bounds
//                       the memory of a run (docs/hybrid-belief.md, "Bounded memory"): every component holds its own
//                       smoother, a copy of its whole factor graph, so the default cap is kDefaultMaxComponents.
//   maxCandidates       the candidate children one step may hold at once. WholeAssociation counts, before
//                       branching, an upper bound of the step's candidates, Σ_parents N!/(N−n)! · M^n (n detections,
//                       N objects, M classes when semantics enumerate them); past this bound the step branches one
//                       detection at a time instead (reported: PropWeightsReport::branchedOneAtATime).
//                       OneDetectionAtATime keeps at most this many partial associations between detections, the
//                       heaviest by linearised weight (reported: truncatedPartials).
//   maxMemoryMiB        the memory the belief's smoothers may hold, in MiB. Before the observation update of a step
//                       the belief reads the largest propagated component's Smoother::memoryBytes() (its estimate,
//                       index and cached factorization: what each child will hold); during a step the previous
//                       components, their propagated copies and the children are alive at once, so at most
//                       floor(budget / (3 · that)) children are kept, the heaviest (reported:
//                       HybridStepReport::memoryCappedComponents). A budget that holds not one component throws
//                       std::runtime_error naming the step and both sizes. The count is deterministic (container
//                       sizes, not the allocator's), so the same seed gives the same belief on any machine.
//   enumerateAllClasses start from all M^N class realizations instead of collapsing unassociated objects
//                       (A sec. IV-D); for tests that check collapsing.
//   visibility          multiply sampled weights by the object observation model P(β_k | x_k, X^o) (A eq. 14-16).
//   seed                the one random stream of a run (Monte Carlo draws).
//   smootherFactory     makes each component's Smoother (default: BatchSmoother, Levenberg-Marquardt); an
//                       incremental smoother slots in here.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "semslam/solve/SmootherFactory.h"

namespace semslam {

enum class WeightMethod { Sampled, Analytic, Importance };  // values fixed: Analytic stays 1

/// "sampled", "importance", "analytic" ↔ WeightMethod; parseWeightMethod throws std::invalid_argument otherwise.
WeightMethod parseWeightMethod(const std::string& name);
const char* weightMethodName(WeightMethod method);
enum class Branching { WholeAssociation, OneDetectionAtATime };


/// BatchSmoother with Levenberg-Marquardt (robust to the far-off linearisation points of a broad initial prior).
SmootherFactory defaultSmootherFactory();

struct HybridOptions {
  static constexpr int kDefaultMaxComponents = 1000;
  static constexpr int kDefaultMaxCandidates = 100000;
  static constexpr double kDefaultMaxMemoryMiB = 2048.0;

  bool useSemantics = true;
  WeightMethod weights = WeightMethod::Sampled;
  int samples = 1000;
  int importanceIterations = 1;
  double pruneRatio = 150.0;
  double gateRatio = 1e5;
  Branching branching = Branching::WholeAssociation;
  double jointCompatibility = 0.999;
  int maxComponents = kDefaultMaxComponents;
  int maxCandidates = kDefaultMaxCandidates;
  double maxMemoryMiB = kDefaultMaxMemoryMiB;
  bool enumerateAllClasses = false;
  bool visibility = true;
  std::uint64_t seed = 1;
  SmootherFactory smootherFactory;  // empty: defaultSmootherFactory()

  /// Throws std::invalid_argument for samples < 2, importanceIterations < 1, non-finite ratios, jointCompatibility outside (0, 1),
  /// maxComponents < 0, maxCandidates < 1 or a maxMemoryMiB that is not a positive finite number.
  void validate() const;
};

}  // namespace semslam
