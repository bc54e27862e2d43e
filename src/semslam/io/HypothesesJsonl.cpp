#include "semslam/io/HypothesesJsonl.h"

#include <cmath>
#include <stdexcept>
#include <nlohmann/json.hpp>

#include "semslam/io/AtomicFile.h"

namespace semslam {
namespace {

nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

nlohmann::json matrix(const Matrix& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(number(m(i, j)));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

std::string hypothesesJsonLine(const HybridStepRecord& record, const HypothesisMetrics& h) {
  const HybridMarginals& m = record.marginals;
  nlohmann::json line;
  line["step"] = m.step;
  nlohmann::json components = nlohmann::json::array();
  for (const HypothesisComponent& c : m.components) {
    const SE2& x = std::get<SE2>(c.pose);
    components.push_back({{"weight", number(c.weight)},
                          {"associations", c.associations},
                          {"classes", c.classes},
                          {"pose", {x.translation().x(), x.translation().y(), x.theta()}},
                          {"covariance", matrix(c.covariance)}});
  }
  line["components"] = components;
  nlohmann::json association = nlohmann::json::array();
  for (const AssociationHypothesis& a : m.association) {
    association.push_back({{"associations", a.associations}, {"weight", number(a.weight)}});
  }
  line["association_marginal"] = association;
  line["class_marginal"] = m.classes.size() > 0 ? matrix(m.classes) : nlohmann::json::array();
  line["mixture"] = {{"mean", {m.mixtureMean.x(), m.mixtureMean.y()}}, {"covariance", matrix(m.mixtureCovariance)}};
  line["metrics"] = {{"entropy", number(h.entropy)},       {"det_cov", number(h.detCovariance)},
                     {"err_wmax", number(h.errorHeaviest)}, {"err_wavg", number(h.errorWeightedAverage)},
                     {"ess", number(h.ess)},               {"assoc_weight_max", number(h.heaviestAssociationWeight)},
                     {"components", h.components},         {"histories", h.histories}};
  const HybridStepReport& r = record.report;
  line["report"] = {{"parents", r.parents},
                    {"candidates", r.weights.candidates},
                    {"gated", r.weights.gated},
                    {"sampled", r.weights.sampled},
                    {"gate_lost_mass", number(r.weights.gateLostMass)},
                    {"pruned_mass", number(r.prunedMass)},
                    {"survivors", r.survivors},
                    {"dropped_detections", r.weights.droppedDetections},
                    {"fell_back_to_linearized", r.weights.fellBackToLinearized},
                    {"analytic_total_variation", number(r.weights.analyticTotalVariation)},
                    {"max_relative_standard_error", number(r.weights.maxRelativeStandardError)},
                    {"sampling_s", number(r.weights.samplingSeconds)},
                    {"step_s", number(r.seconds)}};
  return line.dump();
}

void writeHypothesesJsonl(const std::string& path, const std::vector<HybridStepRecord>& steps,
                          const std::vector<HypothesisMetrics>& metrics) {
  if (metrics.size() != steps.size()) throw std::invalid_argument("hypotheses.jsonl: one metrics record per step");
  std::string text;
  for (std::size_t k = 0; k < steps.size(); ++k) text += hypothesesJsonLine(steps[k], metrics[k]) + "\n";
  writeFileAtomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace semslam
