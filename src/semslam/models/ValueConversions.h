#pragma once
// A graph variable (graph/Values.h's Value) as the log's and the result's types (models/MeasurementLog.h): a robot
// pose (SE2 or SE3) or a landmark state (Point2, Point3, SE2 or SE3). Both estimators fill their RunResult through
// these. A rotation (SO2, SO3) is neither: std::logic_error.

#include "semslam/graph/Values.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam {

Pose toPose(const Value& value);
LandmarkState toLandmarkState(const Value& value);

}  // namespace semslam
