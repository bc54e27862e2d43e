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
// Per component the statistics are: the count; mean and (population) standard deviation of r_i; the median and the
// robust standard deviation 1.4826 · median |r_i − median| (equal to the std for Gaussian residuals, insensitive to
// outliers); the stated standard deviation, sqrt(mean over residuals of Σ_ii) (the RMS of the stated sigmas, which
// vary per detection or step in some logs); and the standard deviation of the normalised residuals r_i / sqrt(Σ_ii)
// (1 when the stated noise is right, whatever its variation). Components with no residual have count 0 and zeros.

#include <cstddef>
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
  LogHeader header_;
  std::vector<Samples> detection_;
  std::vector<Samples> odometry_;
  LogResidualStatistics counts_;
  std::optional<Pose> previousTruePose_;
  bool first_ = true;
};

/// The residual statistics of a whole log.
LogResidualStatistics computeResidualStatistics(const MeasurementLog& log);

/// A plain-text table of the statistics, one line per component, with the counts.
std::string formatResidualStatistics(const LogResidualStatistics& statistics);

}  // namespace semslam
