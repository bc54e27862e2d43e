// The joint compatibility search (association/JointCompatibility.h) against exhaustive enumeration, and the case it
// is for: re-sightings under a broad, shared pose uncertainty.
//
// The problems here are linear-Gaussian in the plane: a robot at an uncertain position p (mean p̂, covariance Σ_p)
// measures landmark j at l_j − p + noise (covariance R_i). The joint density of a set of pairings is then exact:
// ν = stacked (z_i − (l_j − p̂)), S = H Σ_p Hᵀ + blockdiag(R_i) with H the stacked −I.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "semslam/association/JointCompatibility.h"
#include "semslam/geometry/Matrix.h"

namespace semslam {
namespace {

struct PlanarProblem {
  Matrix poseCovariance = Matrix::Identity(2, 2);
  std::vector<Vector> landmarks;      // l_j, relative to the predicted pose p̂
  std::vector<Vector> measurements;   // z_i
  std::vector<Matrix> noise;          // R_i
  std::vector<JointAssignmentRow> rows;

  double logNormalizer(std::size_t i) const {
    return std::log(2.0 * std::numbers::pi) + 0.5 * std::log(noise[i].determinant());
  }

  LinearizedLikelihood density(const std::vector<std::pair<std::size_t, int>>& pairings) const {
    const Eigen::Index n = static_cast<Eigen::Index>(2 * pairings.size());
    Vector innovation(n);
    Matrix S = Matrix::Zero(n, n);
    for (std::size_t a = 0; a < pairings.size(); ++a) {
      const auto [row, landmark] = pairings[a];
      const Eigen::Index i = static_cast<Eigen::Index>(2 * a);
      innovation.segment(i, 2) = measurements[row] - landmarks[static_cast<std::size_t>(landmark)];
      for (std::size_t b = 0; b < pairings.size(); ++b) {
        S.block(i, static_cast<Eigen::Index>(2 * b), 2, 2) = poseCovariance;  // (−I) Σ_p (−I)ᵀ
      }
      S.block(i, i, 2, 2) += noise[row];
    }
    const Eigen::LLT<Matrix> llt(S);
    LinearizedLikelihood result;
    result.dimension = static_cast<int>(n);
    result.innovationChi2 = innovation.dot(llt.solve(innovation));
    const double logDet = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
    result.logLikelihood = -0.5 * result.innovationChi2 - 0.5 * logDet - 0.5 * n * std::log(2.0 * std::numbers::pi);
    return result;
  }

  JointDensity densityFunction() const {
    return [this](const std::vector<std::pair<std::size_t, int>>& pairings) { return density(pairings); };
  }

