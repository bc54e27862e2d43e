#pragma once
// PoseGraphBuilder: assembles a PoseGraphFile from the records of a LineReader and enforces what the g2o, TORO
// and iSAM readers share. Every problem is thrown as InputError at the reader's current record:
//   a vertex declared twice (naming the line of the first declaration), an edge or FIX naming a vertex not
//   declared on an earlier line or of the wrong type, an edge from a vertex to itself, 2D and 3D records in one
//   file, a vertex whose coordinates cannot be squared, an edge whose error or gradient at the initial values
//   overflows, an information or square-root information matrix the noise model rejects, a file without records
//   or without a pose.

#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>

#include "semslam/graph/NoiseModel.h"
#include "semslam/io/LineReader.h"
#include "semslam/io/PoseGraphFile.h"

namespace semslam {

class PoseGraphBuilder {
 public:
  explicit PoseGraphBuilder(LineReader& reader) : reader_(reader) {}

  /// Declares that the current record is 2D or 3D; a file must not mix them.
  void requireDimension(int dimension);

  /// Adds a vertex declared by the current record. The first SE2/SE3 vertex becomes firstPose.
  void addVertex(Key key, const Value& value);
  bool hasVertex(Key key) const { return file_.initial.exists(key); }

  /// The vertex named by value `field` of the current record, which must be declared and hold a T.
  template <class T>
  const T& vertex(std::size_t field, Key key) const {
    const Value& value = declaredVertex(field, key);
    if (const T* typed = std::get_if<T>(&value)) return *typed;
    wrongType(field, key, value, vertexTypeName<T>());
  }

  /// Fails unless the two vertices of an edge differ.
  void requireDistinct(Key from, Key to) const;

  /// Adds the current record's factor; fails when its error, Jacobians or gradient at the initial values are not
  /// finite (finite but huge numbers whose products overflow).
  void addFactor(FactorPtr factor);
  /// Records a TORO equivalence between two declared, distinct vertices.
  void addEquivalence(Key first, Key second);
  /// Adds a FIX vertex (which must be declared); a vertex fixed twice is listed once.
  void addFixed(std::size_t field, Key key);

  /// The Gaussian with this information / square-root information; a rejected matrix is an InputError.
  SharedNoiseModel fromInformation(const Matrix& information) const;
  SharedNoiseModel fromSqrtInformation(const Matrix& sqrtInformation) const;

  /// The finished file; fails for a file without records or without a pose.
  PoseGraphFile finish();

 private:
  const Value& declaredVertex(std::size_t field, Key key) const;
  [[noreturn]] void wrongType(std::size_t field, Key key, const Value& value, const char* expected) const;

  template <class T>
  static constexpr const char* vertexTypeName() {
    if constexpr (std::is_same_v<T, SE2>) return "SE2";
    if constexpr (std::is_same_v<T, SE3>) return "SE3";
    if constexpr (std::is_same_v<T, Point2>) return "Point2";
    if constexpr (std::is_same_v<T, Point3>) return "Point3";
    return "variable";
  }

  LineReader& reader_;
  PoseGraphFile file_;
  bool havePose_ = false;
  int dimension_ = 0;
  std::size_t dimensionLine_ = 0;
  std::unordered_map<Key, std::size_t> declaredAt_;
  std::unordered_set<Key> fixed_;
};

}  // namespace semslam
