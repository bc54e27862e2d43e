#include "semslam/solve/NormalEquations.h"

#include <algorithm>
#include <stdexcept>

namespace semslam {

namespace {
// Small dense blocks live on the stack: no variable of ours has more than 6 tangent dimensions.
using BlockMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 6, 6>;
}  // namespace

NormalEquations::NormalEquations(const FactorGraph& graph, const Values& values) : graph_(graph) {
  // Variables: every key a factor touches, in key order.
  keys_ = graph.keys();
  offsets_.reserve(keys_.size());
  dims_.reserve(keys_.size());
  for (Key key : keys_) {
    if (!values.exists(key)) {
      throw std::invalid_argument("a factor names variable " + keyToString(key) + ", which has no value");
    }
    const int d = semslam::dimension(values.value(key));
    if (d > 6) throw std::invalid_argument("variable " + keyToString(key) + " has more than 6 dimensions");
    offsets_.push_back(dimension_);
    dims_.push_back(d);
    dimension_ += d;
  }

  // Block pattern of the upper triangle: rowsOfColumn[b] = sorted block rows a ≤ b that share a factor with b.
  const int n = static_cast<int>(keys_.size());
  std::vector<std::vector<int>> rowsOfColumn(n);
  factorVariables_.resize(graph.size());
  for (std::size_t f = 0; f < graph.size(); ++f) {
    std::vector<int>& vars = factorVariables_[f];
    for (Key key : graph[f]->keys()) vars.push_back(variableIndex(key));
    std::vector<int> sorted = vars;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      throw std::invalid_argument("a factor names one variable twice");
    }
    for (int a : vars) {
      for (int b : vars) {
        if (a <= b) rowsOfColumn[b].push_back(a);
      }
    }
  }
  for (auto& rows : rowsOfColumn) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  }
  for (int b = 0; b < n; ++b) {
    if (rowsOfColumn[b].empty() || rowsOfColumn[b].back() != b) rowsOfColumn[b].push_back(b);
  }

  // Compressed columns: scalar column s of block b holds every off-diagonal block row in full, then the first
  // s + 1 rows of the diagonal block. rowOffset[b][k] is where block row rowsOfColumn[b][k] starts in a column.
  std::vector<std::vector<int>> rowOffset(n);
  std::vector<int> outer(dimension_ + 1, 0);
  for (int b = 0; b < n; ++b) {
    int offDiagonalRows = 0;
    for (int a : rowsOfColumn[b]) {
      rowOffset[b].push_back(offDiagonalRows);
      if (a != b) offDiagonalRows += dims_[a];
    }
    for (int s = 0; s < dims_[b]; ++s) outer[offsets_[b] + s + 1] = offDiagonalRows + s + 1;
  }
  for (int c = 0; c < dimension_; ++c) outer[c + 1] += outer[c];
  std::vector<int> inner(outer.back());
  diagonalPositions_.resize(dimension_);
  for (int b = 0; b < n; ++b) {
    for (int s = 0; s < dims_[b]; ++s) {
      const int column = offsets_[b] + s;
      int position = outer[column];
      for (int a : rowsOfColumn[b]) {
        const int rows = (a == b) ? s + 1 : dims_[a];
        for (int r = 0; r < rows; ++r) inner[position++] = offsets_[a] + r;
      }
      diagonalPositions_[column] = position - 1;
    }
  }
  hessian_.resize(dimension_, dimension_);
  hessian_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), hessian_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), hessian_.innerIndexPtr());
  std::fill(hessian_.valuePtr(), hessian_.valuePtr() + inner.size(), 0.0);

  // Per factor, the row offset of each block (a, b), a ≤ b, it contributes to.
  factorBlockRows_.resize(graph.size());
  for (std::size_t f = 0; f < graph.size(); ++f) {
    const std::vector<int>& vars = factorVariables_[f];
    for (int a : vars) {
      for (int b : vars) {
        if (a > b) continue;
        const auto& rows = rowsOfColumn[b];
        const auto k = std::lower_bound(rows.begin(), rows.end(), a) - rows.begin();
        factorBlockRows_[f].push_back(rowOffset[b][k]);
      }
    }
  }
  linearized_.resize(graph.size());
  gradient_ = Vector::Zero(dimension_);
}

