#include "semslam/io/PoseGraphBuilder.h"

#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "semslam/core/InputError.h"

namespace semslam {

namespace {

const char* dimensionName(int dimension) { return dimension == 3 ? "3D" : "2D"; }

/// The squared norm of a vertex's position (0 for a rotation): infinite when its coordinates are too large to
/// square, and every chi2 and gradient through it would overflow.
double squaredPosition(const Value& value) {
  return std::visit(
      [](const auto& v) -> double {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, SE2> || std::is_same_v<T, SE3>) return v.translation().squaredNorm();
        if constexpr (std::is_same_v<T, Point2> || std::is_same_v<T, Point3>) return v.squaredNorm();
        return 0.0;
      },
      value);
}

bool finite(const LinearizedFactor& linearized) {
  if (!std::isfinite(linearized.chi2) || !linearized.whitenedError.allFinite()) return false;
  for (const Matrix& jacobian : linearized.jacobians) {
    if (!jacobian.allFinite() || !(jacobian.transpose() * linearized.whitenedError).allFinite()) return false;
  }
  return true;
}

}  // namespace

void PoseGraphBuilder::addFactor(FactorPtr factor) {
  for (const Key key : factor->keys()) {
    if (!file_.initial.exists(key)) {  // not placed yet: checked once the optimiser sees it
      file_.factors.add(std::move(factor));
      return;
    }
  }
  LinearizedFactor linearized;
  factor->linearize(file_.initial, linearized);
  if (!finite(linearized)) {
    reader_.fail(std::string(reader_.tag()) +
                 ": the edge's error or gradient at the initial values overflows (not finite): a measurement, "
                 "information entry or vertex is too large");
  }
  file_.factors.add(std::move(factor));
}

void PoseGraphBuilder::requireDimension(int dimension) {
  if (dimension_ == 0) {
    dimension_ = dimension;
    dimensionLine_ = reader_.lineNumber();
    file_.dimension = dimension;
  } else if (dimension_ != dimension) {
    reader_.fail(std::string(dimensionName(dimension)) + " record " + std::string(reader_.tag()) +
                 " in a file whose records are " + dimensionName(dimension_) + " (since line " +
                 std::to_string(dimensionLine_) + "): 2D and 3D records cannot be mixed");
  }
}

void PoseGraphBuilder::addVertex(Key key, const Value& value) {
  const auto [it, inserted] = declaredAt_.emplace(key, reader_.lineNumber());
  if (!inserted) {
    reader_.fail("duplicate vertex " + keyToString(key) + ": already declared at line " + std::to_string(it->second));
  }
  if (!std::isfinite(squaredPosition(value))) {
    reader_.fail("vertex " + keyToString(key) +
                 ": coordinates too large (their squares overflow a double; every error through them would too)");
  }
  file_.initial.insert(key, value);
  if (!havePose_ && (std::holds_alternative<SE2>(value) || std::holds_alternative<SE3>(value))) {
    havePose_ = true;
    file_.firstPose = key;
  }
}

const Value& PoseGraphBuilder::declaredVertex(std::size_t field, Key key) const {
  if (!file_.initial.exists(key)) {
    std::string problem =
        reader_.describe(field) + " names vertex " + keyToString(key) + ", which is not declared on an earlier line";
    if (file_.initial.empty()) {
      problem += " (no vertex is declared before this line; iSAM files have no vertex records: read them as isam)";
    }
    reader_.fail(problem);
  }
  return file_.initial.value(key);
}

void PoseGraphBuilder::wrongType(std::size_t field, Key key, const Value& value, const char* expected) const {
  reader_.fail(reader_.describe(field) + " names vertex " + keyToString(key) + " of type " + typeName(value) +
               ", expected " + expected);
}

void PoseGraphBuilder::requireDistinct(Key from, Key to) const {
  if (from == to) reader_.fail(std::string(reader_.tag()) + " connects vertex " + keyToString(from) + " to itself");
}

void PoseGraphBuilder::addEquivalence(Key first, Key second) {
  declaredVertex(1, first);
  declaredVertex(2, second);
  requireDistinct(first, second);
  file_.equivalences.emplace_back(first, second);
}

void PoseGraphBuilder::addFixed(std::size_t field, Key key) {
  declaredVertex(field, key);
  if (fixed_.insert(key).second) file_.fixed.push_back(key);
}

SharedNoiseModel PoseGraphBuilder::fromInformation(const Matrix& information) const {
  try {
    return NoiseModel::fromInformation(information);
  } catch (const std::invalid_argument& error) {
    reader_.fail(std::string(reader_.tag()) + ": " + error.what());
  }
}

SharedNoiseModel PoseGraphBuilder::fromSqrtInformation(const Matrix& sqrtInformation) const {
  try {
    return NoiseModel::fromSqrtInformation(sqrtInformation);
  } catch (const std::invalid_argument& error) {
    reader_.fail(std::string(reader_.tag()) + ": " + error.what());
  }
}

PoseGraphFile PoseGraphBuilder::finish() {
  if (reader_.recordCount() == 0) {
    throw InputError(reader_.path(), 0, "no records: the file is empty or holds only comments and blank lines");
  }
  if (!havePose_) throw InputError(reader_.path(), 0, "no pose in the file");
  return std::move(file_);
}

}  // namespace semslam
