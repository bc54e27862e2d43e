#pragma once
// Values: the current estimate of every variable of a factor graph, by key.
//
// A value is one of the manifold types of the geometry layer (points, SO2, SE2, SO3, SE3). Each has a tangent
// dimension and is perturbed by Manifold<T>::retract (right perturbation, translation-first tangent).
// Iteration is in increasing key order, so everything built from a Values is deterministic.

#include <map>
#include <string>
#include <variant>

#include "semslam/core/MemoryBytes.h"
#include <vector>

#include "semslam/geometry/Manifold.h"
#include "semslam/geometry/SE2.h"
#include "semslam/geometry/SE3.h"
#include "semslam/geometry/SO2.h"
#include "semslam/geometry/SO3.h"
#include "semslam/graph/Key.h"

namespace semslam {

using Value = std::variant<Point2, Point3, SO2, SE2, SO3, SE3>;

/// Tangent dimension of a value.
int dimension(const Value& value);

/// value ⊕ delta, where delta has the value's tangent dimension.
Value retract(const Value& value, const Eigen::Ref<const Vector>& delta);

/// Name of the value's type ("SE2", "Point3", ...), for messages.
std::string typeName(const Value& value);

class Values {
 public:
  using Map = std::map<Key, Value>;
  using const_iterator = Map::const_iterator;

  /// Adds a new variable; throws std::invalid_argument if the key exists.
  void insert(Key key, const Value& value);
  /// Adds every variable of `other`; throws if any key exists.
  void insert(const Values& other);
  /// Replaces the value of an existing variable; throws std::out_of_range if the key is absent.
  void update(Key key, const Value& value);
  void insertOrAssign(Key key, const Value& value) { values_.insert_or_assign(key, value); }
  void erase(Key key);

  bool exists(Key key) const { return values_.count(key) != 0; }
  std::size_t size() const { return values_.size(); }
  /// Heap bytes held (core/MemoryBytes.h).
  std::size_t memoryBytes() const { return mapBytes(values_); }
  bool empty() const { return values_.empty(); }

  /// The variable as type T; throws std::out_of_range if absent or of another type.
  template <class T>
  const T& at(Key key) const {
    const Value& stored = value(key);
    if (const T* typed = std::get_if<T>(&stored)) return *typed;
    throwWrongType(key, stored);
  }
  const Value& value(Key key) const;

  /// Sum of the tangent dimensions of all variables.
  int totalDimension() const;
  std::vector<Key> keys() const;

  const_iterator begin() const { return values_.begin(); }
  const_iterator end() const { return values_.end(); }

 private:
  [[noreturn]] static void throwWrongType(Key key, const Value& stored);
  Map values_;
};

}  // namespace semslam
