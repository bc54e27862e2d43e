#include "semslam/solve/LaplaceEvidence.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "semslam/solve/NormalEquations.h"
#include "semslam/solve/SparseCholesky.h"

namespace semslam {

double laplaceEvidenceScore(const FactorGraph& graph, const Values& mode) {
  double normalizers = 0.0;
  for (const FactorPtr& factor : graph) {
    const std::optional<double> logNormalizer = factor->logNormalizer();
    if (!logNormalizer) {
      throw std::invalid_argument("laplaceEvidenceScore: a factor is not a normalised Gaussian density");
    }
    normalizers += *logNormalizer;
  }
  NormalEquations system(graph, mode);
  const double chi2 = system.assemble(mode);
  SparseCholesky cholesky;
  if (!cholesky.factorize(system.hessian())) {
    throw std::domain_error("laplaceEvidenceScore: the information matrix is not positive definite (a variable the "
                            "factors do not determine)");
  }
  return chi2 + 2.0 * normalizers + cholesky.logDeterminant() -
         system.dimension() * std::log(2.0 * std::numbers::pi);
}

}  // namespace semslam
