#include "semslam/run/Method.h"

#include <stdexcept>

namespace semslam {

std::vector<Method> allMethods() {
  return {Method::Known,      Method::MaximumLikelihood,        Method::Gpda,  Method::MaxMixture,
          Method::MaxMixtureNullHypothesis, Method::Hybrid, Method::HybridGeometric};
}

bool isHybrid(Method method) { return method == Method::Hybrid || method == Method::HybridGeometric; }

AssociationStrategy associationStrategy(Method method) {
  switch (method) {
    case Method::Known: return AssociationStrategy::Known;
    case Method::MaximumLikelihood: return AssociationStrategy::MaximumLikelihood;
    case Method::Gpda: return AssociationStrategy::Gpda;
    case Method::MaxMixture: return AssociationStrategy::MaxMixture;
    case Method::MaxMixtureNullHypothesis: return AssociationStrategy::MaxMixtureNullHypothesis;
    case Method::Hybrid:
    case Method::HybridGeometric: break;
  }
  throw std::invalid_argument("method " + methodName(method) + " is paper A's hybrid belief, not an association strategy");
}

Method methodFor(AssociationStrategy strategy) {
  switch (strategy) {
    case AssociationStrategy::Known: return Method::Known;
    case AssociationStrategy::MaximumLikelihood: return Method::MaximumLikelihood;
    case AssociationStrategy::Gpda: return Method::Gpda;
    case AssociationStrategy::MaxMixture: return Method::MaxMixture;
    case AssociationStrategy::MaxMixtureNullHypothesis: return Method::MaxMixtureNullHypothesis;
  }
  throw std::invalid_argument("unknown association strategy");
}

std::string methodName(Method method) {
  switch (method) {
    case Method::Hybrid: return "hybrid";
    case Method::HybridGeometric: return "hybrid-geometric";
    default: return strategyName(associationStrategy(method));
  }
}

std::vector<std::string> methodNames() {
  std::vector<std::string> names;
  for (Method method : allMethods()) names.push_back(methodName(method));
  return names;
}

Method parseMethod(std::string_view name) {
  for (Method method : allMethods()) {
    if (methodName(method) == name) return method;
  }
  std::string known;
  for (const std::string& n : methodNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown method \"" + std::string(name) + "\" (known: " + known + ")");
}

}  // namespace semslam
