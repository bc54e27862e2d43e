#pragma once
// The settings every dataset converter takes, and what a conversion reports.
//
// A converter reads a real dataset into a MeasurementLog (models/MeasurementLog.h) in four stages, the same for
// every dataset (docs/datasets.md):
//   1. the dataset's own records become time steps: odometry with its covariance, detections with geometry,
//      covariance and their true landmark id (kNotALandmark for clutter), the true pose where known;
//   2. keyframing (keyframePeriod > 0) keeps one step per period and composes the odometry in between; the
//      detections of the steps it drops are dropped and counted (ConversionStats::detectionsDroppedByKeyframing);
//   3. maxSteps keeps the first N steps of the result;
//   4. the header gets its classes (class of landmark id = id mod M), the detections their sampled labels
//      (ClassLabels.h), the initial pose prior and, with mapPriorSigma > 0, the landmark ground truth as a prior map.
// Identities go only into the ground truth (`truth`), never into the input a method reads.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "semslam/io/convert/ClassLabels.h"

namespace semslam {

/// KITTI tracking (KittiTrackingConverter.h): the settings only it reads.
struct KittiTrackingOptions {
  /// The sequence number (label_02/NNNN.txt); required (−1: not given).
  int sequence = -1;
  /// Detections with a score below the threshold of their class (Car, Pedestrian, Cyclist) are dropped;
  /// std::nullopt: the class's default (KittiTrackingConverter.h).
  std::array<std::optional<double>, 3> scoreThresholds;
  /// Odometry: ORB-SLAM3's relative motion with its stated covariance, or that plus seeded Gaussian noise.
  enum class Odometry { OrbSlam, Noisy } odometry = Odometry::OrbSlam;
  /// Noisy odometry: the noise is K times the stated ORB-SLAM3 standard deviations (std::nullopt: 1).
  std::optional<double> odometryNoiseScale;
  /// > 0: detections farther than this (metres) are dropped, and the sensor's max_range is set to it.
  double maxRange = 0.0;
  /// A 3x3 table of counts (rows: true Car, Pedestrian, Cyclist; columns: detected) from which the categorical
  /// misclassification rate is estimated instead of from this sequence's own matches; empty: the sequence's own.
  std::string confusionFile;
  /// Non-empty: write every kept detection with its match and residual to this CSV (for the σ(r) fit).
  std::string matchesOut;
};

struct ConvertOptions {
  /// M, the number of classes. 1: no semantic part (header semantic "none", classifier "none").
  int classes = 1;
  /// p, the categorical model's misclassification rate, in [0, 1); must be 0 when classes is 1.
  double misclassification = 0.0;
  /// How clutter detections are labelled (ClassLabels.h): uniform, or one class per known source.
  ClutterLabels clutterLabels = ClutterLabels::Uniform;
  /// Seeds the std::mt19937 that draws the labels (and, for kitti-tracking, which has its own labels, the noise of
  /// `--odometry noisy`).
  std::uint32_t seed = 1;
  /// Keep one step per period (seconds); 0 keeps every step.
  double keyframePeriod = 0.0;
  /// Keep the first N steps of the (keyframed) log; 0 keeps all.
  std::size_t maxSteps = 0;
  /// Standard deviations of the prior on the first pose: (x, y, θ) in 2D, (x, y, z, rx, ry, rz) in 3D, metres and
  /// radians. Empty: kDefaultInitialPoseSigma on every component.
  std::vector<double> initialPoseSigmas;
  /// > 0: the landmark ground truth goes into the header as a prior map, each point with covariance σ² I.
  double mapPriorSigma = 0.0;
  /// MRCLAM: the robot (1..5) whose odometry and measurements are converted.
  int robot = 1;
  /// MRCLAM: seconds between a command's stamp and the motion it causes (the command takes effect this long after
  /// its stamp; docs/datasets.md measures about 0.2 s on every robot). 0: at its stamp.
  double commandDelay = 0.0;
  /// KITTI tracking only.
  KittiTrackingOptions kitti;
};

/// The default standard deviation of every component of the initial pose prior (metres or radians).
inline constexpr double kDefaultInitialPoseSigma = 1e-3;

/// What a conversion did: counts before and after keyframing and truncation.
struct ConversionStats {
  std::size_t datasetSteps = 0;       ///< steps before keyframing and truncation
  std::size_t datasetDetections = 0;  ///< detections before keyframing and truncation (every measurement record)
  std::size_t steps = 0;              ///< steps written
  std::size_t detections = 0;         ///< detections written
  std::size_t clutter = 0;            ///< detections written whose truth is "not a landmark"
  std::size_t unknownTruth = 0;       ///< detections written whose truth is "unknown" (kUnknownTruth)
  std::size_t truePoses = 0;          ///< steps written with a true pose
  std::size_t landmarks = 0;          ///< landmarks in the ground truth
  std::size_t stepsDroppedByKeyframing = 0;
  std::size_t detectionsDroppedByKeyframing = 0;
  std::size_t stepsDroppedByMaxSteps = 0;
  std::size_t detectionsDroppedByMaxSteps = 0;
  /// Dataset-specific lines for the terminal (kitti-tracking: the detections of each truth kind, the confusion
  /// counts), one per entry.
  std::vector<std::string> notes;
};

/// Throws InputError naming the option when `options` is out of range for a log of `dimension` (2 or 3).
void validateConvertOptions(const ConvertOptions& options, int dimension);

/// "M=3 p=0.1 seed=7 keyframe-period=1 s max-steps=all initial-pose-sigma=0.001,0.001,0.001 map-prior=none":
/// the settings, for a log's `source` text.
std::string describeConvertOptions(const ConvertOptions& options, int dimension);

}  // namespace semslam
