#include "semslam/slam/LoopClosureBranches.h"

#include <stdexcept>

#include "semslam/slam/BranchScore.h"

namespace semslam {

LoopClosureBranches::LoopClosureBranches(const LogHeader& header, SemanticSlamOptions options)
    : window_(options.loopClosureBranchWindow) {
  if (window_ < 0) throw std::invalid_argument("loop-closure branch window must be >= 0");
  if (window_ > 0 && (options.birth != BirthRule::Unassigned || options.strategy == AssociationStrategy::Known)) {
    throw std::invalid_argument("loop-closure branches need the unassigned birth rule and a strategy that associates "
                                "(not known)");
  }
  main_ = std::make_unique<SemanticSlam>(header, std::move(options));
}

void LoopClosureBranches::addStep(const TimeStep& step) {
  main_->beginStep(step);
  if (alternative_) {
    alternative_->addStep(step);
  } else if (window_ > 0) {
    const std::vector<std::size_t> anchoring = main_->anchoringDetections();
    if (!anchoring.empty()) {
      alternative_ = main_->fork();
      alternative_->keepApart(anchoring);
      alternative_->completeStep();
      splits_.push_back({main_->steps() - 1, 0, 0.0, 0.0, false});
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
  split.keptB = split.scoreB < split.scoreA;
  if (split.keptB) main_ = std::move(alternative_);
  alternative_.reset();
}

void LoopClosureBranches::finish() {
  if (alternative_) closeSplit();
  main_->finish();
}

}  // namespace semslam
