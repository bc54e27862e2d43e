#include "semslam/slam/LoopClosureBranches.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "semslam/slam/BranchScore.h"

namespace semslam {

const char* LoopClosureBranches::branchName(Branch branch) {
  switch (branch) {
    case Branch::AsIs:
      return "as-is";
    case Branch::Apart:
      return "apart";
    case Branch::NextBest:
      return "next-best";
  }
  throw std::logic_error("unknown branch");
}

int LoopClosureBranches::window(const SemanticSlamOptions& options) {
  const bool applies = options.birth == BirthRule::Unassigned && !options.decideOnTrueHistory &&
                       (options.strategy == AssociationStrategy::MaximumLikelihood ||
                        options.strategy == AssociationStrategy::MaxMixture ||
                        options.strategy == AssociationStrategy::MaxMixtureNullHypothesis);
  int window = applies ? kDefaultWindow : 0;
  if (options.loopClosureBranchWindow) {
    window = *options.loopClosureBranchWindow;
    if (window < 0) throw std::invalid_argument("loop-closure branch window must be >= 0");
    if (window > 0 && !applies) {
      throw std::invalid_argument("loop-closure branches need the unassigned birth rule and the ml, mm or mm-nh "
                                  "strategy (known assigns nothing; gpda's factors carry EM weights), applying its "
                                  "own decisions (not on the true history)");
    }
  }
  if (options.loopClosureNextBest.value_or(false) && window == 0) {
    throw std::invalid_argument("the next-best branch is a third branch of a loop-closure split: it needs branches "
                                "(a window > 0, the unassigned birth rule and ml, mm or mm-nh)");
  }
  return window;
}

bool LoopClosureBranches::nextBest(const SemanticSlamOptions& options) {
  const bool branches = window(options) > 0;
  if (options.loopClosureNextBest) return *options.loopClosureNextBest;
  return branches && options.strategy == AssociationStrategy::MaxMixtureNullHypothesis;
}

int LoopClosureBranches::maximumOpenSplits(const SemanticSlamOptions& options) {
  const bool branches = window(options) > 0;
  if (!options.loopClosureOpenSplits) return branches ? kDefaultOpenSplits : 1;
  const int maximum = *options.loopClosureOpenSplits;
  if (maximum < 1) throw std::invalid_argument("loop-closure open splits must be >= 1");
  if (maximum > 1 && !branches) {
    throw std::invalid_argument("more than one open split (splits within splits) needs branches (a window > 0, the "
                                "unassigned birth rule and ml, mm or mm-nh)");
  }
  return maximum;
}

LoopClosureBranches::LoopClosureBranches(const LogHeader& header, SemanticSlamOptions options)
    : window_(window(options)),
      nextBestBranch_(nextBest(options)),
      apartKeepsMerges_(options.loopClosureApartKeepsMerges),
      maximumOpenSplits_(maximumOpenSplits(options)) {
  leaves_.push_back({std::make_unique<SemanticSlam>(header, std::move(options)), {}});
}

void LoopClosureBranches::addStep(const TimeStep& step) {
  for (std::size_t leaf = 0; leaf < leaves_.size();) leaf += 1 + advance(leaf, step);
  LeafScores scores;  // splits closing after the same step score each leaf once
  while (!open_.empty() && slam().steps() - 1 - open_.front().split.openedAt >= window_) closeOldestSplit(scores);
}

std::size_t LoopClosureBranches::advance(std::size_t leaf, const TimeStep& step) {
  SemanticSlam& run = *leaves_[leaf].run;
  run.beginStep(step);
  std::vector<Leaf> branches;  // B, then C where it opens
  if (window_ > 0 && static_cast<int>(open_.size()) < maximumOpenSplits_) {
    const std::vector<std::size_t> anchoring = run.anchoringDetections();
    if (!anchoring.empty()) {
      const double rateBeforeStep = run.unassignedHypothesis().rate();  // the branches' shared history's μ
      const int id = nextSplitId_++;
      std::vector<std::pair<int, Branch>> lineage = leaves_[leaf].lineage;
      Leaf apart{run.fork(), lineage};
      apart.lineage.emplace_back(id, Branch::Apart);
      apart.run->keepApart(anchoring);
      if (apartKeepsMerges_) apart.run->keepMergesApart();
      apart.run->completeStep();
      branches.push_back(std::move(apart));
      if (nextBestBranch_) {
        Leaf nextBest{run.fork(), lineage};
        nextBest.lineage.emplace_back(id, Branch::NextBest);
        if (nextBest.run->pairElsewhere(anchoring)) {
          nextBest.run->completeStep();
          branches.push_back(std::move(nextBest));
        }
      }
      leaves_[leaf].lineage.emplace_back(id, Branch::AsIs);
      open_.push_back({id, {run.steps() - 1, 0, 0.0, 0.0, std::nullopt, Branch::AsIs}, rateBeforeStep});
    }
  }
  run.completeStep();
  const std::size_t added = branches.size();
  leaves_.insert(leaves_.begin() + static_cast<std::ptrdiff_t>(leaf) + 1, std::make_move_iterator(branches.begin()),
                 std::make_move_iterator(branches.end()));
  return added;
}

void LoopClosureBranches::closeOldestSplit(LeafScores& scoreOf) {
  const int id = open_.front().id;
  Split split = open_.front().split;
  const double unassignedRate = open_.front().unassignedRate;
  open_.erase(open_.begin());
  split.closedAfter = slam().steps() - 1;
  // Each branch scores as its lowest-scoring leaf.
  const auto branchOf = [id](const Leaf& leaf) {
    for (const auto& [splitId, branch] : leaf.lineage) {
      if (splitId == id) return std::optional<Branch>(branch);
    }
    return std::optional<Branch>();
  };
  std::optional<double> branchScores[3];
  for (const Leaf& leaf : leaves_) {
    const std::optional<Branch> branch = branchOf(leaf);
    if (!branch) continue;
    std::optional<double>& score = branchScores[static_cast<int>(*branch)];
    const auto [cached, isNew] = scoreOf.try_emplace({leaf.run.get(), unassignedRate}, 0.0);
    if (isNew) cached->second = branchScore(*leaf.run, unassignedRate);
    const double leafScore = cached->second;
    if (!score || leafScore < *score) score = leafScore;
  }
  split.scoreA = branchScores[static_cast<int>(Branch::AsIs)].value();
  split.scoreB = branchScores[static_cast<int>(Branch::Apart)].value();
  split.scoreC = branchScores[static_cast<int>(Branch::NextBest)];
  // The lowest score; scores within the precision they are converged to (kBranchScoreTolerance) are a tie, kept
  // for the earlier branch (A before B before C): the closure as made unless a branch explains the log better
  // (§10, "The score's precision, and ties").
  double best = split.scoreA;
  if (split.scoreB < best - kBranchScoreTolerance) {
    best = split.scoreB;
    split.kept = Branch::Apart;
  }
  if (split.scoreC && *split.scoreC < best - kBranchScoreTolerance) split.kept = Branch::NextBest;
  // Drop the leaves below the other branches, and the splits open only among them.
  std::vector<Leaf> kept;
  for (Leaf& leaf : leaves_) {
    const std::optional<Branch> branch = branchOf(leaf);
    if (branch && *branch != split.kept) continue;
    std::erase_if(leaf.lineage, [id](const std::pair<int, Branch>& entry) { return entry.first == id; });
    kept.push_back(std::move(leaf));
  }
  leaves_ = std::move(kept);
  std::erase_if(open_, [this](const OpenSplit& open) {
    return std::none_of(leaves_.begin(), leaves_.end(), [&open](const Leaf& leaf) {
      return std::any_of(leaf.lineage.begin(), leaf.lineage.end(),
                         [&open](const std::pair<int, Branch>& entry) { return entry.first == open.id; });
    });
  });
  splits_.push_back(split);
}

void LoopClosureBranches::finish() {
  LeafScores scores;
  while (!open_.empty()) closeOldestSplit(scores);
  if (leaves_.size() != 1) throw std::logic_error("LoopClosureBranches: more than one branch after every split closed");
  leaves_.front().run->finish();
}

}  // namespace semslam
