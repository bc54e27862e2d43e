#include "semslam/slam/AssociationStrategy.h"

#include <stdexcept>

namespace semslam {

std::vector<AssociationStrategy> allStrategies() {
  return {AssociationStrategy::Known, AssociationStrategy::MaximumLikelihood, AssociationStrategy::Gpda,
          AssociationStrategy::MaxMixture, AssociationStrategy::MaxMixtureNullHypothesis};
}

std::string strategyName(AssociationStrategy strategy) {
  switch (strategy) {
    case AssociationStrategy::Known: return "known";
    case AssociationStrategy::MaximumLikelihood: return "ml";
    case AssociationStrategy::Gpda: return "gpda";
    case AssociationStrategy::MaxMixture: return "mm";
    case AssociationStrategy::MaxMixtureNullHypothesis: return "mm-nh";
  }
  return "?";
}

AssociationStrategy parseStrategy(std::string_view name) {
  for (AssociationStrategy strategy : allStrategies()) {
    if (strategyName(strategy) == name) return strategy;
  }
  throw std::invalid_argument("unknown method '" + std::string(name) + "' (known, ml, gpda, mm, mm-nh)");
}

}  // namespace semslam
