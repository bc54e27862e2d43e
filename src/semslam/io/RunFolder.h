#pragma once
// A run folder: what one run of a method writes, in files a person, evo or a plotting script can read.
//
//   trajectory.tum         estimated poses, `t x y z qx qy qz qw` (2D poses with z = 0 and a yaw quaternion)
//   truth.tum              true poses, where known (same format)
//   landmarks.csv          `id,x,y[,z],class,p_class` (the most probable class and its probability; -1 and empty
//                          where the method keeps no class belief)
//   landmarks_truth.csv    `id,x,y[,z],class`, where known
//   covariances.csv        `kind,id,cxx,cxy,cyy`: the position block of each pose's (kind `pose`, id = its index
//                          in trajectory.tum) and landmark's marginal covariance, for covariance ellipses
//   associations.csv       `step,detection,landmark,weight,truth,chi2` (landmark `null` for the null hypothesis,
//                          truth `not-a-landmark` for clutter, `unknown` where the dataset cannot decide, empty
//                          where the log has no truth; chi2 = rᵀR⁻¹r of the detection against its landmark at the
//                          final estimate, empty without a landmark)
//   branches.csv           `opened_at,closed_after,score_as_is,score_apart,score_next_best,kept`: paper B's ml,
//                          mm and mm-nh (loop-closure branches, on by default), one row per split
//                          (slam/LoopClosureBranches.h): the step that opened it, the step after which it closed,
//                          the branches' scores (−2 ln evidence, slam/BranchScore.h; score_next_best empty where
//                          that split opened no next-best branch: mm-nh's default, --loop-closure-next-best for ml
//                          and mm) and which was kept, `as-is`, `apart` or `next-best`
//   decisions.csv          `step,detection,decided,right,truth`: runs on the true history (--on-true-history) only,
//                          one row per detection: the landmark the front end decided and the landmark the true
//                          history had for the detection's object (`unassigned` for the unassigned hypothesis, and as
//                          `right` for clutter and first sightings; landmark ids those of landmarks.csv), truth as
//                          in associations.csv. A decision is right exactly when `decided` equals `right`
//                          (eval/DecisionAccuracy.h)
// metrics.json is written by io/RunMetricsFile.h. Every file is written atomically (io/AtomicFile.h); a file whose
// data is empty (no truth, no associations) is not written.

#include <optional>
#include <string>
#include <vector>

#include "semslam/models/Trajectory.h"
#include "semslam/models/MeasurementLog.h"
#include "semslam/models/RunResult.h"

namespace semslam {

/// One row of landmarks.csv and covariances.csv (models/RunResult.h has the estimator's EstimatedLandmark).
struct RunLandmark {
  int id = 0;
  Vector position;               // 2 or 3 numbers
  int classIndex = -1;           // -1: no class belief
  double classProbability = 0.0;
  std::optional<Matrix> positionCovariance;
};

/// One row of branches.csv (slam/LoopClosureBranches.h, Split).
struct BranchSplitRecord {
  int openedAt = 0;
  int closedAfter = 0;
  double scoreAsIs = 0.0;   // branch A: the step as the front end decided it
  double scoreApart = 0.0;  // branch B: the anchoring detections kept apart
  std::optional<double> scoreNextBest;  // branch C, where it was opened: the next-best landmarks
  std::string kept;                     // "as-is", "apart" or "next-best"
};

/// One row of decisions.csv: a decision on the true history (models/RunResult.h, HistoryDecision).
struct DecisionRecord {
  int step = 0;
  int detection = 0;
  HistoryDecision decision;
  std::optional<int> truth;  // as AssociationRecord::truth
};

struct RunOutput {
  int dimension = 2;
  Trajectory trajectory;
  std::optional<Trajectory> truth;
  std::vector<Matrix> posePositionCovariances;  // empty, or one per trajectory pose
  std::vector<RunLandmark> landmarks;
  std::vector<LandmarkTruth> landmarkTruth;
  std::vector<AssociationRecord> associations;
  std::vector<BranchSplitRecord> branchSplits;
  std::vector<DecisionRecord> decisions;
};

/// The SE3 form of a pose for trajectory files: SE2 (x, y, θ) becomes (x, y, 0) with a rotation θ about z.
SE3 toSE3(const Pose& pose);

/// Writes the files above into `directory` (created if needed).
void writeRunFolder(const std::string& directory, const RunOutput& run);

}  // namespace semslam
