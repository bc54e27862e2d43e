#pragma once
// Residuals of a measurement log against its own ground truth: how well the log's stated noise describes the data.
//
// Detections: for every detection whose truth is a landmark of the header's landmark_truth, at a step with a true
// pose, the residual is measured − h(true pose, true landmark) with the header's sensor model
// (RangeBearingSensor2, RangeBearingElevationSensor3, RelativePositionSensor2/3; angle differences wrapped to
// (−π, π]). Relative-pose sensors and landmarks with an orientation are not evaluated (counted as skipped).
// Odometry: for every step with odometry whose own and previous step have a true pose, the residual is
//     r = Log(increment⁻¹ · x_{k−1}⁻¹ x_k)
// in the tangent of the right perturbation (translation first), the same error as a between factor's, so its
// covariance is the stated odometry covariance.
//
// Odometry over windows: per-step statistics cannot show errors that are correlated in time (a heading bias of a
// few tenths of a degree per step is invisible beside a step's σ, yet turns the map by tens of degrees over a loop).
// So the increments of every n consecutive steps (n in kOdometryWindowSteps, every start step, so windows overlap)
// are composed, Z = Z_1 ⋯ Z_n, with the covariance propagated to first order in the right perturbation,
//     Σ ← Ad(Z_i⁻¹) Σ Ad(Z_i⁻¹)ᵀ + Σ_i      (since T Exp(ε) Z_i = T Z_i Exp(Ad(Z_i⁻¹) ε)),
// and compared with the true relative pose of the window's ends: r = Log(Z⁻¹ · x_{k−n}⁻¹ x_k), NEES = rᵀ Σ⁻¹ r.
// White noise as stated gives a mean NEES of d (3 in 2D, 6 in 3D) at every n and 95 % of windows inside the χ²_d
// 95 % quantile; a mean that grows with n says the stated noise holds per step and fails over a loop.
//
// Per component the statistics are: the count; mean and (population) standard deviation of r_i; the median and the
// robust standard deviation 1.4826 · median |r_i − median| (equal to the std for Gaussian residuals, insensitive to
// outliers); the stated standard deviation, sqrt(mean over residuals of Σ_ii) (the RMS of the stated sigmas, which
// vary per detection or step in some logs); and the standard deviation of the normalised residuals r_i / sqrt(Σ_ii)
// (1 when the stated noise is right, whatever its variation). Components with no residual have count 0 and zeros.

#include <array>
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "semslam/models/MeasurementLog.h"

namespace semslam {

struct ComponentResidualStatistics {
  std::string name;  ///< "range", "bearing", "elevation", "x", "y", "z", "theta", "rx", "ry", "rz"
  std::size_t count = 0;
  double mean = 0.0;
  double std = 0.0;
  double median = 0.0;
  double robustStd = 0.0;      ///< 1.4826 · MAD
  double statedStd = 0.0;      ///< sqrt(mean Σ_ii)
  double normalizedStd = 0.0;  ///< std of r_i / sqrt(Σ_ii)
  double within95 = 0.0;       ///< fraction with |r_i − median| ≤ 1.96 sqrt(Σ_ii): 0.95 for stated σ that cover
                               ///< the data as its Gaussian would (well below: the gate and likelihoods are too narrow)
};

/// The window lengths of the odometry's consistency over windows (steps): one step, and the decades above it, up to
/// the horizon of a loop closure in the project's real logs (a hundred 1 s keyframes).
inline constexpr std::array<int, 3> kOdometryWindowSteps = {1, 10, 100};

struct OdometryWindowStatistics {
  int steps = 0;                ///< n
  int dimension = 0;            ///< d, the odometry's tangent dimension
  std::size_t windows = 0;      ///< windows evaluated: n consecutive steps with odometry, true poses at both ends
  double meanNees = 0.0;        ///< expected: the tangent dimension d
  double withinQuantile = 0.0;  ///< fraction with NEES ≤ the χ²_d 95 % quantile: 0.95 when consistent
};

struct LogResidualStatistics {
  std::vector<ComponentResidualStatistics> detection;  ///< one per geometry component
  std::vector<ComponentResidualStatistics> odometry;   ///< one per tangent component
  std::size_t detectionsEvaluated = 0;
  std::size_t detectionsClutter = 0;          ///< truth "not a landmark": nothing to predict
  std::size_t detectionsUnknownTruth = 0;     ///< no truth, truth "unknown", or an id not in landmark_truth
  std::size_t detectionsWithoutTruePose = 0;  ///< at a step without a true pose
  std::size_t detectionsSkipped = 0;          ///< a sensor or landmark kind that is not evaluated
  std::size_t detectionsUndefined = 0;        ///< the prediction is undefined (landmark at the sensor)
  std::size_t odometryEvaluated = 0;
  std::size_t odometryWithoutTruePoses = 0;  ///< this or the previous step has no true pose
  std::vector<OdometryWindowStatistics> odometryWindows;  ///< one per kOdometryWindowSteps entry
};

/// Accumulates residuals step by step (for logs read with MeasurementLogReader).
class ResidualAccumulator {
 public:
  explicit ResidualAccumulator(const LogHeader& header);
  void add(const TimeStep& step);
  LogResidualStatistics statistics() const;

 private:
  struct Samples {
    std::vector<double> residual, variance;
  };
  struct WindowEntry {  // one step of the odometry window: its odometry (none for the first step) and true pose
    std::optional<Odometry> odometry;
    std::optional<Pose> truePose;
  };
  struct WindowSums {
    std::size_t windows = 0, inside = 0;
    double nees = 0.0;
  };
  void addWindows();
  LogHeader header_;
  std::vector<Samples> detection_;
  std::vector<Samples> odometry_;
  LogResidualStatistics counts_;
  std::optional<Pose> previousTruePose_;
  bool first_ = true;
  std::deque<WindowEntry> window_;  // the last max(kOdometryWindowSteps) + 1 steps
  std::array<WindowSums, kOdometryWindowSteps.size()> windowSums_;
};

/// The residual statistics of a whole log.
LogResidualStatistics computeResidualStatistics(const MeasurementLog& log);

/// A plain-text table of the statistics, one line per component, with the counts.
std::string formatResidualStatistics(const LogResidualStatistics& statistics);

}  // namespace semslam
