#include "semslam/io/RunFolder.h"

#include <filesystem>
#include <ostream>

#include "semslam/core/ExactNumber.h"
#include "semslam/eval/LandmarkMetrics.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/io/TumFormat.h"

namespace semslam {

namespace {

std::string truthField(const std::optional<int>& truth) {
  if (!truth) return "";
  if (*truth == kNotALandmark) return "not-a-landmark";
  if (*truth == kUnknownTruth) return "unknown";
  return std::to_string(*truth);
}

std::string landmarkOrUnassigned(const std::optional<int>& landmark) {
  return landmark ? std::to_string(*landmark) : "unassigned";
}

void writePositionColumns(std::ostream& out, const Vector& position) {
  for (int i = 0; i < position.size(); ++i) out << "," << seventeenDigitNumber(position(i));
}

}  // namespace

SE3 toSE3(const Pose& pose) {
  if (const SE3* spatial = std::get_if<SE3>(&pose)) return *spatial;
  const SE2& planar = std::get<SE2>(pose);
  return SE3(SO3::fromAxisAngle(Vector3::UnitZ(), planar.theta()), Point3(planar.x(), planar.y(), 0.0));
}

void writeRunFolder(const std::string& directory, const RunOutput& run) {
  const std::filesystem::path folder(directory);
  std::filesystem::create_directories(folder);
  const std::string axes = run.dimension == 3 ? "x,y,z" : "x,y";

  writeTumTrajectory((folder / "trajectory.tum").string(), run.trajectory);
  if (run.truth) writeTumTrajectory((folder / "truth.tum").string(), *run.truth);

  writeFileAtomically((folder / "landmarks.csv").string(), [&](std::ostream& out) {
    out << "id," << axes << ",class,p_class\n";
    for (const RunLandmark& landmark : run.landmarks) {
      out << landmark.id;
      writePositionColumns(out, landmark.position);
      out << "," << landmark.classIndex << ","
          << (landmark.classIndex >= 0 ? seventeenDigitNumber(landmark.classProbability) : "") << "\n";
    }
  });
  if (!run.landmarkTruth.empty()) {
    writeFileAtomically((folder / "landmarks_truth.csv").string(), [&](std::ostream& out) {
      out << "id," << axes << ",class\n";
      for (const LandmarkTruth& truth : run.landmarkTruth) {
        out << truth.id;
        writePositionColumns(out, landmarkPosition(truth.state));
        out << "," << truth.classIndex << "\n";
      }
    });
  }
  writeFileAtomically((folder / "covariances.csv").string(), [&](std::ostream& out) {
    out << "kind,id,cxx,cxy,cyy\n";
    for (std::size_t i = 0; i < run.posePositionCovariances.size(); ++i) {
      const Matrix& c = run.posePositionCovariances[i];
      out << "pose," << i << "," << seventeenDigitNumber(c(0, 0)) << "," << seventeenDigitNumber(c(0, 1)) << ","
          << seventeenDigitNumber(c(1, 1)) << "\n";
    }
    for (const RunLandmark& landmark : run.landmarks) {
      if (!landmark.positionCovariance) continue;
      const Matrix& c = *landmark.positionCovariance;
      out << "landmark," << landmark.id << "," << seventeenDigitNumber(c(0, 0)) << "," << seventeenDigitNumber(c(0, 1))
          << "," << seventeenDigitNumber(c(1, 1)) << "\n";
    }
  });
  if (!run.associations.empty()) {
    writeFileAtomically((folder / "associations.csv").string(), [&](std::ostream& out) {
      out << "step,detection,landmark,weight,truth,chi2\n";
      for (const AssociationRecord& a : run.associations) {
        out << a.step << "," << a.detection << "," << (a.landmark ? std::to_string(*a.landmark) : "null") << ","
            << seventeenDigitNumber(a.weight) << "," << truthField(a.truth) << ","
            << (a.chi2 ? seventeenDigitNumber(*a.chi2) : "") << "\n";
      }
    });
  }
  if (!run.branchSplits.empty()) {
    writeFileAtomically((folder / "branches.csv").string(), [&](std::ostream& out) {
      out << "opened_at,closed_after,score_as_is,score_apart,score_next_best,kept\n";
      for (const BranchSplitRecord& split : run.branchSplits) {
        out << split.openedAt << "," << split.closedAfter << "," << seventeenDigitNumber(split.scoreAsIs) << ","
            << seventeenDigitNumber(split.scoreApart) << ","
            << (split.scoreNextBest ? seventeenDigitNumber(*split.scoreNextBest) : "") << "," << split.kept << "\n";
      }
    });
  }
  if (!run.decisions.empty()) {
    writeFileAtomically((folder / "decisions.csv").string(), [&](std::ostream& out) {
      out << "step,detection,decided,right,truth\n";
      for (const DecisionRecord& d : run.decisions) {
        out << d.step << "," << d.detection << "," << landmarkOrUnassigned(d.decision.decided) << ","
            << landmarkOrUnassigned(d.decision.right) << "," << truthField(d.truth) << "\n";
      }
    });
  }
}

}  // namespace semslam