  /// Each row's pairings alone, s_ij + ln N(ν_ij; 0, S_ij), as the front end weighs them.
  void weighPairingsAlone() {
    for (std::size_t i = 0; i < rows.size(); ++i) {
      rows[i].pairingLogLikelihoods.clear();
      for (std::size_t c = 0; c < rows[i].candidates.size(); ++c) {
        rows[i].pairingLogLikelihoods.push_back(rows[i].labelLogLikelihoods[c] +
                                                density({{i, rows[i].candidates[c]}}).logLikelihood);
      }
    }
  }
};

/// Every exclusive assignment, each admissible only if every prefix of its pairings (in row order) passes the joint
/// gate (χ² − 2 Σ ln(P(s | j) / P₀(s))), the best by the score of the header (the incumbent kept on a tie; the
/// random problems below have no other ties).
std::pair<std::vector<int>, double> enumerate(const PlanarProblem& problem, const AssociationGate& gate,
                                              const std::vector<int>& incumbent) {
  const std::size_t rows = problem.rows.size();
  std::vector<int> current(rows, -1), best;
  double bestScore = -std::numeric_limits<double>::infinity();
  const auto scoreOf = [&](const std::vector<int>& assignment) -> std::optional<double> {
    double total = 0.0, labelRatios = 0.0;
    std::vector<std::pair<std::size_t, int>> pairings;
    for (std::size_t i = 0; i < rows; ++i) {
      const JointAssignmentRow& row = problem.rows[i];
      if (assignment[i] < 0) {
        total += row.unassignedLogLikelihood;
        continue;
      }
      for (std::size_t c = 0; c < row.candidates.size(); ++c) {
        if (row.candidates[c] != assignment[i]) continue;
        total += row.labelLogLikelihoods[c];
        labelRatios += row.labelLogLikelihoods[c] - row.labelPriorLogLikelihood;
      }
      pairings.emplace_back(i, assignment[i]);
      const LinearizedLikelihood prefix = problem.density(pairings);
      if (prefix.innovationChi2 - 2.0 * labelRatios > gate.threshold(prefix.dimension)) return std::nullopt;
    }
    if (!pairings.empty()) total += problem.density(pairings).logLikelihood;
    return total;
  };
  const std::vector<int> none(rows, -1);
  best = none;
  bestScore = *scoreOf(none);
  if (const std::optional<double> given = scoreOf(incumbent); given && *given >= bestScore) {
    best = incumbent;
    bestScore = *given;
  }
  const std::function<void(std::size_t)> visit = [&](std::size_t i) {
    if (i == rows) {
      const std::optional<double> value = scoreOf(current);
      if (value && *value > bestScore) {
        bestScore = *value;
        best = current;
      }
      return;
    }
    current[i] = -1;
    visit(i + 1);
    for (int landmark : problem.rows[i].candidates) {
      if (std::find(current.begin(), current.begin() + static_cast<std::ptrdiff_t>(i), landmark) !=
          current.begin() + static_cast<std::ptrdiff_t>(i)) {
        continue;
      }
      current[i] = landmark;
      visit(i + 1);
      current[i] = -1;
    }
  };
  visit(0);
  return {best, bestScore};
}

/// A random problem: `landmarkCount` landmarks in a 10 m square, `rowCount` detections, most of a landmark (some
/// of none), each with the landmarks within reach as candidates; pose uncertainty from 0.1 to 5 m.
PlanarProblem randomProblem(std::mt19937& rng, int landmarkCount, int rowCount) {
  std::uniform_real_distribution<double> position(-5.0, 5.0), unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  PlanarProblem problem;
  const double poseSigma = 0.1 + 4.9 * unit(rng);
  problem.poseCovariance = poseSigma * poseSigma * Matrix::Identity(2, 2);
  for (int j = 0; j < landmarkCount; ++j) problem.landmarks.push_back(Vector2(position(rng), position(rng)));
  const Vector poseError = poseSigma * Vector2(normal(rng), normal(rng));
  for (int i = 0; i < rowCount; ++i) {
    const double sigma = 0.1 + 0.4 * unit(rng);
    problem.noise.push_back(sigma * sigma * Matrix::Identity(2, 2));
    const bool clutter = unit(rng) < 0.2;
    const Vector source = clutter ? Vector(Vector2(position(rng), position(rng)))
                                  : problem.landmarks[static_cast<std::size_t>(i % landmarkCount)];
    problem.measurements.push_back(source - poseError + sigma * Vector2(normal(rng), normal(rng)));
    JointAssignmentRow row;
    for (int j = 0; j < landmarkCount; ++j) {
      const Vector offset = problem.measurements.back() - problem.landmarks[static_cast<std::size_t>(j)];
      if (offset.norm() > 3.0 * poseSigma + 2.0) continue;
      row.candidates.push_back(j);
      row.labelLogLikelihoods.push_back(std::log(0.2 + 0.8 * unit(rng)));
    }
    row.unassignedLogLikelihood = std::log(0.002 + 0.05 * unit(rng));
    row.labelPriorLogLikelihood = std::log(0.5);  // labels both likelier and less likely than under the prior
    row.logNormalizer = problem.logNormalizer(static_cast<std::size_t>(i));
    problem.rows.push_back(std::move(row));
  }
  problem.weighPairingsAlone();
  return problem;
}

TEST(JointCompatibility, FindsTheBestAdmissibleAssignmentOfEveryRandomProblem) {
  std::mt19937 rng(20261206);
  const AssociationGate gate(0.99);  // a tight gate, so that some branches are cut by it
  int changed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const PlanarProblem problem = randomProblem(rng, 2 + trial % 5, 1 + trial % 5);
    const std::vector<int> incumbent(problem.rows.size(), -1);
    const JointAssignment found = jointlyCompatibleAssignment(problem.rows, problem.densityFunction(), gate, incumbent);
    const auto [expected, expectedScore] = enumerate(problem, gate, incumbent);
    ASSERT_TRUE(found.exhaustive);
    EXPECT_EQ(found.landmarkOfRow, expected) << "trial " << trial;
    EXPECT_NEAR(found.logLikelihood, expectedScore, 1e-9 * (1.0 + std::abs(expectedScore))) << "trial " << trial;
    changed += found.landmarkOfRow != incumbent;
  }
  EXPECT_GT(changed, 100);  // the problems are not all left unassigned
}

TEST(JointCompatibility, TwoReSightingsUnderABroadPoseUncertaintyArePairedTogether) {
  // Two landmarks 4 m apart; the pose is known to 6 m, the detections to 0.1 m; both detections are of the two
  // landmarks, seen 5 m off where the pose predicts them. Alone, each pairing's density (its S holds the whole pose
  // uncertainty) is below the unassigned density; together the second pays only its own noise given the first.
  PlanarProblem problem;
  problem.poseCovariance = 36.0 * Matrix::Identity(2, 2);
  problem.landmarks = {Vector2(0.0, 0.0), Vector2(4.0, 0.0)};
  const Vector offset = Vector2(3.0, 4.0);
  problem.measurements = {problem.landmarks[0] + offset, problem.landmarks[1] + offset};
  problem.noise = {0.01 * Matrix::Identity(2, 2), 0.01 * Matrix::Identity(2, 2)};
  const double unassigned = std::log(0.005);  // per m², e.g. a field of 200 m² holding one new object per step
  for (std::size_t i = 0; i < 2; ++i) {
    problem.rows.push_back({{0, 1}, {0.0, 0.0}, {}, unassigned, 0.0, problem.logNormalizer(i)});
  }
  problem.weighPairingsAlone();
  const AssociationGate gate;
  for (std::size_t i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      EXPECT_LT(problem.density({{i, j}}).logLikelihood, unassigned) << "each pairing alone loses";
    }
  }
  const JointAssignment found =
      jointlyCompatibleAssignment(problem.rows, problem.densityFunction(), gate, std::vector<int>{-1, -1});
  EXPECT_EQ(found.landmarkOfRow, (std::vector<int>{0, 1}));  // and not swapped: the geometry between them decides
  EXPECT_GT(found.logLikelihood, 2.0 * unassigned + 5.0);
  // Swapped, the pair is jointly incompatible (8 m between the innovations, 0.14 m of noise between them).
  const LinearizedLikelihood swapped = problem.density({{0, 1}, {1, 0}});
  EXPECT_GT(swapped.innovationChi2, gate.threshold(swapped.dimension));
}

