#include "semslam/sim/Aliased2dScenario.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <charconv>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>

namespace semslam {

namespace {

constexpr double kPi = std::numbers::pi;

bool sameSE2(const SE2& a, const SE2& b) { return a.x() == b.x() && a.y() == b.y() && a.theta() == b.theta(); }

template <class M>
M diagonal(std::initializer_list<double> values) {
  M m = M::Zero();
  int i = 0;
  for (double v : values) {
    m(i, i) = v;
    ++i;
  }
  return m;
}

[[noreturn]] void fail(const std::string& field, const std::string& problem) {
  throw std::invalid_argument(field + ": " + problem);
}

/// The value in the shortest form that reads back ("1e-09", not to_string's "0.000000").
std::string text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

void checkFinite(const std::string& field, double value) {
  if (!std::isfinite(value)) fail(field, "must be a finite number");
}

void checkPose(const std::string& field, const SE2& pose) {
  checkFinite(field, pose.x());
  checkFinite(field, pose.y());
  checkFinite(field, pose.theta());
}

template <class M>
void checkCovariance(const std::string& field, const M& covariance) {
  if (!covariance.allFinite()) fail(field, "every entry must be a finite number");
  const double scale = covariance.diagonal().cwiseAbs().maxCoeff();
  if ((covariance - covariance.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) fail(field, "not symmetric");
  Eigen::LLT<M> llt(covariance);
  if (llt.info() != Eigen::Success) fail(field, "not positive definite");
}

}  // namespace

bool Aliased2dObject::operator==(const Aliased2dObject& other) const {
  return id == other.id && classIndex == other.classIndex && sameSE2(pose, other.pose);
}

std::string poseMeanName(PoseMean mean) { return mean == PoseMean::Start ? "start" : "sampled"; }

std::string objectMeansName(ObjectMeans means) { return means == ObjectMeans::Sampled ? "sampled" : "truth"; }

bool Aliased2dPriors::operator==(const Aliased2dPriors& other) const {
  return initialPoseCovariance == other.initialPoseCovariance && objectCovariance == other.objectCovariance &&
         poseMean == other.poseMean && objectMeans == other.objectMeans;
}

bool Aliased2dMotion::operator==(const Aliased2dMotion& other) const {
  return covariance == other.covariance && stepLength == other.stepLength && maxTurn == other.maxTurn &&
         arenaCenter == other.arenaCenter && arenaRadius == other.arenaRadius && clearance == other.clearance &&
         timeStep == other.timeStep;
}

bool Aliased2dSensor::operator==(const Aliased2dSensor& other) const {
  return sameSE2(bodyToSensor, other.bodyToSensor) && maxRange == other.maxRange && fieldOfView == other.fieldOfView &&
         covariance == other.covariance;
}

bool Aliased2dScenario::operator==(const Aliased2dScenario& other) const {
  return name == other.name && classes == other.classes && objects == other.objects && sameSE2(start, other.start) &&
         priors == other.priors && motion == other.motion && sensor == other.sensor && alpha == other.alpha &&
         sharpness == other.sharpness;
}

Point2 defaultAliased2dBayShift() { return Point2(6.0, 0.0); }

Aliased2dScenario defaultAliased2dScenario() {
  Aliased2dScenario scenario;
  scenario.name = "aliased2d-default";
  scenario.classes = 2;
  // Three bays, 6 m apart along x. In every bay car "a" is parked at (0, 2) and car "b" at (2.5, -2) relative to
  // the bay; heading -pi/2 faces the aisle (y = 0) from the north side, +pi/2 from the south side.
  //   bay 0: a faces the aisle, b faces the aisle
  //   bay 1: a faces away,      b faces the aisle     (differs from bay 0 in a)
  //   bay 2: a faces the aisle, b faces away          (differs from bay 0 in b, from bay 1 in both)
  const double headings[3][2] = {{-kPi / 2.0, kPi / 2.0}, {kPi / 2.0, kPi / 2.0}, {-kPi / 2.0, -kPi / 2.0}};
  const Point2 shift = defaultAliased2dBayShift();
  for (int bay = 0; bay < 3; ++bay) {
    const Point2 origin = bay * shift;
    scenario.objects.push_back({2 * bay, 0, SE2(origin.x() + 0.0, origin.y() + 2.0, headings[bay][0])});
    scenario.objects.push_back({2 * bay + 1, 0, SE2(origin.x() + 2.5, origin.y() - 2.0, headings[bay][1])});
  }
  scenario.start = SE2(-4.0, 0.0, 0.0);
  // Paper A, sec. V.
  scenario.priors.initialPoseCovariance = diagonal<Matrix3>({100.0, 100.0, 0.04});
  scenario.priors.objectCovariance = diagonal<Matrix3>({0.05, 0.05, 0.5e-3});
  scenario.priors.poseMean = PoseMean::Start;  // paper A, sec. V
  scenario.priors.objectMeans = ObjectMeans::Sampled;
  scenario.motion.covariance = diagonal<Matrix3>({0.75e-3, 0.75e-3, 0.25e-3});
  scenario.motion.stepLength = 1.0;
  scenario.motion.maxTurn = 0.35;
  scenario.motion.arenaCenter = Point2(7.25, 0.0);
  scenario.motion.arenaRadius = 9.0;
  scenario.motion.clearance = 1.0;
  scenario.motion.timeStep = 1.0;
  scenario.sensor.bodyToSensor = SE2();
  scenario.sensor.maxRange = 6.0;
  scenario.sensor.fieldOfView = kPi / 2.0;
  scenario.sensor.covariance = diagonal<Matrix2>({0.1, 0.05});
  scenario.alpha = 0.25;
  scenario.sharpness = 15.0;
  return scenario;
}

void validateAliased2dScenario(const Aliased2dScenario& scenario) {
  if (scenario.classes != 2) {
    fail("classes", "the analytic viewpoint classifier (paper A, eq. 18) is defined for 2 classes, found " +
                        std::to_string(scenario.classes));
  }
  if (scenario.objects.empty()) fail("objects", "at least one object is needed");
  std::set<int> ids;
  for (std::size_t i = 0; i < scenario.objects.size(); ++i) {
    const Aliased2dObject& object = scenario.objects[i];
    const std::string where = "objects[" + std::to_string(i) + "]";
    if (object.id < 0) fail(where + ".id", "must be >= 0, found " + std::to_string(object.id));
    if (!ids.insert(object.id).second) fail(where + ".id", "duplicate id " + std::to_string(object.id));
    if (object.classIndex < 0 || object.classIndex >= scenario.classes) {
      fail(where + ".class",
           "must be in [0, " + std::to_string(scenario.classes - 1) + "], found " + std::to_string(object.classIndex));
    }
    checkPose(where + ".pose", object.pose);
  }
  checkPose("start", scenario.start);
  checkCovariance("priors.initial_pose_covariance", scenario.priors.initialPoseCovariance);
  checkCovariance("priors.object_covariance", scenario.priors.objectCovariance);

  const Aliased2dMotion& motion = scenario.motion;
  checkCovariance("motion.covariance", motion.covariance);
  checkFinite("motion.step_length", motion.stepLength);
  if (!(motion.stepLength > 0.0)) fail("motion.step_length", "must be positive, found " + text(motion.stepLength));
  checkFinite("motion.max_turn", motion.maxTurn);
  if (motion.maxTurn < 0.0 || motion.maxTurn > kPi) {
    fail("motion.max_turn", "must be in [0, pi], found " + text(motion.maxTurn));
  }
  checkFinite("motion.arena.center", motion.arenaCenter.x());
  checkFinite("motion.arena.center", motion.arenaCenter.y());
  checkFinite("motion.arena.radius", motion.arenaRadius);
  if (!(motion.arenaRadius > 0.0)) fail("motion.arena.radius", "must be positive, found " + text(motion.arenaRadius));
  checkFinite("motion.clearance", motion.clearance);
  if (motion.clearance < 0.0) fail("motion.clearance", "must be >= 0, found " + text(motion.clearance));
  // Values the motion model could only ignore: an arena smaller than one step is overstepped every step, and
  // no pose inside an arena keeps a clearance as wide as the arena.
  if (motion.arenaRadius < motion.stepLength) {
    fail("motion.arena.radius", "must be at least motion.step_length (" + text(motion.stepLength) + "), found " +
                                    text(motion.arenaRadius));
  }
  if (motion.clearance >= motion.arenaRadius) {
    fail("motion.clearance", "must be below motion.arena.radius (" + text(motion.arenaRadius) + "), found " +
                                 text(motion.clearance));
  }
  checkFinite("motion.time_step", motion.timeStep);
  if (!(motion.timeStep > 0.0)) fail("motion.time_step", "must be positive, found " + text(motion.timeStep));

  const Aliased2dSensor& sensor = scenario.sensor;
  checkPose("sensor.body_to_sensor", sensor.bodyToSensor);
  checkFinite("sensor.max_range", sensor.maxRange);
  if (sensor.maxRange < 0.0) fail("sensor.max_range", "must be >= 0 (0: unlimited), found " + text(sensor.maxRange));
  checkFinite("sensor.field_of_view", sensor.fieldOfView);
  if (sensor.fieldOfView < 0.0 || sensor.fieldOfView > 2.0 * kPi) {
    fail("sensor.field_of_view", "must be in [0, 2 pi] radians (0: all around), found " + text(sensor.fieldOfView));
  }
  checkCovariance("sensor.covariance", sensor.covariance);

  checkFinite("classifier.alpha", scenario.alpha);
  if (scenario.alpha < 0.0 || scenario.alpha > 1.0) {
    fail("classifier.alpha", "must be in [0, 1], found " + text(scenario.alpha));
  }
  checkFinite("classifier.sharpness", scenario.sharpness);
  if (!(scenario.sharpness > 0.0)) {
    fail("classifier.sharpness", "must be positive, found " + text(scenario.sharpness));
  }
}

}  // namespace semslam
