#include "semslam/models/ValueConversions.h"

#include <stdexcept>

namespace semslam {

Pose toPose(const Value& value) {
  if (const auto* se2 = std::get_if<SE2>(&value)) return *se2;
  if (const auto* se3 = std::get_if<SE3>(&value)) return *se3;
  throw std::logic_error("a robot pose must be an SE2 or an SE3");
}

LandmarkState toLandmarkState(const Value& value) {
  return std::visit(
      [](const auto& v) -> LandmarkState {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, SO2> || std::is_same_v<V, SO3>) {
          throw std::logic_error("a landmark cannot be a rotation");
        } else {
          return v;
        }
      },
      value);
}

}  // namespace semslam
