#pragma once
// LogPerturbation: the two perturbations of paper B's robustness study (sec. V-A, Fig. 3) applied to a
// measurement log: extra odometry noise and class labels redrawn at a chosen misclassification rate.
// docs/robustness-study.md describes the study; the decisions here are repeated there.
//
// Odometry noise (scale s ≥ 0)
//   Baseline per second of travel (paper B's values are lost from our copy): σ_x = σ_y = 0.02 m, σ_θ = 0.01 rad.
//   For step k with duration dt = t_k − t_{k−1} (1 s for every step when the log has no times, i.e. all its times
//   are equal), the added noise is
//       δ ~ N(0, Q),  Q = diag((s σ_x)², (s σ_y)², (s σ_θ)²) · dt           (2D tangent: x, y, θ)
//       Q = diag((s σ_x)², (s σ_y)², (s σ_x)², (s σ_θ)², (s σ_θ)², (s σ_θ)²) · dt   (3D tangent: x, y, z, rx, ry, rz)
//   (3D: the x/y sigma is used for all three translation axes, the yaw sigma for all three rotation axes), applied
//   by right perturbation, increment ← increment · Exp(δ), and the increment's covariance becomes Σ + Q, so the
//   methods see noise that is consistent with their model. δ = s √dt diag(σ) n with n standard normal: every
//   scale uses the same draw n (common random numbers), and n is drawn for every step whatever s is. s = 0 leaves
//   the log bit-identical.
//
// Misclassification (rate p ∈ [0, 1))
//   Every detection of a Label log gets a new label: for a detection of landmark l, of true class c, the label is
//   drawn from row c of the symmetric confusion matrix C = (1 − p) I + p/(M − 1)(11ᵀ − I)
//   (CategoricalClassifierModel): with uniforms u₁, u₂ per detection, the label is c when u₁ ≥ p and otherwise
//   the ⌊u₂ (M − 1)⌋-th of the other classes. This has exactly the distribution of row c, and because u₁, u₂ do
//   not depend on p, the detections misclassified at rate p are a subset of those misclassified at any p' > p
//   (common random numbers across levels). Clutter (truth kNotALandmark) gets the uniform label ⌊u₂ M⌋.
//   The true class of landmark l is header.landmarkTruth's classIndex for l, or l mod M when the log has no class
//   for it (the converters' rule: "a landmark's class is its id mod M", paper B sec. V-A). Logs whose semantic
//   part is Probabilities or Scores become Label logs. The header's classifier becomes Categorical(p) (table
//   cleared), so every method uses the matching model. Requires M ≥ 2 and a truth id on every detection.
//
// Invariants: every function returns a new log and throws std::invalid_argument for bad arguments (negative or
// non-finite scale, p outside [0, 1), a log that cannot be perturbed as asked), naming the problem.

#include <cstdint>
#include <random>

#include "semslam/models/MeasurementLog.h"

namespace semslam {

/// The baseline added-noise standard deviations, per second of travel.
struct OdometryNoiseBaseline {
  double sigmaX = 0.02;      ///< m (also y; 3D: also z)
  double sigmaY = 0.02;      ///< m
  double sigmaTheta = 0.01;  ///< rad (3D: every rotation axis)
};

/// Q for one step: the added noise's covariance (3x3 for dimension 2, 6x6 for dimension 3).
Matrix addedOdometryCovariance(int dimension, double scale, double dt, const OdometryNoiseBaseline& baseline = {});

/// The duration of every step (element 0 unused, 0): t_k − t_{k−1}, or 1 s each when all times are equal. Throws
/// when the times decrease or repeat (but are not all equal).
std::vector<double> stepDurations(const MeasurementLog& log);

/// The log with odometry noise of scale s added (see above); exactly d standardNormal() draws from `rng` per step
/// with odometry (d = 3 or 6), whatever the scale.
MeasurementLog addOdometryNoise(const MeasurementLog& log, double scale, std::mt19937& rng,
                                const OdometryNoiseBaseline& baseline = {});

/// The true class of landmark `landmarkId` (see above).
int trueLandmarkClass(const LogHeader& header, int landmarkId);

/// The log with every detection's label redrawn at misclassification rate p (see above); two uniform01() draws per
/// detection, whatever p.
MeasurementLog redrawLabels(const MeasurementLog& log, double misclassification, std::mt19937& rng);

/// One cell's perturbation: noise of `scale` from the stream (seed, noise) and labels at rate p from the stream
/// (seed, labels); `maxSteps` > 0 truncates the log to its first maxSteps steps first; the model floor below.
struct LogPerturbation {
  double odometryNoiseScale = 0.0;
  double misclassification = 0.1;
  int maxSteps = 0;
  OdometryNoiseBaseline baseline;
  /// The header's model rate becomes max(p, modelMisclassificationFloor) (labels are still drawn at p); 0, the
  /// default, gives the methods the exact rate (at p = 0 a label then rules classes out exactly, which the
  /// pipeline handles: such a landmark is no candidate).
  double modelMisclassificationFloor = 0.0;
};

/// The streams of one study seed: std::mt19937 through std::seed_seq with the words
/// (seed mod 2³², seed div 2³², stream, 0x5714d7). Stream 1: odometry noise, 2: labels.
std::mt19937 perturbationStream(std::uint64_t seed, std::uint32_t stream);

/// The perturbed log of one cell; the same (log, perturbation, seed) gives the same log.
MeasurementLog perturbLog(const MeasurementLog& log, const LogPerturbation& perturbation, std::uint64_t seed);

}  // namespace semslam