TEST(JointCompatibility, TiesKeepTheIncumbentAndABudgetStopsTheSearch) {
  // Two identical rows with one landmark between them: pairing either one scores the same; the incumbent stays.
  PlanarProblem problem;
  problem.landmarks = {Vector2(0.0, 0.0)};
  problem.measurements = {Vector2(0.0, 0.0), Vector2(0.0, 0.0)};
  problem.noise = {0.01 * Matrix::Identity(2, 2), 0.01 * Matrix::Identity(2, 2)};
  for (std::size_t i = 0; i < 2; ++i) {
    problem.rows.push_back({{0}, {0.0}, {}, std::log(1e-4), 0.0, problem.logNormalizer(i)});
  }
  problem.weighPairingsAlone();
  const AssociationGate gate;
  for (const std::vector<int>& incumbent : {std::vector<int>{0, -1}, std::vector<int>{-1, 0}}) {
    const JointAssignment found = jointlyCompatibleAssignment(problem.rows, problem.densityFunction(), gate, incumbent);
    EXPECT_EQ(found.landmarkOfRow, incumbent);
    EXPECT_TRUE(found.exhaustive);
  }
  // One evaluation allowed: the search stops and says so, keeping the best found (here the incumbent).
  const JointAssignment stopped =
      jointlyCompatibleAssignment(problem.rows, problem.densityFunction(), gate, std::vector<int>{-1, 0}, 1);
  EXPECT_FALSE(stopped.exhaustive);
  EXPECT_EQ(stopped.landmarkOfRow, (std::vector<int>{-1, 0}));
}

