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

std::pair<int, double> MaxMixtureFactor::choose(const Values& values, double* chi2sOut) const {
  std::array<double, kInlineComponents> inlineChi2;  // each component's chi2, for the widenings
  std::vector<double> heapChi2(components_.size() > kInlineComponents && !chi2sOut ? components_.size() : 0);
  double* chi2s = chi2sOut ? chi2sOut : components_.size() > kInlineComponents ? heapChi2.data() : inlineChi2.data();
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

MaxMixtureFactor::Choice MaxMixtureFactor::chooseAt(const Values& values) const {
  std::array<double, kInlineComponents> inlineChi2;
  std::vector<double> heapChi2(components_.size() > kInlineComponents ? components_.size() : 0);
  double* chi2s = components_.size() > kInlineComponents ? heapChi2.data() : inlineChi2.data();
  Choice choice;
  choice.component = choose(values, chi2s).first;
  if (keys().size() != 2) return choice;  // components on several landmarks: each would move its own way
  const auto certified = [&](double epsilon) { return certifiedWithin(values, chi2s, choice.component, epsilon); };
  // The reach: from a millimetre, ×4 up while certified, or else ÷4 down to the first certified ε (none at a
  // nanometre: no reach); then four bisections between the last certified ε and the first not. Certification is
  // monotone in ε (every bound grows with it), so the bracket holds the largest certified ε.
  double good = 0.0;
  double bad = 0.0;
  if (certified(1e-3)) {
    good = 1e-3;
    for (bad = 4e-3; certified(bad) && bad < 1e9; bad *= 4.0) good = bad;
  } else {
    if (!certified(1e-9)) return choice;  // at a switch, or a component without a bound
    for (bad = 1e-3, good = 2.5e-4; !certified(good); good /= 4.0) bad = good;
  }
  for (int i = 0; i < 4; ++i) {
    const double middle = 0.5 * (good + bad);
    (certified(middle) ? good : bad) = middle;
  }
  choice.reach = good;
  return choice;
}

bool MaxMixtureFactor::certifiedWithin(const Values& values, const double* chi2s, int chosen, double epsilon) const {
  const std::size_t n = components_.size();
  std::array<double, kInlineComponents> inlineBounds;
  std::vector<double> heapBounds(n > kInlineComponents ? n : 0);
  double* bounds = n > kInlineComponents ? heapBounds.data() : inlineBounds.data();
  for (std::size_t i = 0; i < n; ++i) {  // δ_i; a widening's from its original, which comes earlier
    const std::optional<Widening>& widens = components_[i].widens;
    if (widens) {
      bounds[i] = bounds[widens->of] / widens->sigmaScale;
      continue;
    }
    const std::optional<double> bound = components_[i].factor->whitenedErrorBoundForSeenMove(values, chi2s[i], epsilon);
    if (!bound) return false;
    bounds[i] = *bound;
  }
  const auto cost = [&](std::size_t i, double sign) {  // the largest (+1) or smallest (−1) cost of component i
    const double norm = std::max(0.0, std::sqrt(chi2s[i]) + sign * bounds[i]);
    return norm * norm + 2.0 * constants_[i];
  };
  const std::size_t best = static_cast<std::size_t>(chosen);
  const double largest = cost(best, +1.0);
  const double margin = 1e-9 * (1.0 + largest);
  for (std::size_t i = 0; i < n; ++i) {
    if (i != best && !(largest + margin < cost(i, -1.0))) return false;
  }
  return true;
}

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
