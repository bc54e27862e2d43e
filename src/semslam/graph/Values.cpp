#include "semslam/graph/Values.h"

#include <stdexcept>

namespace semslam {

namespace {
template <class>
constexpr bool kAlwaysFalse = false;
}  // namespace

int dimension(const Value& value) {
  return std::visit([](const auto& v) { return Manifold<std::decay_t<decltype(v)>>::kDim; }, value);
}

Value retract(const Value& value, const Eigen::Ref<const Vector>& delta) {
  return std::visit(
      [&delta](const auto& v) -> Value { return Manifold<std::decay_t<decltype(v)>>::retract(v, delta); }, value);
}

std::string typeName(const Value& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Point2>) return "Point2";
        else if constexpr (std::is_same_v<T, Point3>) return "Point3";
        else if constexpr (std::is_same_v<T, SO2>) return "SO2";
        else if constexpr (std::is_same_v<T, SE2>) return "SE2";
        else if constexpr (std::is_same_v<T, SO3>) return "SO3";
        else if constexpr (std::is_same_v<T, SE3>) return "SE3";
        else static_assert(kAlwaysFalse<T>, "unnamed value type");
      },
      value);
}

void Values::insert(Key key, const Value& value) {
  if (!values_.emplace(key, value).second) {
    throw std::invalid_argument("Values::insert: variable " + keyToString(key) + " already exists");
  }
}

void Values::insert(const Values& other) {
  for (const auto& [key, value] : other) insert(key, value);
}

void Values::update(Key key, const Value& value) {
  auto it = values_.find(key);
  if (it == values_.end()) throw std::out_of_range("Values::update: no variable " + keyToString(key));
  it->second = value;
}

void Values::erase(Key key) {
  if (values_.erase(key) == 0) throw std::out_of_range("Values::erase: no variable " + keyToString(key));
}

const Value& Values::value(Key key) const {
  auto it = values_.find(key);
  if (it == values_.end()) throw std::out_of_range("no variable " + keyToString(key));
  return it->second;
}

int Values::totalDimension() const {
  int total = 0;
  for (const auto& [key, value] : values_) total += dimension(value);
  return total;
}

std::vector<Key> Values::keys() const {
  std::vector<Key> result;
  result.reserve(values_.size());
  for (const auto& entry : values_) result.push_back(entry.first);
  return result;
}

void Values::throwWrongType(Key key, const Value& stored) {
  throw std::out_of_range("variable " + keyToString(key) + " is a " + typeName(stored) +
                          ", not the type the factor expects");
}

}  // namespace semslam
