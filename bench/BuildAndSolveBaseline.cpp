// semslam_build_solve_baseline: the C++ side of the Python calling-overhead benchmark (bench/python_overhead.py).
//
// Reads a g2o pose graph (untimed), keeps its first N poses and the edges among them, then, after one warm-up run, REPEATS times builds the
// problem factor by factor from plain numbers — a prior holding pose 0 (σ = 1e-6, as `semslam optimize` anchors
// it), one SE2 value per pose, one BetweenFactor<SE2> per edge with its information matrix — and solves it by
// Gauss-Newton (solve/Optimizer.h). bench/python_overhead.py does exactly the same through the Python module, so
// the ratio of the two medians is what Python costs. Prints one JSON object: every run's seconds, their median,
// the final chi2 (both sides must agree) and the problem's size.
//
//   semslam_build_solve_baseline FILE.g2o [--poses N] [--repeats R]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "semslam/core/InputError.h"
#include "semslam/factors/BetweenFactor.h"
#include "semslam/factors/PriorFactor.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/solve/Optimizer.h"

namespace {

using namespace semslam;

struct Edge {
  Key from = 0, to = 0;
  double dx = 0, dy = 0, dtheta = 0;
  Matrix information;
};

struct Vertex {
  Key key = 0;
  double x = 0, y = 0, theta = 0;
};

double buildAndSolve(const std::vector<Vertex>& vertices, const std::vector<Edge>& edges, double& finalChi2) {
  const auto start = std::chrono::steady_clock::now();
  FactorGraph graph;
  Values values;
  const Vertex& first = vertices.front();
  graph.add(std::make_shared<PriorFactor<SE2>>(first.key, SE2(first.x, first.y, first.theta),
                                               NoiseModel::fromSigmas(Vector3::Constant(1e-6))));
  for (const Vertex& v : vertices) values.insert(v.key, SE2(v.x, v.y, v.theta));
  for (const Edge& e : edges) {
    graph.add(std::make_shared<BetweenFactor<SE2>>(e.from, e.to, SE2(e.dx, e.dy, e.dtheta),
                                                   NoiseModel::fromInformation(e.information)));
  }
  OptimizerParams params;
  params.solver = SolverType::GaussNewton;
  const OptimizationResult result = optimize(graph, values, params);
  finalChi2 = result.finalChi2;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE.g2o [--poses N] [--repeats R]\n", argv[0]);
    return 2;
  }
  std::size_t poses = 1000;
  int repeats = 5;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--poses") == 0) poses = std::stoul(argv[i + 1]);
    else if (std::strcmp(argv[i], "--repeats") == 0) repeats = std::stoi(argv[i + 1]);
  }
  try {
    const PoseGraphFile file = readPoseGraph(argv[1], GraphFormat::G2o);
    std::vector<Vertex> vertices;
    for (const auto& [key, value] : file.initial) {
      if (key >= poses) continue;
      const SE2& pose = std::get<SE2>(value);
      vertices.push_back({key, pose.x(), pose.y(), pose.theta()});
    }
    std::vector<Edge> edges;
    for (const FactorPtr& factor : file.factors) {
      const auto* between = dynamic_cast<const BetweenFactor<SE2>*>(factor.get());
      if (between == nullptr || between->keys()[0] >= poses || between->keys()[1] >= poses) continue;
      const SE2& z = between->measured();
      edges.push_back({between->keys()[0], between->keys()[1], z.x(), z.y(), z.theta(),
                       between->noiseModel()->information()});
    }
    std::vector<double> seconds;
    double finalChi2 = 0.0;
    buildAndSolve(vertices, edges, finalChi2);  // warm-up (first allocations, caches), as the Python side does one
    for (int r = 0; r < repeats; ++r) seconds.push_back(buildAndSolve(vertices, edges, finalChi2));
    std::vector<double> sorted = seconds;
    std::sort(sorted.begin(), sorted.end());
    std::printf("{\"poses\": %zu, \"edges\": %zu, \"final_chi2\": %.17g, \"median_s\": %.9g, \"seconds\": [",
                vertices.size(), edges.size(), finalChi2, sorted[sorted.size() / 2]);
    for (std::size_t i = 0; i < seconds.size(); ++i) std::printf("%s%.9g", i ? ", " : "", seconds[i]);
    std::printf("]}\n");
  } catch (const InputError& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 2;
  }
  return 0;
}
