#pragma once
// NoiseModelFactor<ErrorDim, Variables...>: the base of every factor with a Gaussian (optionally robust) noise
// model on a fixed-size error e(x_1, ..., x_n).
//
// A concrete factor implements only
//     ErrorVector evaluateError(const V1& x1, ..., const Vn& xn, Jacobian<V1>* H1, ..., Jacobian<Vn>* Hn) const
// returning the unwhitened error e and, where a pointer is non-null, ∂e/∂δ_i (right perturbation of x_i). This
// class whitens with the noise model (r = R e, J = R H), applies the robust kernel's IRLS weight, and writes the
// result into the solver's buffers. Jacobians are fixed-size Eigen matrices, so evaluation allocates nothing.

#include <array>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "semslam/graph/Factor.h"
#include "semslam/graph/NoiseModel.h"

namespace semslam {

template <int ErrorDim, class... Variables>
class NoiseModelFactor : public Factor {
 public:
  static constexpr int kErrorDim = ErrorDim;
  static constexpr std::size_t kArity = sizeof...(Variables);
  using ErrorVector = VectorN<ErrorDim>;
  template <class V>
  using Jacobian = MatrixN<ErrorDim, Manifold<V>::kDim>;

  NoiseModelFactor(SharedNoiseModel noiseModel, const std::array<Key, kArity>& keys)
      : Factor(std::vector<Key>(keys.begin(), keys.end())), noiseModel_(std::move(noiseModel)) {
    if (!noiseModel_) throw std::invalid_argument("factor needs a noise model");
    if (noiseModel_->dimension() != ErrorDim) {
      throw std::invalid_argument("noise model has dimension " + std::to_string(noiseModel_->dimension()) +
                                  ", the factor's error has " + std::to_string(ErrorDim));
    }
  }

  /// The unwhitened error e and, where requested, its Jacobians.
  virtual ErrorVector evaluateError(const Variables&... values, Jacobian<Variables>*... jacobians) const = 0;

  int errorDimension() const override { return ErrorDim; }
  const SharedNoiseModel& noiseModel() const { return noiseModel_; }

  /// The Gaussian's log-normaliser; none under a robust kernel (the density is then not a normalised Gaussian).
  std::optional<double> logNormalizer() const override {
    if (noiseModel_->robustKernel()) return std::nullopt;
    return noiseModel_->logNormalizer();
  }

  /// e at `values` (no Jacobians), e.g. for reports.
  ErrorVector unwhitenedError(const Values& values) const {
    return evaluate(values, nullptr, std::index_sequence_for<Variables...>{});
  }

  double chi2(const Values& values) const override {
    ErrorVector r = unwhitenedError(values);
    noiseModel_->whitenInPlace(r);
    const double squared = r.squaredNorm();
    const RobustKernel* kernel = noiseModel_->robustKernel();
    return kernel ? kernel->cost(squared) : squared;
  }

  void linearize(const Values& values, LinearizedFactor& out) const override {
    std::tuple<Jacobian<Variables>...> jacobians;
    ErrorVector r = evaluate(values, &jacobians, std::index_sequence_for<Variables...>{});
    noiseModel_->whitenInPlace(r);
    double scale = 1.0;
    out.chi2 = r.squaredNorm();
    if (const RobustKernel* kernel = noiseModel_->robustKernel()) {
      scale = std::sqrt(kernel->weight(out.chi2));
      out.chi2 = kernel->cost(out.chi2);
      r *= scale;
    }
    out.whitenedError = r;
    out.jacobians.resize(kArity);
    writeJacobians(jacobians, scale, out, std::index_sequence_for<Variables...>{});
  }

 private:
  template <std::size_t... I>
  ErrorVector evaluate(const Values& values, std::tuple<Jacobian<Variables>...>* jacobians,
                       std::index_sequence<I...>) const {
    if (jacobians == nullptr) {
      return evaluateError(values.at<Variables>(keys()[I])..., static_cast<Jacobian<Variables>*>(nullptr)...);
    }
    return evaluateError(values.at<Variables>(keys()[I])..., &std::get<I>(*jacobians)...);
  }

  // GCC 12 warns (-Warray-bounds) that copying a 1×1 fixed-size Jacobian may read a 16-byte packet; Eigen
  // copies 1×1 blocks element-wise, so the warning is a false positive of its analysis.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif
  template <std::size_t... I>
  void writeJacobians(std::tuple<Jacobian<Variables>...>& jacobians, double scale, LinearizedFactor& out,
                      std::index_sequence<I...>) const {
    ((out.jacobians[I] = std::get<I>(jacobians), noiseModel_->whitenInPlace(out.jacobians[I])), ...);
    if (scale != 1.0) {
      for (Matrix& jacobian : out.jacobians) jacobian *= scale;
    }
  }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

  SharedNoiseModel noiseModel_;
};

}  // namespace semslam