int NormalEquations::variableIndex(Key key) const {
  const auto it = std::lower_bound(keys_.begin(), keys_.end(), key);
  if (it == keys_.end() || *it != key) throw std::out_of_range("variable " + keyToString(key) + " is not in the system");
  return static_cast<int>(it - keys_.begin());
}

int NormalEquations::offset(Key key) const { return offsets_[variableIndex(key)]; }
int NormalEquations::dimension(Key key) const { return dims_[variableIndex(key)]; }

double NormalEquations::assemble(const Values& values) {
  double* H = hessian_.valuePtr();
  const int* outer = hessian_.outerIndexPtr();
  std::fill(H, H + hessian_.nonZeros(), 0.0);
  gradient_.setZero();
  double chi2 = 0.0;
  BlockMatrix block;

  for (std::size_t f = 0; f < graph_.size(); ++f) {
    LinearizedFactor& lin = linearized_[f];
    graph_[f]->linearize(values, lin);
    const Vector& r = lin.whitenedError;
    chi2 += lin.chi2;
    const std::vector<int>& vars = factorVariables_[f];
    std::size_t pair = 0;
    for (std::size_t p = 0; p < vars.size(); ++p) {
      const int a = vars[p];
      gradient_.segment(offsets_[a], dims_[a]).noalias() += lin.jacobians[p].transpose() * r;
      for (std::size_t q = 0; q < vars.size(); ++q) {
        const int b = vars[q];
        if (a > b) continue;
        block.noalias() = lin.jacobians[p].transpose() * lin.jacobians[q];
        const int rowOffset = factorBlockRows_[f][pair++];
        for (int s = 0; s < dims_[b]; ++s) {
          double* column = H + outer[offsets_[b] + s] + rowOffset;
          const int rows = (a == b) ? s + 1 : dims_[a];
          for (int i = 0; i < rows; ++i) column[i] += block(i, s);
        }
      }
    }
  }
  return chi2;
}

Vector NormalEquations::transposedJacobianTimes(const std::vector<Vector>& perFactor) const {
  if (perFactor.size() != linearized_.size()) {
    throw std::invalid_argument("NormalEquations::transposedJacobianTimes: one vector per factor");
  }
  Vector product = Vector::Zero(dimension_);
  for (std::size_t f = 0; f < linearized_.size(); ++f) {
    const LinearizedFactor& lin = linearized_[f];
    if (perFactor[f].size() != lin.whitenedError.size()) {
      throw std::invalid_argument("NormalEquations::transposedJacobianTimes: a vector of the wrong dimension");
    }
    const std::vector<int>& vars = factorVariables_[f];
    for (std::size_t p = 0; p < vars.size(); ++p) {
      product.segment(offsets_[vars[p]], dims_[vars[p]]).noalias() += lin.jacobians[p].transpose() * perFactor[f];
    }
  }
  return product;
}

Values NormalEquations::retract(const Values& values, const Vector& delta) const {
  if (delta.size() != dimension_) throw std::invalid_argument("NormalEquations::retract: wrong step dimension");
  Values result = values;
  for (std::size_t v = 0; v < keys_.size(); ++v) {
    result.update(keys_[v], semslam::retract(values.value(keys_[v]), delta.segment(offsets_[v], dims_[v])));
  }
  return result;
}

std::size_t NormalEquations::memoryBytes() const {
  std::size_t bytes = vectorBytes(keys_) + vectorBytes(offsets_) + vectorBytes(dims_) + graph_.memoryBytes() +
                      nestedVectorBytes(factorVariables_) + nestedVectorBytes(factorBlockRows_) +
                      vectorBytes(linearized_) + vectorBytes(diagonalPositions_) + denseBytes(gradient_);
  for (const LinearizedFactor& f : linearized_) {
    bytes += denseBytes(f.whitenedError) + vectorBytes(f.jacobians);
    for (const Matrix& j : f.jacobians) bytes += denseBytes(j);
  }
  bytes += static_cast<std::size_t>(hessian_.nonZeros()) * (sizeof(double) + sizeof(int)) +
           static_cast<std::size_t>(hessian_.outerSize() + 1) * sizeof(int);
  return bytes;
}

}  // namespace semslam
