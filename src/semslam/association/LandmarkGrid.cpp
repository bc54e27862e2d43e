#include "semslam/association/LandmarkGrid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace semslam {
namespace {

/// Cell coordinates are clamped here, far beyond any map (and within int64 after adding the query's extent).
constexpr double kMaxCellCoordinate = 1e15;

std::int64_t cellCoordinate(double x, double cellSize) {
  return static_cast<std::int64_t>(std::clamp(std::floor(x / cellSize), -kMaxCellCoordinate, kMaxCellCoordinate));
}

void checkCellSize(double cellSize) {
  if (!(cellSize > 0.0) || !std::isfinite(cellSize)) {
    throw std::invalid_argument("grid cell size must be positive and finite");
  }
}

}  // namespace

std::size_t LandmarkGrid::CellKeyHash::operator()(const CellKey& key) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (std::int64_t k : key) {
    h ^= static_cast<std::uint64_t>(k) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  }
  return static_cast<std::size_t>(h);
}

LandmarkGrid::LandmarkGrid(int dimension, double cellSize) : dimension_(dimension), cellSize_(cellSize) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("grid dimension must be 2 or 3");
  checkCellSize(cellSize);
}

LandmarkGrid::CellKey LandmarkGrid::cellOf(const Vector3& position) const {
  return {cellCoordinate(position.x(), cellSize_), cellCoordinate(position.y(), cellSize_),
          dimension_ == 3 ? cellCoordinate(position.z(), cellSize_) : 0};
}

void LandmarkGrid::insertIntoCell(int id) {
  const std::size_t i = static_cast<std::size_t>(id);
  cellOfPoint_[i] = cellOf(positions_[i]);
  Cell& cell = cells_[cellOfPoint_[i]];
  cell.members.push_back(id);
  cell.maxSpread = std::max(cell.maxSpread, spreads_[i]);
}

void LandmarkGrid::removeFromCell(int id) {
  const auto found = cells_.find(cellOfPoint_[static_cast<std::size_t>(id)]);
  Cell& cell = found->second;
  cell.members.erase(std::find(cell.members.begin(), cell.members.end(), id));
  if (cell.members.empty()) {
    cells_.erase(found);
    return;
  }
  cell.maxSpread = 0.0;
  for (int member : cell.members) cell.maxSpread = std::max(cell.maxSpread, spreads_[static_cast<std::size_t>(member)]);
}

void LandmarkGrid::set(int id, const Eigen::Ref<const Vector>& position, double spread) {
  if (id < 0 || id > size()) throw std::invalid_argument("grid id " + std::to_string(id) + " is not in [0, size()]");
  if (position.size() != dimension_ || !position.allFinite()) {
    throw std::invalid_argument("grid position must have " + std::to_string(dimension_) + " finite coordinates");
  }
  if (!(spread >= 0.0) || !std::isfinite(spread)) throw std::invalid_argument("grid spread must be finite and >= 0");
  Vector3 padded = Vector3::Zero();
  padded.head(dimension_) = position;
  if (id == size()) {
    positions_.push_back(padded);
    spreads_.push_back(spread);
    cellOfPoint_.push_back({});
    allSpreads_.insert(spread);
    insertIntoCell(id);
    return;
  }
  const std::size_t i = static_cast<std::size_t>(id);
  const bool sameCell = cellOf(padded) == cellOfPoint_[i];
  const bool spreadShrinks = spread < spreads_[i];
  if (spread != spreads_[i]) {
    allSpreads_.erase(allSpreads_.find(spreads_[i]));
    allSpreads_.insert(spread);
  }
  if (sameCell && !spreadShrinks) {  // the common case after a solve: the point moved a little within its cell
    positions_[i] = padded;
    spreads_[i] = spread;
    Cell& cell = cells_.at(cellOfPoint_[i]);
    cell.maxSpread = std::max(cell.maxSpread, spread);
    return;
  }
  removeFromCell(id);
  positions_[i] = padded;
  spreads_[i] = spread;
  insertIntoCell(id);
}

double LandmarkGrid::distanceToCell(const Vector3& center, const CellKey& key) const {
  double squared = 0.0;
  for (int axis = 0; axis < dimension_; ++axis) {
    const double low = static_cast<double>(key[static_cast<std::size_t>(axis)]) * cellSize_;
    const double high = low + cellSize_;
    const double gap = std::max({low - center(axis), center(axis) - high, 0.0});
    squared += gap * gap;
  }
  return std::sqrt(squared);
}

void LandmarkGrid::collect(const Cell& cell, const CellKey& key, const Vector3& center, double base, double slope,
                           std::vector<int>& out) const {
  // Rounding in the cell bounds must never drop a point: the cell test has a relative margin (the point test is
  // exact).
  const double cellRadius = base + slope * cell.maxSpread;
  if (distanceToCell(center, key) > cellRadius * (1.0 + 1e-9) + 1e-9 * (cellSize_ + center.cwiseAbs().maxCoeff())) {
    return;
  }
  for (int id : cell.members) {
    const std::size_t i = static_cast<std::size_t>(id);
    if ((positions_[i] - center).norm() <= base + slope * spreads_[i]) out.push_back(id);
  }
}

std::vector<int> LandmarkGrid::within(const Eigen::Ref<const Vector>& center, double base, double slope) const {
  if (center.size() != dimension_ || !center.allFinite()) {
    throw std::invalid_argument("grid query centre must have " + std::to_string(dimension_) + " finite coordinates");
  }
  if (!(base >= 0.0) || !(slope >= 0.0) || !std::isfinite(base) || !std::isfinite(slope)) {
    throw std::invalid_argument("grid query radius must be finite and >= 0");
  }
  std::vector<int> out;
  if (positions_.empty()) return out;
  Vector3 c = Vector3::Zero();
  c.head(dimension_) = center;
  const double largest = base + slope * *allSpreads_.rbegin();
  const double reach = largest * (1.0 + 1e-9) + 1e-9 * (cellSize_ + c.cwiseAbs().maxCoeff());
  CellKey low{0, 0, 0}, high{0, 0, 0};
  double boxCells = 1.0;
  for (int axis = 0; axis < dimension_; ++axis) {
    const std::size_t a = static_cast<std::size_t>(axis);
    low[a] = cellCoordinate(c(axis) - reach, cellSize_);
    high[a] = cellCoordinate(c(axis) + reach, cellSize_);
    boxCells *= static_cast<double>(high[a] - low[a]) + 1.0;
  }
  if (boxCells > static_cast<double>(cells_.size())) {
    for (const auto& [key, cell] : cells_) collect(cell, key, c, base, slope, out);
  } else {
    for (std::int64_t x = low[0]; x <= high[0]; ++x) {
      for (std::int64_t y = low[1]; y <= high[1]; ++y) {
        for (std::int64_t z = low[2]; z <= high[2]; ++z) {
          const CellKey key{x, y, z};
          const auto found = cells_.find(key);
          if (found != cells_.end()) collect(found->second, key, c, base, slope, out);
        }
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

void LandmarkGrid::rebuild(double cellSize) {
  checkCellSize(cellSize);
  cellSize_ = cellSize;
  cells_.clear();
  for (int id = 0; id < size(); ++id) insertIntoCell(id);
}

}  // namespace semslam
