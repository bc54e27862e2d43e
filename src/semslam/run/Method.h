#pragma once
// Method: the estimation methods a run can use, by the names of the command line and of metrics.json.
//
//   known | ml | gpda | mm | mm-nh   paper B's five association strategies on one front end (slam/SemanticSlam.h)
//   hybrid | hybrid-geometric        paper A's hybrid belief with and without the viewpoint-dependent classifier
//                                    model (hybrid/HybridBelief.h)

#include <string>
#include <string_view>
#include <vector>

#include "semslam/slam/AssociationStrategy.h"

namespace semslam {

enum class Method { Known, MaximumLikelihood, Gpda, MaxMixture, MaxMixtureNullHypothesis, Hybrid, HybridGeometric };

/// "known", "ml", "gpda", "mm", "mm-nh", "hybrid", "hybrid-geometric".
std::string methodName(Method method);
/// The inverse of methodName; anything else throws std::invalid_argument listing the names.
Method parseMethod(std::string_view name);
/// Every method, in the order above.
std::vector<Method> allMethods();
/// Every method's name, in the order above (for option checks and help texts).
std::vector<std::string> methodNames();

/// Paper A's two methods.
bool isHybrid(Method method);
/// Paper B's strategy of a non-hybrid method (std::invalid_argument for a hybrid one).
AssociationStrategy associationStrategy(Method method);
/// The method that runs paper B's `strategy`.
Method methodFor(AssociationStrategy strategy);

}  // namespace semslam
