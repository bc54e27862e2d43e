#pragma once
// LoopClosureBranches: a SemanticSlam run that keeps a second branch open where a step closes a loop on an
// uncertain estimate (docs/association-front-end.md §10).
//
// A loop closure is decided by the step that makes it, yet the detection that would show it wrong (the true
// landmark's own re-sighting, when the closure took a look-alike) often comes a few steps later. So where the
// joint assignment of step k holds an anchoring pairing (SemanticSlam::anchoringDetections: I = ½ ln det(S R⁻¹)
// above SemanticSlamOptions::anchoringInformation), the run splits:
//   branch A  the step as the front end decided it;
//   branch B  a fork of the run taken between the halves of step k (SemanticSlam::beginStep / completeStep), in
//             which the anchoring detections start provisional landmarks, never merged with the landmarks they
//             were paired with (SemanticSlam::keepApart).
//   branch C  (SemanticSlamOptions::loopClosureNextBest; on by default for mm-nh, nextBest()) a fork in which the
//             anchoring detections may not take the landmarks they were paired with, so they take their next-best
//             ones (SemanticSlam::pairElsewhere): the other look-alike; opened only where some detection then has
//             one.
// All take steps k+1 … k+W (W = SemanticSlamOptions::loopClosureBranchWindow); then the branch with the lowest
// BranchScore (−2 ln of its evidence, BranchScore.h) is kept and the others dropped; a split still open at the end
// of the log is closed by finish(). At most one split is open at a time: an anchoring step during an open split is
// decided by each branch's front end, as without branches. So a run costs at most twice a single run over the
// steps a split is open (three times with branch C), and a run with no anchoring step (or W = 0) is step for step
// the single run.
//
// Where branches apply: a joint assignment whose pairings can anchor (BirthRule::Unassigned; not `known`) and
// factors that are the data's likelihood under one association, which BranchScore integrates: ml's single
// factors and mm / mm-nh's max-mixtures. gpda's factors are scaled by its EM weights (Bowman et al.), so two gpda
// branches have no comparable evidence. There the window defaults to kDefaultWindow; elsewhere to none, and an
// explicit window is refused.
//
// Invariants: main_ is branch A while a split is open and the kept branch otherwise; alternative_ is branch B
// exactly while a split is open, nextBest_ branch C while a split that opened it is open; all have processed the
// same steps whenever no step is begun.

#include <memory>
#include <optional>
#include <vector>

#include "semslam/slam/SemanticSlam.h"

namespace semslam {

class LoopClosureBranches {
 public:
  /// The branches of a split (the class comment's A, B and C).
  enum class Branch { AsIs, Apart, NextBest };
  /// "as-is", "apart" or "next-best" (branches.csv, io/RunFolder.h).
  static const char* branchName(Branch branch);

  /// One split: the step that opened it, the step after which it closed, the branches' scores then, and which was
  /// kept.
  struct Split {
    int openedAt = 0;
    int closedAfter = 0;
    double scoreA = 0.0;
    double scoreB = 0.0;
    std::optional<double> scoreC;  ///< branch C's, where it was opened
    Branch kept = Branch::AsIs;
  };

  /// The window where branches apply and SemanticSlamOptions::loopClosureBranchWindow is unset: the middle of the
  /// stable range of the sweep over KITTI 00 and 07 simulations, MRCLAM, KITTI tracking and Lost in the Woods
  /// (docs/association-front-end.md §10: 16 and 32 equal on the simulations, 8 short of them; 16 costs half of 32).
  static constexpr int kDefaultWindow = 16;

  /// The window `options` ask for: loopClosureBranchWindow if set, else kDefaultWindow where branches apply and 0
  /// elsewhere. Throws std::invalid_argument for a negative window, a positive one where branches do not apply, or
  /// loopClosureNextBest set to true without branches.
  static int window(const SemanticSlamOptions& options);

  /// Whether splits open branch C: loopClosureNextBest if set, else on for mm-nh wherever window() > 0 and off
  /// elsewhere (docs/association-front-end.md §10: mm-nh gains on MRCLAM and the KITTI 00 simulation, ml loses on
  /// MRCLAM; equal on the other logs). Throws as window() does.
  static bool nextBest(const SemanticSlamOptions& options);

  /// Throws as window() does.
  LoopClosureBranches(const LogHeader& header, SemanticSlamOptions options);

  /// Processes the next step in every open branch, splitting or closing as above.
  void addStep(const TimeStep& step);
  /// Closes an open split, then ends the kept run (SemanticSlam::finish). Call once, after the last step.
  void finish();

  /// The kept run (while a split is open: branch A).
  const SemanticSlam& slam() const { return *main_; }
  /// Every split so far, in order.
  const std::vector<Split>& splits() const { return splits_; }

 private:
  void closeSplit();

  int window_;
  bool nextBestBranch_;
  std::unique_ptr<SemanticSlam> main_;
  std::unique_ptr<SemanticSlam> alternative_;
  std::unique_ptr<SemanticSlam> nextBest_;
  std::vector<Split> splits_;
};

}  // namespace semslam
