// semslam_build_solve_baseline: the C++ side of the Python calling-overhead benchmark (bench/python_overhead.py).
//
// Reads a g2o pose graph (untimed), keeps its first N poses and the edges among them, then, after one warm-up run, REPEATS times builds the
// problem factor by factor from plain numbers — a prior holding pose 0 (σ = 1e-6, as `semslam optimize` anchors
// it), one SE2 value per pose, one BetweenFactor<SE2> per edge with its information matrix — and solves it by
// Gauss-Newton (solve/Optimizer.h), timed in the thread's CPU time. bench/python_overhead.py does exactly the same
// through the Python module, so the ratio of the two medians is what Python costs. Prints one JSON object: every run's seconds, their median,
// the medians of the build and of the solve alone and their runs, the final chi2 (both sides must agree) and the problem's size.
//
//   semslam_build_solve_baseline FILE.g2o [--poses N] [--repeats R]

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>
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

/// One timed run: the seconds of building the problem and of solving it.
struct RunSeconds {
  double build = 0.0;
  double solve = 0.0;
};

/// The CPU time of the calling thread, in seconds: on a shared virtual machine, wall time also counts what other
/// tenants take (steal time), which hits two runs unequally; the work of one thread is what is compared here.
double threadSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

RunSeconds buildAndSolve(const std::vector<Vertex>& vertices, const std::vector<Edge>& edges, double& finalChi2) {
  const double start = threadSeconds();
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
  const double built = threadSeconds();
  OptimizerParams params;
  params.solver = SolverType::GaussNewton;
  const OptimizationResult result = optimize(graph, values, params);
  finalChi2 = result.finalChi2;
  return {built - start, threadSeconds() - built};
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
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
    std::vector<double> seconds, build, solve;
    double finalChi2 = 0.0;
    buildAndSolve(vertices, edges, finalChi2);  // warm-up (first allocations, caches), as the Python side does one
    for (int r = 0; r < repeats; ++r) {
      const RunSeconds run = buildAndSolve(vertices, edges, finalChi2);
      seconds.push_back(run.build + run.solve);
      build.push_back(run.build);
      solve.push_back(run.solve);
    }
    std::printf("{\"poses\": %zu, \"edges\": %zu, \"final_chi2\": %.17g, \"median_s\": %.9g, "
                "\"build_median_s\": %.9g, \"solve_median_s\": %.9g, \"seconds\": [",
                vertices.size(), edges.size(), finalChi2, median(seconds), median(build), median(solve));
    for (std::size_t i = 0; i < seconds.size(); ++i) std::printf("%s%.9g", i ? ", " : "", seconds[i]);
    std::printf("], \"build_seconds\": [");
    for (std::size_t i = 0; i < build.size(); ++i) std::printf("%s%.9g", i ? ", " : "", build[i]);
    std::printf("], \"solve_seconds\": [");
    for (std::size_t i = 0; i < solve.size(); ++i) std::printf("%s%.9g", i ? ", " : "", solve[i]);
    std::printf("]}\n");
  } catch (const InputError& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 2;
  }
  return 0;
}
