#pragma once
// PoseGraphReplay: a pose-graph file fed to a smoother the way an online front end would produce it, one pose
// per step in increasing pose-key order (the incremental benchmarks of iSAM and iSAM2 replay files this way:
// Kaess et al., IJRR 2012, Sec. VII).
//
// Step k introduces pose p_k together with
//   - every factor whose variables are all known by then: the edges between p_k and earlier poses (its
//     odometry and loop closures), the observations from p_k, and the gauge priors of PoseGraphAnchor.h on
//     the poses they hold;
//   - every landmark (any non-pose variable) first observed at this step: a landmark enters with its first
//     observation, as in an iSAM file.
// A factor's step is the latest step among its poses, or among the entry steps of its landmarks, whichever is
// later; a landmark's entry step is the earliest step of the factors that observe it from a pose.
//
// Initial values are the online ones, computed from the smoother's current estimate when the step is taken:
//   pose p_k      chained through its odometry edge: x_k = x_{k−1}·z for a between factor from p_{k−1} to p_k
//                 (x_{k−1}·z⁻¹ when the edge points the other way); failing that, through the first between edge
//                 to any earlier pose; the first pose (or one with no such edge) takes the file's initial value;
//   landmark l    its first observation from a pose: l = x ⊕ z = x·z (RelativePointFactor, 2D or 3D); failing
//                 that, the file's initial value.

#include <vector>

#include "semslam/graph/FactorGraph.h"
#include "semslam/graph/Values.h"
#include "semslam/io/PoseGraphFile.h"

namespace semslam {

struct ReplayStep {
  Key pose = 0;         // the pose this step introduces (the newest pose afterwards)
  FactorGraph factors;  // its new factors, in file order (anchor priors last)
  Values values;        // initial values of its new variables
};

class PoseGraphReplay {
 public:
  /// Splits the file's edges and its anchor priors (PoseGraphAnchor.h) into steps. Throws std::invalid_argument
  /// if the file has no pose (SE2 or SE3 variable).
  explicit PoseGraphReplay(const PoseGraphFile& file);

  std::size_t size() const { return poses_.size(); }
  /// Step `index` (0-based), its new variables initialised from `current`, which must hold every variable of
  /// the earlier steps.
  ReplayStep step(std::size_t index, const Values& current) const;

  /// Every factor of the replay (the file's edges and the anchor priors): the final graph.
  const FactorGraph& graph() const { return graph_; }

 private:
  Value initialPose(std::size_t index, const Values& current, const Values& fresh) const;
  Value initialLandmark(Key landmark, std::size_t index, const Values& current, const Values& fresh) const;

  FactorGraph graph_;
  Values fileValues_;
  std::vector<Key> poses_;
  std::vector<std::vector<FactorPtr>> factorsOfStep_;
  std::vector<std::vector<Key>> landmarksOfStep_;
};

}  // namespace semslam
