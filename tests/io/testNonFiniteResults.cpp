// Finite input whose products overflow: refused as an InputError naming the file (and the line where one
// record is the cause), never a success with an infinite gradient or inf/nan statistics (issue 16).

#include <gtest/gtest.h>

#include <string>

#include "IoTesting.h"
#include "semslam/io/PoseGraphFile.h"
#include "semslam/io/TrajectoryErrorReport.h"
#include "semslam/run/PoseGraphOptimization.h"

namespace semslam {
namespace {

using test::TempDir;

TEST(NonFiniteResults, AnIsamOdometryOfMinusOneE308IsRefusedAtItsLine) {
  // It exited 0 with "max-norm of the gradient inf" and wrote its output.
  const TempDir dir;
  const std::string path = dir.write("big.isam", "EDGE2 0 1 1 0 0 1 0 0 1 0 1\n"
                                                 "EDGE2 1 2 -1e308 0 0 1 0 0 1 0 1\n"
                                                 "EDGE2 2 3 1 0 0 1 0 0 1 0 1\n");
  EXPECT_INPUT_ERROR(readPoseGraph(path, GraphFormat::Isam), path, 2, "coordinates too large");
}

TEST(NonFiniteResults, AG2oEdgeWhoseErrorOverflowsIsRefusedAtItsLine) {
  const TempDir dir;
  const std::string path = dir.write("edge.g2o", "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\n"
                                                 "EDGE_SE2 0 1 1e200 0 0 1e200 0 0 1 0 1\n");
  EXPECT_INPUT_ERROR(readPoseGraph(path, GraphFormat::G2o), path, 3, "overflows (not finite)");
}

TEST(NonFiniteResults, AnOptimisationWhoseGradientOverflowsIsAnInputErrorNotASuccess) {
  // Each edge's own chi2 (1e308) is finite; their sum is not.
  const TempDir dir;
  const std::string path = dir.write("sum.g2o", "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 0 0 0\nVERTEX_SE2 2 0 0 0\n"
                                                "VERTEX_SE2 3 0 0 0\n"
                                                "EDGE_SE2 0 1 1e154 0 0 1 0 0 1 0 1\n"
                                                "EDGE_SE2 2 1 1e154 0 0 1 0 0 1 0 1\n"
                                                "EDGE_SE2 3 1 1e154 0 0 1 0 0 1 0 1\n");
  PoseGraphOptimizationOptions options;
  options.file = path;
  try {
    optimizePoseGraphFile(options);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_NE(std::string(error.what()).find("is not finite"), std::string::npos) << error.what();
  }
}

TEST(NonFiniteResults, TrajectoryStatisticsThatOverflowNameTheFileAndPose) {
  // A TUM coordinate of 1e308 gave inf/nan statistics and exit 0 (--json printed null).
  const TempDir dir;
  const std::string reference = dir.write("ref.tum", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n");
  const std::string estimate = dir.write("est.tum", "0 0 0 0 0 0 0 1\n1 1e308 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n");
  TrajectoryErrorRequest request;
  request.reference = reference;
  request.estimate = estimate;
  EXPECT_INPUT_ERROR(evaluateTrajectoryFiles(request), estimate, 0, "pose 1 (0-based)");
}

}  // namespace
}  // namespace semslam
