#include "semslam/io/PoseGraphAnchor.h"

#include "semslam/factors/PriorFactor.h"

namespace semslam {

namespace {

FactorPtr tightPrior(Key key, const Value& value, double sigma) {
  return std::visit(
      [key, sigma](const auto& v) -> FactorPtr {
        using T = std::decay_t<decltype(v)>;
        return std::make_shared<const PriorFactor<T>>(key, v, NoiseModel::isotropic(Manifold<T>::kDim, sigma));
      },
      value);
}

}  // namespace

FactorGraph anchorFactors(const PoseGraphFile& file, double sigma) {
  FactorGraph priors;
  if (file.fixed.empty()) {
    priors.add(tightPrior(file.firstPose, file.initial.value(file.firstPose), sigma));
  } else {
    for (Key key : file.fixed) priors.add(tightPrior(key, file.initial.value(key), sigma));
  }
  return priors;
}

}  // namespace semslam
