#include "semslam/io/HypothesesJsonl.h"

#include <cmath>
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

/// [x, y, θ] (2D) or [x, y, z, qx, qy, qz, qw] (3D, TUM's order).
nlohmann::json poseArray(const Pose& pose) {
  if (const SE2* x = std::get_if<SE2>(&pose)) return {x->translation().x(), x->translation().y(), x->theta()};
  const SE3& x = std::get<SE3>(pose);
  const Eigen::Quaterniond q = x.rotation().toQuaternion();
  return {x.translation().x(), x.translation().y(), x.translation().z(), q.x(), q.y(), q.z(), q.w()};
}

}  // namespace

std::string hypothesesJsonLine(const HybridStepRecord& record, const HypothesisMetrics& h) {
  const HybridMarginals& m = record.marginals;
  nlohmann::json line;
  line["step"] = m.step;
  nlohmann::json components = nlohmann::json::array();
  for (std::size_t i = 0; i < m.components.size(); ++i) {
    const HypothesisComponent& c = m.components[i];
    components.push_back({{"weight", number(c.weight)},
                          {"ancestor", m.ancestors.at(i)},
                          {"beta", c.associations.empty() ? std::vector<int>() : c.associations.back()},
                          {"classes", c.classes},
                          {"pose", poseArray(c.pose)},
                          {"covariance", matrix(c.covariance)}});
  }
  line["components"] = components;
  nlohmann::json association = nlohmann::json::array();
  for (const AssociationHypothesis& a : m.association) {
    association.push_back({{"component", a.firstComponent}, {"weight", number(a.weight)}});
  }
  line["association_marginal"] = association;
  line["class_marginal"] = m.classes.size() > 0 ? matrix(m.classes) : nlohmann::json::array();
  line["mixture"] = {{"mean", std::vector<double>(m.mixtureMean.data(), m.mixtureMean.data() + m.mixtureMean.size())},
                     {"covariance", matrix(m.mixtureCovariance)}};
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
                    {"capped_components", r.cappedComponents},
                    {"memory_capped_components", r.memoryCappedComponents},
                    {"dropped_detections", r.weights.droppedDetections},
                    {"fell_back_to_linearized", r.weights.fellBackToLinearized},
                    {"analytic_total_variation", number(r.weights.analyticTotalVariation)},
                    {"max_relative_standard_error", number(r.weights.maxRelativeStandardError)},
                    {"sampling_s", number(r.weights.samplingSeconds)},
                    {"step_s", number(r.seconds)}};
  return line.dump();
}

void writeHypothesesJsonl(const std::string& path, const SpooledText& lines) {
  writeFileAtomically(path, [&](std::ostream& out) { lines.copyTo(out); });
}

}  // namespace semslam
