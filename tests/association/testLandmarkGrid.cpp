// LandmarkGrid (docs/association-front-end.md, §7): the inflated-ball query returns exactly the points inside, on a
// hand-made layout and against brute force on seeded random layouts in 2D and 3D, through moves, spread changes
// and re-binning, for any cell size.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "semslam/association/LandmarkGrid.h"

using namespace semslam;

namespace {

struct Layout {
  std::vector<Vector> positions;
  std::vector<double> spreads;
};

std::vector<int> bruteForce(const Layout& layout, const Vector& center, double base, double slope) {
  std::vector<int> inside;
  for (std::size_t j = 0; j < layout.positions.size(); ++j) {
    const double radius = base + slope * layout.spreads[j];
    if ((layout.positions[j] - center).norm() <= radius) inside.push_back(static_cast<int>(j));
  }
  return inside;
}

Vector randomPoint(std::mt19937& rng, int dimension, double halfWidth) {
  std::uniform_real_distribution<double> u(-halfWidth, halfWidth);
  Vector p(dimension);
  for (int i = 0; i < dimension; ++i) p(i) = u(rng);
  return p;
}

/// Random points, moves, spread changes and queries, each query compared with brute force; returns how many
/// queries had a non-empty answer (so that the comparison is not vacuous).
int compareWithBruteForce(int dimension, double cellSize, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  LandmarkGrid grid(dimension, cellSize);
  Layout layout;
  const auto spread = [&] { return u01(rng) < 0.02 ? 20.0 * u01(rng) : 2.0 * u01(rng); };  // a few wide ones
  int nonEmpty = 0;
  for (int round = 0; round < 40; ++round) {
    for (int i = 0; i < 25; ++i) {  // new points
      layout.positions.push_back(randomPoint(rng, dimension, 50.0));
      layout.spreads.push_back(spread());
      grid.set(static_cast<int>(layout.positions.size()) - 1, layout.positions.back(), layout.spreads.back());
    }
    for (int i = 0; i < 30; ++i) {  // moves: small (within a cell, mostly), large, and spread changes
      const int j = std::uniform_int_distribution<int>(0, grid.size() - 1)(rng);
      const double r = u01(rng);
      if (r < 0.4) layout.positions[static_cast<std::size_t>(j)] += randomPoint(rng, dimension, 0.05);
      else if (r < 0.7) layout.positions[static_cast<std::size_t>(j)] = randomPoint(rng, dimension, 50.0);
      else layout.spreads[static_cast<std::size_t>(j)] = spread();
      grid.set(j, layout.positions[static_cast<std::size_t>(j)], layout.spreads[static_cast<std::size_t>(j)]);
    }
    if (round % 10 == 9) grid.rebuild(cellSize * (0.5 + u01(rng)));
    for (int q = 0; q < 20; ++q) {
      const Vector center = randomPoint(rng, dimension, 60.0);
      const double base = 15.0 * u01(rng), slope = 3.0 * u01(rng);
      const std::vector<int> expected = bruteForce(layout, center, base, slope);
      EXPECT_EQ(grid.within(center, base, slope), expected) << "round " << round << " query " << q;
      nonEmpty += expected.empty() ? 0 : 1;
    }
  }
  return nonEmpty;
}

}  // namespace

TEST(LandmarkGrid, ReturnsThePointsInsideTheirOwnInflatedBallOnAHandMadeLayout) {
  LandmarkGrid grid(2, 1.0);
  grid.set(0, Vector2(0.0, 0.0), 0.0);
  grid.set(1, Vector2(1.0, 0.0), 0.0);
  grid.set(2, Vector2(0.0, -2.0), 0.0);  // exactly on the radius: inside (closed ball)
  grid.set(3, Vector2(3.0, 4.0), 1.0);   // at distance 5
  grid.set(4, Vector2(-7.0, 0.5), 0.0);
  EXPECT_EQ(grid.within(Vector2(0.0, 0.0), 2.0, 0.0), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(grid.within(Vector2(0.0, 0.0), 2.0, 2.9), (std::vector<int>{0, 1, 2}));     // 2 + 2.9 · 1 < 5
  EXPECT_EQ(grid.within(Vector2(0.0, 0.0), 2.0, 3.0), (std::vector<int>{0, 1, 2, 3}));  // 2 + 3 · 1 = 5
  EXPECT_EQ(grid.within(Vector2(-7.0, 0.0), 0.5, 0.0), (std::vector<int>{4}));
  EXPECT_TRUE(grid.within(Vector2(100.0, 100.0), 1.0, 1.0).empty());
  grid.set(3, Vector2(-7.0, 1.0), 0.0);  // moved next to point 4
  EXPECT_EQ(grid.within(Vector2(-7.0, 0.0), 1.0, 0.0), (std::vector<int>{3, 4}));
  EXPECT_EQ(grid.within(Vector2(0.0, 0.0), 2.0, 3.0), (std::vector<int>{0, 1, 2}));
}

TEST(LandmarkGrid, MatchesBruteForceOnRandomLayoutsIn2dAnd3dForAnyCellSize) {
  for (int dimension : {2, 3}) {
    for (double cellSize : {0.7, 4.0, 30.0, 500.0}) {  // 500: one cell holds everything
      EXPECT_GT(compareWithBruteForce(dimension, cellSize, 17u + static_cast<unsigned>(dimension)), 100)
          << dimension << "D, cell " << cellSize;
    }
  }
}

TEST(LandmarkGrid, RejectsBadInput) {
  EXPECT_THROW(LandmarkGrid(4, 1.0), std::invalid_argument);
  EXPECT_THROW(LandmarkGrid(2, 0.0), std::invalid_argument);
  LandmarkGrid grid(3, 1.0);
  EXPECT_THROW(grid.set(1, Vector3(0, 0, 0), 0.0), std::invalid_argument);  // ids are dense
  EXPECT_THROW(grid.set(0, Vector2(0, 0), 0.0), std::invalid_argument);     // wrong dimension
  EXPECT_THROW(grid.set(0, Vector3(0, 0, 0), -1.0), std::invalid_argument);
  grid.set(0, Vector3(0, 0, 0), 0.0);
  EXPECT_THROW(grid.within(Vector3(0, 0, 0), -1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(grid.rebuild(-2.0), std::invalid_argument);
}
