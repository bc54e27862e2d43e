#pragma once
// SemanticSimulator: paper B-style semantic SLAM runs (sec. V): a robot moves along a true trajectory (2D or 3D,
// generated or read from a file), point landmarks with classes stand around its path, and every step brings
// noisy odometry and the detections of the landmarks inside the sensor's field of view, each with a class label
// that is wrong with probability p, plus false detections (clutter). docs/simulators.md describes it in full.
//
// Given the truth x_0..x_K (SimTrajectory) and a user seed (every quantity from its own SimulationStreams
// stream, track 0):
//   landmarks  n = options.landmarks, or round(density · path length) when that is 0 (at least 1). Landmark i
//              (id i) stands beside the path: at an arc length s = u L along the true positions (L the path
//              length), on the left or right (u < ½: left) at a lateral distance uniform in
//              [minOffset, maxOffset] along the body y axis of the pose starting that segment, and in 3D at a
//              height uniform in [minHeight, maxHeight] along its z axis; class uniform in [0, M).
//   odometry   true increment Δ_k = x_{k−1}⁻¹ x_k; reported Δ_k · Exp(s w), w ~ N(0, Σ_base) (so noise of
//              covariance s² Σ_base, s = odomNoiseScale, and the same noise pattern at every scale), with the
//              covariance c² Σ_base, c = odomCovarianceScale (default: s, or 1e-3 when s = 0, since a log needs
//              a positive-definite covariance). Σ_base is baselineOdometryCovariance(dimension).
//   detections for every landmark visible from x_k (VisibilityModel2/3), in id order: kept with probability
//              detectionProbability; geometry h(x_k, l) + v, v ~ N(0, Σ_v) (MeasurementSampling.h), Σ_v =
//              diag(σ_r², σ_b²[, σ_e²]); label drawn from row c of the confusion matrix (1 − p on the diagonal,
//              p/(M − 1) elsewhere: CategoricalClassifierModel); truth the landmark id.
//   clutter    Poisson(λ) false detections per step (Clutter.h): uniform in the field of view up to the maximum
//              range, uniform random label, truth "not a landmark", covariance Σ_v.
//   order      each step's detections by increasing measured bearing. Step 0 has detections too.
// Header: dimension, classes M, semantic "label", classifier categorical(p), sensor range-bearing (2D) or
// range-bearing-elevation (3D) with the maximum range and field of view, point landmarks with their truth, and
// an initial pose prior at the true first pose with covariance 1e-6 I (the gauge: the map is built from a known
// origin, as in paper B's experiments).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "semslam/models/MeasurementLog.h"
#include "semslam/sim/SimTrajectory.h"

namespace semslam {

struct SemanticSimOptions {
  int classes = 2;
  int landmarks = 0;             // 0: from landmarkDensity
  double landmarkDensity = 0.1;  // landmarks per metre of path
  double minOffset = 1.0;        // lateral distance from the path, metres
  double maxOffset = 6.0;
  double minHeight = -0.5;  // 3D: height above the path, metres
  double maxHeight = 2.0;
  double maxRange = 10.0;                   // metres; 0: unlimited (then no clutter)
  double fieldOfView = 1.5707963267948966;  // full angle, radians; 0 or 2π: all around
  double rangeSigma = 0.1;                  // metres
  double bearingSigma = 0.02;               // radians
  double elevationSigma = 0.02;             // radians (3D)
  double detectionProbability = 1.0;
  double misclassification = 0.1;             // p
  double odomNoiseScale = 1.0;                // s
  std::optional<double> odomCovarianceScale;  // c; default s (1e-3 when s = 0)
  double clutter = 0.0;                       // λ, false detections per step
  std::string description;                    // where the trajectory came from, for the header's source text
};

/// Σ_base, the baseline odometry noise per step in the robot frame (docs/simulators.md):
///   2D: diag(0.02², 0.01², 0.005²)                          (x, y in m; yaw in rad)
///   3D: diag(0.02², 0.01², 0.01², 0.002², 0.002², 0.005²)   (x, y, z in m; roll, pitch, yaw rotation in rad)
Matrix baselineOdometryCovariance(int dimension);

/// The most landmarks a run places (given, or from the density): the simulator holds them all.
inline constexpr int kMaxSimulatedLandmarks = 1000000;

/// Throws std::invalid_argument naming the first invalid option: classes ≥ 1; landmarks in
/// [0, kMaxSimulatedLandmarks]; density ≥ 0; 0 ≤ minOffset ≤ maxOffset; minHeight ≤ maxHeight; maxRange ≥ 0;
/// fieldOfView in [0, 2π]; sigmas > 0; detectionProbability in [0, 1]; misclassification in [0, 1) and 0 when M = 1; odomNoiseScale ≥ 0;
/// odomCovarianceScale > 0; clutter in [0, 100] and, when positive, a positive maxRange; all finite.
void validateSemanticSimOptions(const SemanticSimOptions& options);

/// The log of one run. Throws std::invalid_argument for invalid options or a trajectory with fewer than two
/// poses, mixed pose types or times that do not increase.
/// `progress`, when set, is called after each step with (steps done, steps in all).
MeasurementLog simulateSemantic(const SimTrajectory& truth, const SemanticSimOptions& options, std::uint64_t seed,
                                const std::function<void(int done, int total)>& progress = {});

}  // namespace semslam