TEST(JointCompatibility, RefusesInconsistentProblems) {
  PlanarProblem problem;
  problem.landmarks = {Vector2(0.0, 0.0), Vector2(1.0, 0.0)};
  problem.measurements = {Vector2(0.0, 0.0), Vector2(1.0, 0.0)};
  problem.noise = {Matrix::Identity(2, 2), Matrix::Identity(2, 2)};
  problem.rows = {{{0, 1}, {0.0, 0.0}, {-3.0, -4.0}, -5.0, 0.0, 1.0}, {{0, 1}, {0.0, 0.0}, {-3.0, -4.0}, -5.0, 0.0, 1.0}};
  const AssociationGate gate;
  const JointDensity density = problem.densityFunction();
  EXPECT_THROW(jointlyCompatibleAssignment(problem.rows, density, gate, {-1}), std::invalid_argument);  // size
  EXPECT_THROW(jointlyCompatibleAssignment(problem.rows, density, gate, {0, 0}), std::invalid_argument);  // twice
  EXPECT_THROW(jointlyCompatibleAssignment(problem.rows, density, gate, {2, -1}), std::invalid_argument);  // not one
  EXPECT_THROW(jointlyCompatibleAssignment(problem.rows, density, gate, {-1, -1}, 0), std::invalid_argument);  // budget
  problem.rows[1].pairingLogLikelihoods.pop_back();
  EXPECT_THROW(jointlyCompatibleAssignment(problem.rows, density, gate, {-1, -1}), std::invalid_argument);
  problem.rows[1].pairingLogLikelihoods.push_back(-4.0);
  problem.rows[1].labelLogLikelihoods.pop_back();
  EXPECT_THROW(jointlyCompatibleAssignment(problem.rows, density, gate, {-1, -1}), std::invalid_argument);
}

TEST(JointCompatibility, ThePairingsAloneOnlyOrderTheSearch) {
  // The pairings' own likelihoods only say which option is tried first: with other values (reversed and scrambled,
  // some above the unassigned hypothesis where they were below) the search finds the same maximum (the random
  // problems have no ties).
  std::mt19937 rng(20261207);
  const AssociationGate gate(0.99);
  for (int trial = 0; trial < 200; ++trial) {
    PlanarProblem problem = randomProblem(rng, 2 + trial % 5, 1 + trial % 5);
    const std::vector<int> incumbent(problem.rows.size(), -1);
    const JointAssignment ordered = jointlyCompatibleAssignment(problem.rows, problem.densityFunction(), gate, incumbent);
    for (JointAssignmentRow& row : problem.rows) {
      for (double& value : row.pairingLogLikelihoods) value = -value + std::uniform_real_distribution<double>(-9, 9)(rng);
    }
    const JointAssignment found = jointlyCompatibleAssignment(problem.rows, problem.densityFunction(), gate, incumbent);
    ASSERT_TRUE(found.exhaustive);
    EXPECT_EQ(found.landmarkOfRow, ordered.landmarkOfRow) << "trial " << trial;
    EXPECT_NEAR(found.logLikelihood, ordered.logLikelihood, 1e-9 * (1.0 + std::abs(ordered.logLikelihood)))
        << "trial " << trial;
  }
}

}  // namespace
}  // namespace semslam
