#pragma once
// BranchScore: how well one branch of a run explains the log so far (docs/association-front-end.md §10), as −2 ln
// of its evidence: the probability of every detection and odometry reading under the branch's associations, the
// poses and landmarks integrated out (Laplace's approximation at the branch's converged estimate X̂):
//
//   score = Σ_f [chi2_f(X̂) + 2 n_f] + ln det Λ(X̂) − N ln 2π       the model's factors (solve/LaplaceEvidence.h)
//         − 2 L ln ρ                                                L active landmarks, each with the birth density
//                                                                   ρ as its prior (UnassignedHypothesis::
//                                                                   logLandmarkDensity)
//         − 2 Σ_l ln Σ_c (1/M) Π_{r on l} P(s_r | c)                 each active landmark's labels, one class drawn
//                                                                   from the uniform prior
//         − 2 Σ_{r on no landmark} ln P₀(s_r)                       P₀ = Σ_c P(s | c) / M
//         − 2 Σ_{r on no factor} ln λ(z_r)                          a detection no factor holds (a dropped
//                                                                   provisional landmark's, clutter of `known`)
//                                                                   from the unassigned density (UnassignedHypothesis)
//
// The model's factors are those in force with two substitutions. A max-mixture counts as its component active at
// X̂, without its weight: the front end's candidate weights are posteriors of the association, not part of the
// likelihood of the data given it. The weak priors (SemanticSlam::weakPriors) are left out: they stand in for ρ,
// which is counted for every active landmark instead (their normaliser, σ the sensor's range, would otherwise
// outweigh the evidence between two branches: §10); a dropped or merged-away landmark's variable then touches no
// factor and leaves the integral. A detection that no factor holds is still data the branch must explain: §1's
// model gives it the unassigned density λ(z) (per m·rad for range-bearing). Left out, it would count as a density
// of 1 in whatever units the measurement has, so the score would depend on the units, and a branch would gain
// 2 ln(1/λ) per detection it leaves on no factor (about 5 on MRCLAM, whose λ is about 0.07 per m·rad at 3 m).
//
// A lower score is a better branch. For two branches that differ only in whether detections of one object are on
// one landmark or two, the difference is §5's merge test at X̂: −2 ln(N(p_P − p_L; 0, Σ_d) · class agreement / ρ)
// (tests/slam/testBranchScore.cpp checks the geometric part in closed form).

#include "semslam/slam/SemanticSlam.h"

namespace semslam {

/// The precision of a score, in units of −2 ln: X̂ is Gauss-Newton's from the run's estimate, stopped once a step
/// lowers chi2 by less than this (Optimizer.h, rule 2 in absolute terms); near the optimum Gauss-Newton converges
/// quadratically, so the score is then within far less than this of its value at the exact optimum. Two scores
/// closer than this are a tie (LoopClosureBranches keeps the earlier branch). The score's decisive gaps are units to
/// hundreds (docs/association-front-end.md §10, "The score's precision, and ties").
inline constexpr double kBranchScoreTolerance = 1e-3;

/// The score above of `run` at its estimate converged to kBranchScoreTolerance (the run is unchanged), with ρ and λ
/// at the run's own μ (UnassignedHypothesis::rate).
double branchScore(const SemanticSlam& run);
/// The same with ρ and λ at μ = `unassignedRate`: the branches of one split, whose runs estimate μ each from their
/// own decisions where μ is estimated, are compared at one rate, the one of the history they share
/// (LoopClosureBranches; docs/association-front-end.md §10, "μ from the run"). Throws std::invalid_argument for a
/// rate that is not positive and finite.
double branchScore(const SemanticSlam& run, double unassignedRate);

}  // namespace semslam
