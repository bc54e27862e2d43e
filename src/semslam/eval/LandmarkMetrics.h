#pragma once
// Landmark (map) metrics of metrics.json: count error, position RMSE of matched landmarks after alignment, and
// class accuracy. Estimated and true landmarks are paired by a LandmarkMatching (LandmarkMatching.h: the one-to-one
// matching that maximises shared detections), never by their ids.
//
//   count error      N_est − N_true
//   position RMSE    sqrt( 1/m Σ_(e,t) matched ‖A(p̂_e) − p_t‖² )   (metres; m pairs whose true position is known)
//                    A(p) = R_A p + t_A, the alignment passed in. metrics.json passes the trajectory's rigid
//                    alignment (TrajectoryMetrics.h: SE(2) Umeyama in 2D, SE(3) in 3D, estimated from the robot
//                    positions only), so the map is judged in the frame that best fits the trajectory, not fitted
//                    on its own; without one, the identity (the estimate's own frame). For 2D landmarks only the
//                    planar part of A is used.
//   class accuracy   (matched pairs with argmax_c P̂_e(c) = c_t) / (matched pairs with a class estimate and a known
//                    true class). argmax takes the first (lowest) class on ties.
// The position of a landmark that is a pose (SE2/SE3 object) is its translation. RMSE and class accuracy are NaN
// when nothing is compared.

#include <cstddef>
#include <limits>
#include <vector>

#include "semslam/eval/LandmarkMatching.h"
#include "semslam/eval/Umeyama.h"
#include "semslam/geometry/Matrix.h"
#include "semslam/models/MeasurementLog.h"
#include "semslam/models/RunResult.h"

namespace semslam {

struct LandmarkMetrics {
  std::size_t estimated = 0;           ///< N_est
  std::size_t truth = 0;               ///< N_true
  long long countError = 0;            ///< N_est − N_true
  std::size_t matched = 0;             ///< matching pairs whose landmarks are both present
  std::vector<double> positionErrors;  ///< ‖A(p̂_e) − p_t‖ per compared pair, in matching order
  double positionRmse = std::numeric_limits<double>::quiet_NaN();
  std::size_t classesCompared = 0;
  std::size_t classesCorrect = 0;
  double classAccuracy = std::numeric_limits<double>::quiet_NaN();
};

/// The position of a landmark state: Point2/SE2 → 2 numbers, Point3/SE3 → 3.
Vector landmarkPosition(const LandmarkState& state);
/// A(p) for a 2D or 3D point (2D: the planar part of the transform).
Vector applyAlignment(const SimilarityTransform& alignment, const Vector& point);
/// argmax_c P(c), the first on ties; -1 for an empty vector.
int mostProbableClass(const Vector& probabilities);

/// Landmark metrics (see above). Throws InputError for a repeated id in either list or a 2D/3D mismatch between
/// a matched pair.
LandmarkMetrics evaluateLandmarks(const std::vector<EstimatedLandmark>& estimate,
                                  const std::vector<LandmarkTruth>& truth, const LandmarkMatching& matching,
                                  const SimilarityTransform& alignment = {});

}  // namespace semslam
