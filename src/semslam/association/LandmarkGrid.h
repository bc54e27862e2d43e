#pragma once
// LandmarkGrid: a uniform grid over points in the plane or in space, for the spatial pre-selection of association
// candidates (docs/association-front-end.md, §7). Point j has a position p_j and a spread s_j ≥ 0 (a bound on its
// standard deviation, CandidatePreselection.h); the one query is the inflated ball
//
//     within(c, base, slope) = { j : ‖p_j − c‖ ≤ base + slope · s_j },   ascending j,
//
// each point inside a ball of its own radius. Cells are cubes of side h (squares in 2D) keyed by ⌊p / h⌋ in a hash
// map, so the map may be unbounded and only occupied cells cost memory. A query visits the cells the ball of the
// largest radius, base + slope · max_j s_j, overlaps, skips a cell whose nearest point is farther than
// base + slope · (the cell's largest spread), and tests each remaining point exactly; when that ball overlaps more
// cells than are occupied, it visits the occupied cells instead. Cost: O(cells visited + points tested), i.e.
// independent of the number of points for a bounded radius and a bounded density; O(1) expected per set().
//
// Why a grid and not a k-d tree: the points move after every solve (a landmark's estimate changes), which a grid
// absorbs with O(1) re-binning of the moved points while a k-d tree needs rebalancing or a rebuild; the query radii
// are similar from step to step (the sensor's range scale), which is the case a fixed cell size serves well;
// rebuild(h) re-bins everything when they drift (§7).
//
// Invariants: ids are dense, 0..size()−1, in the order they were first set; positions have dimension() (2 or 3)
// finite coordinates; spreads are finite and ≥ 0; h > 0. The answer does not depend on h (only the cost does).

#include <array>
#include <cstdint>
#include <set>
#include <unordered_map>
#include <vector>

#include "semslam/geometry/Matrix.h"

namespace semslam {

class LandmarkGrid {
 public:
  /// Throws std::invalid_argument unless dimension is 2 or 3 and cellSize > 0 and finite.
  LandmarkGrid(int dimension, double cellSize);

  int dimension() const { return dimension_; }
  int size() const { return static_cast<int>(positions_.size()); }
  double cellSize() const { return cellSize_; }
  const Vector3& position(int id) const { return positions_.at(static_cast<std::size_t>(id)); }
  double spread(int id) const { return spreads_.at(static_cast<std::size_t>(id)); }

  /// Adds point `id` (id == size()) or moves and re-spreads an existing one. Throws std::invalid_argument for a
  /// position of the wrong dimension or non-finite, a negative or non-finite spread, or id outside [0, size()].
  void set(int id, const Eigen::Ref<const Vector>& position, double spread);

  /// { j : ‖p_j − c‖ ≤ base + slope · s_j }, ascending. base and slope must be ≥ 0 and finite (else
  /// std::invalid_argument); c must have dimension() coordinates.
  std::vector<int> within(const Eigen::Ref<const Vector>& center, double base, double slope) const;

  /// Re-bins every point into cells of side `cellSize`.
  void rebuild(double cellSize);

 private:
  using CellKey = std::array<std::int64_t, 3>;
  struct CellKeyHash {
    std::size_t operator()(const CellKey& key) const;
  };
  struct Cell {
    std::vector<int> members;
    double maxSpread = 0.0;
  };

  CellKey cellOf(const Vector3& position) const;
  void insertIntoCell(int id);
  void removeFromCell(int id);
  /// Distance from c to the closed box of cell `key` (0 inside).
  double distanceToCell(const Vector3& center, const CellKey& key) const;
  void collect(const Cell& cell, const CellKey& key, const Vector3& center, double base, double slope,
               std::vector<int>& out) const;

  int dimension_;
  double cellSize_;
  std::vector<Vector3> positions_;  // 2D points have z = 0
  std::vector<double> spreads_;
  std::vector<CellKey> cellOfPoint_;
  std::unordered_map<CellKey, Cell, CellKeyHash> cells_;
  std::multiset<double> allSpreads_;  // for max_j s_j
};

}  // namespace semslam
