#include "semslam/slam/LoopClosureBranches.h"

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
  const bool applies = options.birth == BirthRule::Unassigned &&
                       (options.strategy == AssociationStrategy::MaximumLikelihood ||
                        options.strategy == AssociationStrategy::MaxMixture ||
                        options.strategy == AssociationStrategy::MaxMixtureNullHypothesis);
  int window = applies ? kDefaultWindow : 0;
  if (options.loopClosureBranchWindow) {
    window = *options.loopClosureBranchWindow;
    if (window < 0) throw std::invalid_argument("loop-closure branch window must be >= 0");
    if (window > 0 && !applies) {
      throw std::invalid_argument("loop-closure branches need the unassigned birth rule and the ml, mm or mm-nh "
                                  "strategy (known assigns nothing; gpda's factors carry EM weights)");
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

LoopClosureBranches::LoopClosureBranches(const LogHeader& header, SemanticSlamOptions options)
    : window_(window(options)), nextBestBranch_(nextBest(options)) {
  main_ = std::make_unique<SemanticSlam>(header, std::move(options));
}

void LoopClosureBranches::addStep(const TimeStep& step) {
  main_->beginStep(step);
  if (alternative_) {
    alternative_->addStep(step);
    if (nextBest_) nextBest_->addStep(step);
  } else if (window_ > 0) {
    const std::vector<std::size_t> anchoring = main_->anchoringDetections();
    if (!anchoring.empty()) {
      if (nextBestBranch_) {
        nextBest_ = main_->fork();
        if (nextBest_->pairElsewhere(anchoring)) {
          nextBest_->completeStep();
        } else {
          nextBest_.reset();
        }
      }
      alternative_ = main_->fork();
      alternative_->keepApart(anchoring);
      alternative_->completeStep();
      splits_.push_back({main_->steps() - 1, 0, 0.0, 0.0, std::nullopt, Branch::AsIs});
    }
  }
  main_->completeStep();
  if (alternative_ && main_->steps() - 1 - splits_.back().openedAt >= window_) closeSplit();
}

void LoopClosureBranches::closeSplit() {
  Split& split = splits_.back();
  split.closedAfter = main_->steps() - 1;
  split.scoreA = branchScore(*main_);
  split.scoreB = branchScore(*alternative_);
  if (nextBest_) split.scoreC = branchScore(*nextBest_);
  // The lowest score; on a tie the earlier branch (A before B before C).
  double best = split.scoreA;
  if (split.scoreB < best) {
    best = split.scoreB;
    split.kept = Branch::Apart;
    main_ = std::move(alternative_);
  }
  if (split.scoreC && *split.scoreC < best) {
    split.kept = Branch::NextBest;
    main_ = std::move(nextBest_);
  }
  alternative_.reset();
  nextBest_.reset();
}

void LoopClosureBranches::finish() {
  if (alternative_) closeSplit();
  main_->finish();
}

}  // namespace semslam
