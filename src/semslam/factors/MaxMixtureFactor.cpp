#include "semslam/factors/MaxMixtureFactor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace semslam {

std::vector<Key> MaxMixtureFactor::unionOfKeys(const std::vector<Component>& components) {
  std::vector<Key> keys;
  for (const Component& component : components) {
    if (!component.factor) throw std::invalid_argument("max-mixture component without a factor");
    for (Key key : component.factor->keys()) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
  }
  return keys;
}

MaxMixtureFactor::MaxMixtureFactor(std::vector<Component> components)
    : Factor(unionOfKeys(components)), components_(std::move(components)) {
  if (components_.empty()) throw std::invalid_argument("a max-mixture needs at least one component");
  std::vector<double> constants;
  for (const Component& component : components_) {
    if (!(component.weight > 0.0) || !std::isfinite(component.weight)) {
      throw std::invalid_argument("max-mixture weights must be finite and positive");
    }
    const std::optional<double> normalizer = component.factor->logNormalizer();
    if (!normalizer) throw std::invalid_argument("a max-mixture component must be a Gaussian factor (no robust kernel)");
    constants.push_back(*normalizer - std::log(component.weight));
    maxComponentDimension_ = std::max(maxComponentDimension_, component.factor->errorDimension());
    std::vector<int> slots;
    for (Key key : component.factor->keys()) {
      slots.push_back(static_cast<int>(std::find(keys().begin(), keys().end(), key) - keys().begin()));
    }
    keySlots_.push_back(std::move(slots));
  }
  for (std::size_t i = 0; i < components_.size(); ++i) checkWidening(i);
  const double minimum = *std::min_element(constants.begin(), constants.end());
  for (double c : constants) constants_.push_back(c - minimum);
}

void MaxMixtureFactor::checkWidening(std::size_t i) const {
  const Component& component = components_[i];
  if (!component.widens) return;
  const Widening& widening = *component.widens;
  if (widening.of < 0 || static_cast<std::size_t>(widening.of) >= i || components_[widening.of].widens) {
    throw std::invalid_argument("a widened max-mixture component must widen an earlier, unwidened component");
  }
  const Factor& widened = *component.factor;
  const Factor& original = *components_[widening.of].factor;
  const double expected = *original.logNormalizer() + original.errorDimension() * std::log(widening.sigmaScale);
  if (!(widening.sigmaScale >= 1.0) || widened.keys() != original.keys() ||
      widened.errorDimension() != original.errorDimension() ||
      std::abs(*widened.logNormalizer() - expected) > 1e-9 * std::max(1.0, std::abs(expected))) {
    throw std::invalid_argument("a widened max-mixture component must be its original with every standard "
                                "deviation scaled by sigmaScale >= 1");
  }
}

std::pair<int, double> MaxMixtureFactor::choose(const Values& values) const {
  constexpr std::size_t kInline = 8;  // each component's chi2, for the widenings (no allocation for small mixtures)
  std::array<double, kInline> inlineChi2;
  std::vector<double> heapChi2(components_.size() > kInline ? components_.size() : 0);
  double* chi2s = components_.size() > kInline ? heapChi2.data() : inlineChi2.data();
  int best = 0;
  double bestCost = std::numeric_limits<double>::infinity();
  double bestChi2 = 0.0;
  for (std::size_t i = 0; i < components_.size(); ++i) {
    const std::optional<Widening>& widens = components_[i].widens;
    const double chi2 = widens ? chi2s[widens->of] / (widens->sigmaScale * widens->sigmaScale)
                               : components_[i].factor->chi2(values);
    chi2s[i] = chi2;
    const double cost = chi2 + 2.0 * constants_[i];  // 2 (½‖r_i‖² + c_i − c_min)
    if (cost < bestCost) {
      best = static_cast<int>(i);
      bestCost = cost;
      bestChi2 = chi2;
    }
  }
  return {best, bestChi2};
}

int MaxMixtureFactor::activeComponent(const Values& values) const { return choose(values).first; }

double MaxMixtureFactor::chi2(const Values& values) const {
  const auto [index, chi2] = choose(values);
  return chi2 + 2.0 * constants_[index];
}

void MaxMixtureFactor::linearize(const Values& values, LinearizedFactor& out) const {
  const int index = choose(values).first;
  const Factor& chosen = *components_[index].factor;
  LinearizedFactor component;
  chosen.linearize(values, component);
  const int m = chosen.errorDimension();
  const int rows = errorDimension();
  out.whitenedError = Vector::Zero(rows);
  out.whitenedError.head(m) = component.whitenedError;
  out.whitenedError(rows - 1) = std::sqrt(2.0 * constants_[index]);
  out.chi2 = component.chi2 + 2.0 * constants_[index];
  out.jacobians.resize(keys().size());
  for (std::size_t k = 0; k < keys().size(); ++k) {
    out.jacobians[k] = Matrix::Zero(rows, dimension(values.value(keys()[k])));
  }
  for (std::size_t k = 0; k < chosen.keys().size(); ++k) {
    out.jacobians[keySlots_[index][k]].topRows(m) = component.jacobians[k];
  }
}

}  // namespace semslam
