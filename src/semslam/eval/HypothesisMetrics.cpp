#include "semslam/eval/HypothesisMetrics.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <variant>

#include "semslam/eval/ErrorStatistics.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

Vector positionOf(const Pose& pose) {
  if (const SE2* p = std::get_if<SE2>(&pose)) return p->translation();
  return std::get<SE3>(pose).translation();
}

}  // namespace

double entropy(const std::vector<double>& weights) {
  double h = 0.0;
  for (double w : normalizeWeights(weights)) {
    if (w > 0.0) h -= w * std::log(w);
  }
  return h;
}

double effectiveSampleSize(const std::vector<double>& weights) {
  double squares = 0.0;
  for (double w : normalizeWeights(weights)) squares += w * w;
  return 1.0 / squares;
}

HypothesisMetrics evaluateHypotheses(const std::vector<HypothesisComponent>& components,
                                     const std::optional<Pose>& truePose, double disambiguationThreshold) {
  const std::vector<double> weights = normalizeWeights(componentWeights(components));
  HypothesisMetrics m;
  m.components = components.size();
  m.heaviestComponent = static_cast<std::size_t>(std::max_element(weights.begin(), weights.end()) - weights.begin());

  const std::vector<AssociationHypothesis> marginal = associationMarginal(components);
  std::vector<double> historyWeights;
  for (const AssociationHypothesis& h : marginal) historyWeights.push_back(h.weight);
  m.histories = marginal.size();
  m.entropy = entropy(historyWeights);
  m.heaviestAssociationWeight = marginal.front().weight;
  m.disambiguated = m.heaviestAssociationWeight > disambiguationThreshold;
  m.ess = effectiveSampleSize(weights);

  const HypothesisComponent& heaviest = components[m.heaviestComponent];
  const int d = std::holds_alternative<SE2>(heaviest.pose) ? 2 : 3;
  if (heaviest.covariance.size() > 0) {
    if (heaviest.covariance.rows() < d || heaviest.covariance.cols() < d) {
      throw InputError("hypothesis metrics: the heaviest component's covariance is smaller than its position");
    }
    m.detCovariance = heaviest.covariance.topLeftCorner(d, d).determinant();
  }

  if (truePose) {
    const Vector truth = positionOf(*truePose);
    double average = 0.0;
    for (std::size_t i = 0; i < components.size(); ++i) {
      const Vector p = positionOf(components[i].pose);
      if (p.size() != truth.size()) throw InputError("hypothesis metrics: 2D and 3D poses mixed");
      const double error = (p - truth).norm();
      average += weights[i] * error;
      if (i == m.heaviestComponent) m.errorHeaviest = error;
    }
    m.errorWeightedAverage = average;
  }
  return m;
}

double disambiguatedFraction(const std::vector<double>& heaviestAssociationWeights, double threshold) {
  if (heaviestAssociationWeights.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::size_t count = 0;
  for (double w : heaviestAssociationWeights) {
    if (w > threshold) ++count;
  }
  return static_cast<double>(count) / static_cast<double>(heaviestAssociationWeights.size());
}

}  // namespace semslam
