// The standard pose graphs, solved to their optima under the log-map error convention with the first pose held
// by a prior of σ = 1e-6 (values that two independent solvers agree on to 9 digits).

#include <gtest/gtest.h>

#include "semslam/io/PoseGraphAnchor.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/solve/Marginals.h"
#include "semslam/solve/NormalEquations.h"
#include "semslam/solve/Optimizer.h"
#include "support/TestData.h"

using namespace semslam;

namespace {

struct Dataset {
  const char* path;
  double optimalChi2;
};

const Dataset kDatasets[] = {
    {"vertigo/manhattan/originalDataset/g2o/manhattanOlson3500.g2o", 146.07873},
    {"vertigo/intel/originalDataset/intel.g2o", 546.46312},
    {"vertigo/ring/originalDataset/ring.g2o", 11.163101},
    {"vertigo/sphere2500/originalDataset/sphere2500.g2o", 1351.4019},
};

void PrintTo(const Dataset& dataset, std::ostream* os) { *os << dataset.path; }

class PoseGraphOptimum : public ::testing::TestWithParam<std::tuple<Dataset, SolverType>> {};

}  // namespace

TEST_P(PoseGraphOptimum, ReachesTheKnownOptimumAtAStationaryPoint) {
  const auto [dataset, solver] = GetParam();
  SEMSLAM_REQUIRE_DATA(path, dataset.path);
  const PoseGraphFile file = readPoseGraph(path.string(), GraphFormat::G2o);
  FactorGraph graph = file.factors;
  graph.add(anchorFactors(file));
  OptimizerParams params;
  params.solver = solver;
  const OptimizationResult result = optimize(graph, file.initial, params);
  EXPECT_TRUE(result.converged) << result.stopReason;

  // chi2 over the file's own edges, to the 8 significant digits the optimum is quoted with.
  const double chi2 = file.factors.chi2(result.values);
  EXPECT_NEAR(chi2, dataset.optimalChi2, 1e-6 * dataset.optimalChi2);

  // A true stationary point of the exact objective: the gradient (exact Jacobians) is below 1e-6 of its
  // initial value, in the 2-norm.
  NormalEquations system(graph, file.initial);
  system.assemble(file.initial);
  const double initialGradient = system.gradient().norm();
  system.assemble(result.values);
  EXPECT_LE(system.gradient().norm(), 1e-6 * initialGradient);
}

INSTANTIATE_TEST_SUITE_P(
    Datasets, PoseGraphOptimum,
    ::testing::Combine(::testing::ValuesIn(kDatasets),
                       ::testing::Values(SolverType::GaussNewton, SolverType::LevenbergMarquardt)),
    [](const auto& info) {
      std::string name = std::get<0>(info.param).path;
      name = name.substr(name.find_last_of('/') + 1);
      name = name.substr(0, name.find('.'));
      return name + (std::get<1>(info.param) == SolverType::GaussNewton ? "_gn" : "_lm");
    });

TEST(PoseGraphMarginals, ManhattanLastPose) {
  SEMSLAM_REQUIRE_DATA(path, "vertigo/manhattan/originalDataset/g2o/manhattanOlson3500.g2o");
  const PoseGraphFile file = readPoseGraph(path.string(), GraphFormat::G2o);
  FactorGraph graph = file.factors;
  graph.add(anchorFactors(file));
  const OptimizationResult result = optimize(graph, file.initial);
  const Matrix covariance = Marginals(graph, result.values).marginalCovariance(3499);
  const Vector3 expected(82.0644, 185.3390, 0.432252);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(covariance(i, i), expected(i), 1e-4 * expected(i)) << i;
}
