#pragma once
// TabulatedViewpointClassifier: a viewpoint-dependent Gaussian classifier model (A, eq. 2) given by samples of
// h_c(θ) and Σ_c(θ) over the viewpoint circle, e.g. learned offline from images of objects seen from many
// viewpoints, or tabulated from another model. It stands in wherever the analytic model of eq. 18 is used.
//
// Math
//   Each class c has its own sample angles θ_0 < θ_1 < ... < θ_{N−1} in [−π, π) with means m_i ∈ R^d and
//   covariances S_i (d x d, symmetric positive definite). Between samples the model interpolates linearly and
//   periodically: θ is wrapped to [−π, π); the segment after θ_{N−1} runs to θ_0 + 2π (and the one before θ_0
//   from θ_{N−1} − 2π). On a segment [θ_l, θ_r] with λ = (θ − θ_l)/(θ_r − θ_l):
//       h_c(θ) = (1 − λ) m_l + λ m_r,   dh_c/dθ = (m_r − m_l)/(θ_r − θ_l),   Σ_c(θ) = (1 − λ) S_l + λ S_r
//   (a convex combination of positive definite matrices is positive definite). dh/dθ is piecewise constant; at a
//   sample angle it is the slope of the segment that starts there. One sample gives a constant model.
//
// File format (JSON; docs/models.md)
//   { "format": "semslam-viewpoint-classifier", "version": 1, "dimension": d,
//     "classes": [ { "theta": [θ_0, ...], "mean": [[...d numbers], ...], "covariance": [[[d x d rows]], ...] },
//                  ... one object per class, class c at index c ] }
//   Every problem (not JSON, a missing or mistyped key, wrong lengths, a non-finite number, θ not strictly
//   increasing or outside [−π, π), a covariance that is not symmetric positive definite) throws semslam::InputError
//   naming the file and the offending entry (e.g. "classes[1].covariance[7]").
//
// Invariants: at least one class, d ≥ 1, every class has N ≥ 1 samples satisfying the above. The in-memory
// constructor checks the same and throws std::invalid_argument.

#include <filesystem>
#include <string>
#include <vector>

#include "semslam/models/ViewpointClassifierModel.h"

namespace semslam {

/// The samples of one class.
struct ViewpointTable {
  std::vector<double> theta;      // strictly increasing, in [−π, π)
  std::vector<Vector> mean;       // h_c(θ_i), each of length d
  std::vector<Matrix> covariance;  // Σ_c(θ_i), each d x d symmetric positive definite
};

class TabulatedViewpointClassifier final : public ViewpointClassifierModel {
 public:
  /// From in-memory tables, one per class (class c = tables[c]).
  explicit TabulatedViewpointClassifier(std::vector<ViewpointTable> tables);

  /// Reads a table file (format above).
  static TabulatedViewpointClassifier load(const std::filesystem::path& file);
  /// Parses a table from JSON text; `source` names it in error messages (a file name).
  static TabulatedViewpointClassifier fromJson(const std::string& text, const std::string& source);
  /// Samples `model` at θ_i = −π + 2π i / samples, i = 0 .. samples − 1, for every class.
  static TabulatedViewpointClassifier tabulate(const ViewpointClassifierModel& model, int samples);

  /// The table as JSON text in the file format above (numbers round-trip exactly).
  std::string toJson() const;
  const std::vector<ViewpointTable>& tables() const { return tables_; }

  int classes() const override { return static_cast<int>(tables_.size()); }
  int dimension() const override { return dimension_; }
  Vector mean(int classIndex, double theta, Vector* dMeanDTheta = nullptr) const override;
  Matrix covariance(int classIndex, double theta) const override;

 private:
  struct Segment {
    int left, right;
    double lambda, width;
  };
  Segment locate(int classIndex, double theta) const;

  std::vector<ViewpointTable> tables_;
  int dimension_ = 0;
};

}  // namespace semslam
