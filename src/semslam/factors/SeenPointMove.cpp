#include "semslam/factors/SeenPointMove.h"

namespace semslam {

namespace {

/// The position of a landmark value of dimension D (a point, or an object's pose), if it is one.
template <class Point, class Pose>
std::optional<Point> positionOf(const Value& landmark) {
  if (const Point* point = std::get_if<Point>(&landmark)) return *point;
  if (const Pose* object = std::get_if<Pose>(&landmark)) return object->translation();
  return std::nullopt;
}

template <class Pose, class Point>
std::optional<double> seenPointMoveOf(const Value& poseFrom, const Value& landmarkFrom, const Value& poseTo,
                                      const Value& landmarkTo) {
  const Pose* from = std::get_if<Pose>(&poseFrom);
  const Pose* to = std::get_if<Pose>(&poseTo);
  const std::optional<Point> pointFrom = positionOf<Point, Pose>(landmarkFrom);
  const std::optional<Point> pointTo = positionOf<Point, Pose>(landmarkTo);
  if (!from || !to || !pointFrom || !pointTo) return std::nullopt;
  return seenPointMove(*from, *pointFrom, *to, *pointTo);
}

}  // namespace

std::optional<double> seenPointMove(const Value& poseFrom, const Value& landmarkFrom, const Value& poseTo,
                                    const Value& landmarkTo) {
  if (std::holds_alternative<SE2>(poseFrom))
    return seenPointMoveOf<SE2, Point2>(poseFrom, landmarkFrom, poseTo, landmarkTo);
  return seenPointMoveOf<SE3, Point3>(poseFrom, landmarkFrom, poseTo, landmarkTo);
}

}  // namespace semslam
