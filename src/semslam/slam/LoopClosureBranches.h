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
//             were paired with (SemanticSlam::keepApart), and no provisional landmark closes the loop by a merge at
//             step k either (SemanticSlam::keepMergesApart; SemanticSlamOptions::loopClosureApartKeepsMerges): the
//             step without its closures (a confirmed duplicate's merge, §5c, is not refused).
//   branch C  (SemanticSlamOptions::loopClosureNextBest; on by default for mm-nh, nextBest()) a fork in which the
//             anchoring detections may not take the landmarks they were paired with, so they take their next-best
//             ones (SemanticSlam::pairElsewhere): the other look-alike; opened only where some detection then has
//             one.
// All take steps k+1 … k+W (W = SemanticSlamOptions::loopClosureBranchWindow); then the branch with the lowest
// BranchScore (−2 ln of its evidence, BranchScore.h) is kept and the others dropped, scores within
// kBranchScoreTolerance (the precision they are converged to) being a tie kept for the earlier branch, A before B
// before C; a split still open at the end of the log is closed by finish().
//
// Splits within splits (SemanticSlamOptions::loopClosureOpenSplits, S; kDefaultOpenSplits where branches apply). The
// open branches are the leaves of a tree: each leaf is a run with its lineage, the branch it took at every open split
// above it. At most S splits are open at a time, a budget shared by the whole tree: the leaves take each step in
// pre-order, and while fewer than S splits are open a leaf whose step anchors splits as above (where several leaves
// anchor at one step, the first in pre-order, the one nearest the closures as the front end made them, takes the last
// free split); once S are open, an anchoring step is decided by each leaf's front end, as without branches. A split
// closes W steps after it opened: each of its branches scores as the lowest-scoring leaf below it, the lowest is kept,
// the leaves below the others are dropped with the splits open among them. A run costs at most 1 + S (1 + 2S with
// branch C) times a single run over the steps splits are open; with S = 1, twice (three times). A run with no anchoring
// step (or W = 0) is step for step the single run. (A budget per branch instead, each leaf under at most S open splits,
// was measured too: the same gain for more cost, docs/association-front-end.md §10.)
//
// Where branches apply: a joint assignment whose pairings can anchor (BirthRule::Unassigned; not `known`) and
// factors that are the data's likelihood under one association, which BranchScore integrates: ml's single
// factors and mm / mm-nh's max-mixtures. gpda's factors are scaled by its EM weights (Bowman et al.), so two gpda
// branches have no comparable evidence. There the window defaults to kDefaultWindow; elsewhere to none, and an
// explicit window is refused.
//
// Invariants: leaves_ is never empty and in the tree's pre-order (a split's branches follow the leaf it split
// from), so leaves_.front() took branch A at every open split above it (the kept run when none is open); open_
// holds the at most S open splits in order of opening (which is the order they close in), each named in the
// lineage of at least one leaf; all leaves have processed the same steps whenever no step is begun.

#include <map>
#include <memory>
#include <optional>
#include <utility>
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

  /// Splits open at a time where branches apply and SemanticSlamOptions::loopClosureOpenSplits is unset: a
  /// branch of an open split may split once more (docs/association-front-end.md §10: KITTI 00 simulations within
  /// 2 × known association 6 → 7 of 8 for mm-nh and 4 → 6 of 8 for ml, the real logs even; 1.1-1.3 × the time on
  /// MRCLAM and the KITTI simulations, 2.2 × on Starry Night, where a split is open most of the time).
  static constexpr int kDefaultOpenSplits = 2;

  /// The splits open at a time that `options` ask for: loopClosureOpenSplits if set, else kDefaultOpenSplits where
  /// window() > 0 and 1 elsewhere. Throws std::invalid_argument for a value below 1 or above 1 without branches,
  /// and as window() does.
  static int maximumOpenSplits(const SemanticSlamOptions& options);

  /// Throws as window() and maximumOpenSplits() do.
  LoopClosureBranches(const LogHeader& header, SemanticSlamOptions options);

  /// Processes the next step in every open branch, splitting or closing as above.
  void addStep(const TimeStep& step);
  /// Closes an open split, then ends the kept run (SemanticSlam::finish). Call once, after the last step.
  void finish();

  /// The kept run (while splits are open: the leaf that took branch A at each).
  const SemanticSlam& slam() const { return *leaves_.front().run; }
  /// Every closed split of the kept run's lineage, in order of opening (a split dropped with its branch is not
  /// listed).
  const std::vector<Split>& splits() const { return splits_; }
  /// The open branches (leaves of the tree of open splits); 1 when none is open.
  std::size_t openBranches() const { return leaves_.size(); }

 private:
  /// One open branch: its run and, for each open split above it, that split's id and the branch it took there.
  struct Leaf {
    std::unique_ptr<SemanticSlam> run;
    std::vector<std::pair<int, Branch>> lineage;
  };
  struct OpenSplit {
    int id = 0;
    Split split;
    double unassignedRate = 0.0;  ///< μ of the run that split, before the step: its branches are scored at it
  };
  /// Begins the step in `leaf`, splits it where its step anchors and a split may open, completes it in every
  /// branch. New leaves are inserted after it; returns how many.
  std::size_t advance(std::size_t leaf, const TimeStep& step);
  /// Each leaf's BranchScore at one μ, computed once for all the splits that close after one step at that μ (the
  /// leaves do not move between them; μ differs between splits only where it is estimated from the run).
  using LeafScores = std::map<std::pair<const SemanticSlam*, double>, double>;
  /// Closes the oldest open split: scores its branches by their leaves (through `scoreOf`), keeps the lowest.
  void closeOldestSplit(LeafScores& scoreOf);

  int window_;
  bool nextBestBranch_;
  bool apartKeepsMerges_;  // SemanticSlamOptions::loopClosureApartKeepsMerges
  int maximumOpenSplits_;
  int nextSplitId_ = 0;
  std::vector<Leaf> leaves_;
  std::vector<OpenSplit> open_;
  std::vector<Split> splits_;
};

}  // namespace semslam
