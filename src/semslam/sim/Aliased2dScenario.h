#pragma once
// Aliased2dScenario: paper A's perceptually aliased 2D scenario (sec. V) as data: the objects (poses and
// classes), the fixed start, the priors, the motion and its noise, the sensor, the classifier model, and the
// policy that samples ground-truth tracks. The simulator (Aliased2dSimulator.h) turns it into measurement logs;
// ScenarioFile.h reads and writes it as JSON. docs/simulators.md specifies every field, the default layout and why
// it is aliased.
//
// Units: metres, radians, seconds. Poses are SE2 (x, y, θ); covariances are over the tangent of the right
// perturbation, translation first, as in the measurement log.
//
// The default (defaultAliased2dScenario, equal to data/scenarios/aliased2d_default.json) is a parking aisle:
// three bays 6 m apart along x, each holding two cars (paper A's mirror-symmetric objects) at the same
// positions relative to the bay, so the range-bearing pattern of one bay is that of the next, translated by
// 6 m; the cars of different bays are parked facing different ways, which the viewpoint-dependent classifier
// (A, eq. 18) can tell apart. Priors, noise and classifier are the paper's.

#include <string>
#include <vector>

#include "semslam/geometry/SE2.h"

namespace semslam {

struct Aliased2dObject {
  int id = 0;
  int classIndex = 0;  // the true class (0-based; the paper's class 1 is 0)
  SE2 pose;
  bool operator==(const Aliased2dObject& other) const;
};

/// Where the estimator's prior mean of the first pose comes from.
enum class PoseMean {
  Start,    // the true start, the same for every track: paper A, sec. V ("in all paths, the starting position is
            // identical"); the prior's covariance Σ_p still says the robot does not know it
  Sampled,  // start · Exp(δ), δ ~ N(0, Σ_p): the start is a draw from the stated prior (consistent), a different
            // prior per track, typically metres off
};

/// Where the estimator's prior means of the objects come from.
enum class ObjectMeans {
  Sampled,  // truth · Exp(δ), δ ~ N(0, Σ_o): the map is as uncertain as its prior says (consistent)
  Truth,    // the truth exactly: an optimistic map, for debugging and figures (NEES then falls below its band)
};

/// The scenario file's names: "start" | "sampled", and "sampled" | "truth".
std::string poseMeanName(PoseMean mean);
std::string objectMeansName(ObjectMeans means);

struct Aliased2dPriors {
  Matrix3 initialPoseCovariance;  // Σ_p of the first pose
  Matrix3 objectCovariance;       // Σ_o of every object pose (the uncertain map)
  PoseMean poseMean = PoseMean::Start;
  ObjectMeans objectMeans = ObjectMeans::Sampled;
  bool operator==(const Aliased2dPriors& other) const;
};

/// The motion model and the random policy that samples ground-truth tracks (docs/simulators.md).
struct Aliased2dMotion {
  Matrix3 covariance;       // Σ_w: x_{k+1} = x_k · a_k · Exp(w), w ~ N(0, Σ_w)
  double stepLength = 1.0;  // metres travelled per step (along an arc)
  double maxTurn = 0.35;    // the heading change per step is uniform in [−maxTurn, maxTurn] ...
  Point2 arenaCenter = Point2::Zero();
  double arenaRadius = 9.0;  // ... except outside this circle, where the robot turns back toward its centre
  double clearance = 1.0;    // metres: a track keeps at least this far from every object (robots avoid cars)
  double timeStep = 1.0;     // seconds between steps
  bool operator==(const Aliased2dMotion& other) const;
};

struct Aliased2dSensor {
  SE2 bodyToSensor;
  double maxRange = 6.0;     // metres; 0: unlimited
  double fieldOfView = 0.0;  // full angle, radians; 0: all around
  Matrix2 covariance;        // Σ_v of (range, bearing)
  bool operator==(const Aliased2dSensor& other) const;
};

struct Aliased2dScenario {
  std::string name;
  int classes = 2;  // M; the analytic classifier model needs 2
  std::vector<Aliased2dObject> objects;
  SE2 start;  // the true first pose of every track
  Aliased2dPriors priors;
  Aliased2dMotion motion;
  Aliased2dSensor sensor;
  double alpha = 0.25;      // classifier viewpoint dependency (A, eq. 18)
  double sharpness = 15.0;  // classifier K: Σ_c = (RᵀR)⁻¹, R = K [[1, −0.5], [0, 1]]
  bool operator==(const Aliased2dScenario& other) const;
};

/// The built-in default (docs/simulators.md, "The default layout").
Aliased2dScenario defaultAliased2dScenario();

/// The translation that maps bay i of the default layout onto bay i + 1 (6 m along x).
Point2 defaultAliased2dBayShift();

/// Throws std::invalid_argument naming the first field that breaks a rule of docs/simulators.md: at least one
/// object, ids unique and ≥ 0, classes == 2 and object classes in [0, classes), covariances symmetric positive
/// definite and finite, stepLength > 0, maxTurn in [0, π], arenaRadius > 0, clearance ≥ 0, timeStep > 0,
/// maxRange ≥ 0,
/// fieldOfView in [0, 2π], alpha in [0, 1], sharpness > 0, every number finite.
void validateAliased2dScenario(const Aliased2dScenario& scenario);

}  // namespace semslam
