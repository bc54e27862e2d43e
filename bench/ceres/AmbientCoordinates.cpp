#include "AmbientCoordinates.h"

#include <stdexcept>
#include <type_traits>
#include <utility>

namespace semslam::bench {

namespace {

template <class T>
void encode(const T& value, double* out) {
  if constexpr (std::is_same_v<T, Point2> || std::is_same_v<T, Point3>) {
    Eigen::Map<T>{out} = value;
  } else if constexpr (std::is_same_v<T, SO2>) {
    out[0] = value.theta();
  } else if constexpr (std::is_same_v<T, SE2>) {
    out[0] = value.x();
    out[1] = value.y();
    out[2] = value.theta();
  } else if constexpr (std::is_same_v<T, SO3>) {
    Eigen::Map<Vector3>{out} = SO3::Log(value);
  } else {
    static_assert(std::is_same_v<T, SE3>);
    Eigen::Map<Vector3>{out} = value.translation();
    Eigen::Map<Vector3>{out + 3} = SO3::Log(value.rotation());
  }
}

template <class T>
T decode(const double* in) {
  if constexpr (std::is_same_v<T, Point2> || std::is_same_v<T, Point3>) {
    return T(Eigen::Map<const T>(in));
  } else if constexpr (std::is_same_v<T, SO2>) {
    return SO2(in[0]);
  } else if constexpr (std::is_same_v<T, SE2>) {
    return SE2(in[0], in[1], in[2]);
  } else if constexpr (std::is_same_v<T, SO3>) {
    return SO3::Exp(Vector3(Eigen::Map<const Vector3>(in)));
  } else {
    static_assert(std::is_same_v<T, SE3>);
    return SE3(SO3::Exp(Vector3(Eigen::Map<const Vector3>(in + 3))), Point3(Eigen::Map<const Vector3>(in)));
  }
}

template <std::size_t... I>
Value decodeKind(ValueKind kind, const double* in, std::index_sequence<I...>) {
  Value result;
  const bool found = ((kind == I ? (result = decode<std::variant_alternative_t<I, Value>>(in), true) : false) || ...);
  if (!found) throw std::invalid_argument("fromAmbient: unknown value kind");
  return result;
}

template <std::size_t... I>
int sizeOfKind(ValueKind kind, std::index_sequence<I...>) {
  int size = 0;
  const bool found =
      ((kind == I ? (size = Manifold<std::variant_alternative_t<I, Value>>::kDim, true) : false) || ...);
  if (!found) throw std::invalid_argument("ambientSize: unknown value kind");
  return size;
}

}  // namespace

int ambientSize(ValueKind kind) {
  return sizeOfKind(kind, std::make_index_sequence<std::variant_size_v<Value>>{});
}

void toAmbient(const Value& value, double* ambient) {
  std::visit([ambient](const auto& v) { encode(v, ambient); }, value);
}

Value fromAmbient(ValueKind kind, const double* ambient) {
  return decodeKind(kind, ambient, std::make_index_sequence<std::variant_size_v<Value>>{});
}

}  // namespace semslam::bench
