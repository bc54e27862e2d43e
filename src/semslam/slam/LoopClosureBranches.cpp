#include "semslam/slam/LoopClosureBranches.h"

#include <stdexcept>

#include "semslam/slam/BranchScore.h"

namespace semslam {

int LoopClosureBranches::window(const SemanticSlamOptions& options) {
  const bool applies = options.birth == BirthRule::Unassigned &&
                       (options.strategy == AssociationStrategy::MaximumLikelihood ||
                        options.strategy == AssociationStrategy::MaxMixture ||
                        options.strategy == AssociationStrategy::MaxMixtureNullHypothesis);
  if (!options.loopClosureBranchWindow) return applies ? kDefaultWindow : 0;
  const int window = *options.loopClosureBranchWindow;
  if (window < 0) throw std::invalid_argument("loop-closure branch window must be >= 0");
  if (window > 0 && !applies) {
    throw std::invalid_argument("loop-closure branches need the unassigned birth rule and the ml, mm or mm-nh "
                                "strategy (known assigns nothing; gpda's factors carry EM weights)");
  }
  return window;
}

LoopClosureBranches::LoopClosureBranches(const LogHeader& header, SemanticSlamOptions options)
    : window_(window(options)) {
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
