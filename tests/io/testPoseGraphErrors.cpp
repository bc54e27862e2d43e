// readPoseGraph on malformed files: each problem is an InputError naming the file, the line and the problem.

#include <gtest/gtest.h>

#include "IoTesting.h"
#include "semslam/io/PoseGraphFile.h"

namespace semslam {
namespace {

using test::TempDir;

constexpr const char* kV0 = "VERTEX_SE2 0 0 0 0\n";
constexpr const char* kV1 = "VERTEX_SE2 1 1 0 0\n";
constexpr const char* kInfo = " 1 0 0 1 0 1\n";

class PoseGraphErrors : public ::testing::Test {
 protected:
  /// Writes `contents` to a file and expects reading it as `format` to fail at `line` with `part`.
  void expectError(GraphFormat format, const std::string& contents, std::size_t line, const std::string& part) {
    const std::string file = dir_.write("graph.txt", contents);
    EXPECT_INPUT_ERROR(readPoseGraph(file, format), file, line, part);
  }
  void expectG2oError(const std::string& contents, std::size_t line, const std::string& part) {
    expectError(GraphFormat::G2o, contents, line, part);
  }

  TempDir dir_;
};

TEST_F(PoseGraphErrors, FileThatDoesNotExist) {
  const std::string file = dir_.path("missing.g2o");
  EXPECT_INPUT_ERROR(readPoseGraph(file, GraphFormat::G2o), file, 0, "file does not exist");
  EXPECT_INPUT_ERROR(readPoseGraph(file, GraphFormat::Toro), file, 0, "file does not exist");
  EXPECT_INPUT_ERROR(readPoseGraph(file, GraphFormat::Isam), file, 0, "file does not exist");
}

TEST_F(PoseGraphErrors, EmptyFile) {
  for (GraphFormat format : {GraphFormat::G2o, GraphFormat::Toro, GraphFormat::Isam}) {
    expectError(format, "", 0, "no records");
    expectError(format, "# only a comment\n\n  \n", 0, "no records");
  }
}

TEST_F(PoseGraphErrors, FileWithoutPose) { expectG2oError("VERTEX_XY 3 1 2\n", 0, "no pose in the file"); }

TEST_F(PoseGraphErrors, TruncatedLine) {
  expectG2oError(std::string(kV0) + kV1 + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0\n", 3,
                 "truncated EDGE_SE2 record: expected 11 values after the tag "
                 "(i j dx dy dtheta I11 I12 I13 I22 I23 I33), found 10");
  expectG2oError("VERTEX_SE2 0 0 0\n", 1, "truncated VERTEX_SE2 record: expected 4 values after the tag");
  expectG2oError("VERTEX_SE3:QUAT 0 0 0 0 0 0 1\n", 1, "truncated VERTEX_SE3:QUAT record: expected 8 values");
  expectG2oError(std::string(kV0) + "FIX\n", 2, "truncated FIX record: expected at least 1 value");
  expectError(GraphFormat::Toro, "VERTEX2 0 0 0 0\nVERTEX2 1 0 0 0\nEDGE2 0 1 1 0 0 1 0 1 1 0\n", 3,
              "truncated EDGE2 record: expected 11 values after the tag "
              "(i j dx dy dtheta I_xx I_xy I_yy I_tt I_xt I_yt), found 10");
  expectError(GraphFormat::Isam, "EDGE2 0 1 1 0 0 1 0 0 1 0 1\nLANDMARK 1 0 2 3 1 0\n", 2,
              "truncated LANDMARK record: expected 7 values after the tag (i l dx dy s11 s12 s22), found 6");
}

TEST_F(PoseGraphErrors, ExtraFields) {
  expectG2oError(std::string(kV0) + "VERTEX_SE2 1 1 0 0 7\n", 2,
                 "extra fields in VERTEX_SE2 record: expected 4 values after the tag (id x y theta), found 5");
  expectError(GraphFormat::Isam, "ODOMETRY 0 1 1 0 0 1 0 0 1 0 1 5\n", 1,
              "extra fields in ODOMETRY record: expected 11 values");
  expectError(GraphFormat::Toro, "VERTEX2 0 0 0 0\nVERTEX2 1 0 0 0\nEQUIV 0 1 2\n", 3,
              "extra fields in EQUIV record: expected 2 values after the tag (i j), found 3");
}

TEST_F(PoseGraphErrors, NonNumericField) {
  expectG2oError(std::string(kV0) + kV1 + "EDGE_SE2 0 1 1 abc 0" + kInfo, 3,
                 "EDGE_SE2 field 4 (dy) 'abc' is not a number");
  expectG2oError("VERTEX_SE2 a 0 0 0\n", 1, "VERTEX_SE2 field 1 (id) 'a' is not a non-negative integer id");
  expectG2oError("VERTEX_SE2 -3 0 0 0\n", 1, "'-3' is not a non-negative integer id");
  expectError(GraphFormat::Isam, "EDGE2 0 1 1 0 0 1 0 0 1 0 x\n", 1, "EDGE2 field 11 (s33) 'x' is not a number");
}

TEST_F(PoseGraphErrors, NonFiniteField) {
  expectG2oError("VERTEX_SE2 0 nan 0 0\n", 1, "VERTEX_SE2 field 2 (x) is not finite: 'nan'");
  expectG2oError(std::string(kV0) + kV1 + "EDGE_SE2 0 1 1 0 0 inf 0 0 1 0 1\n", 3,
                 "EDGE_SE2 field 6 (I11) is not finite: 'inf'");
  expectError(GraphFormat::Toro, "VERTEX2 0 0 -inf 0\n", 1, "VERTEX2 field 3 (y) is not finite: '-inf'");
  expectError(GraphFormat::Isam, "EDGE2 0 1 NaN 0 0 1 0 0 1 0 1\n", 1, "EDGE2 field 3 (dx) is not finite: 'NaN'");
}

TEST_F(PoseGraphErrors, DuplicateVertex) {
  expectG2oError(std::string("# header\n") + kV0 + kV1 + "VERTEX_XY 1 5 5\n", 4,
                 "duplicate vertex 1: already declared at line 3");
  expectError(GraphFormat::Toro, "VERTEX2 0 0 0 0\nVERTEX2 0 1 0 0\n", 2,
              "duplicate vertex 0: already declared at line 1");
}

TEST_F(PoseGraphErrors, EdgeNamingUnknownVertex) {
  expectG2oError(std::string(kV0) + "EDGE_SE2 0 7 1 0 0" + kInfo, 2,
                 "EDGE_SE2 field 2 (j) names vertex 7, which is not declared on an earlier line");
  // A vertex declared after the edge that names it does not count.
  expectG2oError(std::string(kV0) + "EDGE_SE2 0 1 1 0 0" + kInfo + kV1, 2, "names vertex 1, which is not declared");
  expectG2oError(std::string(kV0) + "EDGE_SE2_XY 0 4 1 0 1 0 1\n", 2, "EDGE_SE2_XY field 2 (l) names vertex 4");
  expectG2oError(std::string(kV0) + "FIX 0 9\n", 2, "FIX field 2 (id) names vertex 9, which is not declared");
  expectError(GraphFormat::Toro, "VERTEX2 0 0 0 0\nEDGE2 3 0 1 0 0 1 0 1 1 0 0\n", 2,
              "EDGE2 field 1 (i) names vertex 3, which is not declared on an earlier line");
  expectError(GraphFormat::Toro, "VERTEX2 0 0 0 0\nEQUIV 0 2\n", 2, "EQUIV field 2 (j) names vertex 2");
}

TEST_F(PoseGraphErrors, IsamLandmarkNamingUnknownPose) {
  expectError(GraphFormat::Isam, "EDGE2 0 1 1 0 0 1 0 0 1 0 1\nLANDMARK 2 0 1 1 1 0 1\n", 2,
              "LANDMARK field 1 (i) names pose x2, which does not appear in an earlier odometry record");
  expectError(GraphFormat::Isam, "LANDMARK 0 0 1 1 1 0 1\n", 1, "names pose x0, which does not appear");
}

TEST_F(PoseGraphErrors, IsamOdometryBetweenTwoUnknownPoses) {
  expectError(GraphFormat::Isam, "EDGE2 0 1 1 0 0 1 0 0 1 0 1\nEDGE2 5 6 1 0 0 1 0 0 1 0 1\n", 2,
              "EDGE2 connects poses x5 and x6, neither of which appears in an earlier record");
}

TEST_F(PoseGraphErrors, WrongVertexType) {
  expectG2oError(std::string(kV0) + "VERTEX_XY 1 2 3\nEDGE_SE2 0 1 1 0 0" + kInfo, 3,
                 "EDGE_SE2 field 2 (j) names vertex 1 of type Point2, expected SE2");
  expectG2oError(std::string(kV0) + kV1 + "EDGE_SE2_XY 0 1 1 0 1 0 1\n", 3,
                 "EDGE_SE2_XY field 2 (l) names vertex 1 of type SE2, expected Point2");
}

TEST_F(PoseGraphErrors, EdgeFromAVertexToItself) {
  expectG2oError(std::string(kV0) + "EDGE_SE2 0 0 1 0 0" + kInfo, 2, "EDGE_SE2 connects vertex 0 to itself");
  expectError(GraphFormat::Isam, "ODOMETRY 4 4 1 0 0 1 0 0 1 0 1\n", 1, "ODOMETRY connects vertex x4 to itself");
  expectError(GraphFormat::Toro, "VERTEX2 0 0 0 0\nEQUIV 0 0\n", 2, "EQUIV connects vertex 0 to itself");
}

TEST_F(PoseGraphErrors, InformationNotPositiveDefinite) {
  expectG2oError(std::string(kV0) + kV1 + "EDGE_SE2 0 1 1 0 0 1 0 0 -1 0 1\n", 3,
                 "EDGE_SE2: information matrix is not positive definite");
  expectG2oError(std::string(kV0) + kV1 + "EDGE_SE2 0 1 1 0 0 1 2 0 1 0 1\n", 3, "not positive definite");
  expectG2oError(std::string(kV0) + "VERTEX_XY 1 0 0\nEDGE_SE2_XY 0 1 1 0 0 0 0\n", 3,
                 "EDGE_SE2_XY: information matrix is not positive definite");
  const std::string v3 = "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\nVERTEX_SE3:QUAT 1 1 0 0 0 0 0 1\n";
  expectG2oError(v3 + "EDGE_SE3:QUAT 0 1 1 0 0 0 0 0 1 1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 0\n", 3,
                 "EDGE_SE3:QUAT: information matrix is not positive definite");
  // TORO order I_xx I_xy I_yy I_tt I_xt I_yt: a zero I_tt is singular.
  expectError(GraphFormat::Toro, "VERTEX2 0 0 0 0\nVERTEX2 1 0 0 0\nEDGE2 0 1 1 0 0 1 0 1 0 0 0\n", 3,
              "EDGE2: information matrix is not positive definite");
  expectError(GraphFormat::Isam, "EDGE2 0 1 1 0 0 1 0 0 0 0 1\n", 1,
              "EDGE2: square-root information matrix is singular");
  expectError(GraphFormat::Isam, "EDGE2 0 1 1 0 0 1 0 0 1 0 1\nLANDMARK 1 0 1 1 0 0 1\n", 2,
              "LANDMARK: square-root information matrix is singular");
}

TEST_F(PoseGraphErrors, ZeroQuaternion) {
  expectG2oError("VERTEX_SE3:QUAT 0 0 0 0 0 0 0 0\n", 1,
                 "VERTEX_SE3:QUAT: quaternion (qx qy qz qw) is zero (norm below 1e-12) and cannot be normalised");
  const std::string information = " 1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 1\n";
  expectG2oError(
      "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\nVERTEX_SE3:QUAT 1 1 0 0 0 0 0 1\nEDGE_SE3:QUAT 0 1 1 0 0 0 0 0 0" + information,
      3, "EDGE_SE3:QUAT: quaternion (qx qy qz qw) is zero");
}

TEST_F(PoseGraphErrors, UnknownRecordTypes) {
  expectG2oError(std::string(kV0) + "FOO 1 2\n", 2, "unknown record type 'FOO'");
  expectG2oError(std::string("PARAMS_SE2OFFSET 0 0 0 0\n") + kV0, 1, "unsupported g2o record type 'PARAMS_SE2OFFSET'");
  expectG2oError(std::string(kV0) + "VERTEX_TRACKXYZ 1 0 0 0\n", 2, "unsupported g2o record type 'VERTEX_TRACKXYZ'");
  expectG2oError("VERTEX2 0 0 0 0\n", 1,
                 "unsupported record type 'VERTEX2' in a g2o file: it is a TORO or iSAM record");
  expectError(GraphFormat::Toro, "VERTEX2 0 0 0 0\nBR 0 1 0.1 2 0.01 0.1\n", 2, "unsupported record type 'BR'");
  expectError(GraphFormat::Toro, "VERTEX_SE2 0 0 0 0\n", 1, "it is a g2o record; read the file as g2o");
  expectError(GraphFormat::Toro, "VERTEX2 0 0 0 0\nWHAT 1\n", 2, "unknown record type 'WHAT'");
  expectError(GraphFormat::Isam, "EDGE3 0 1 0 0 0 0 0 0 1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 1\n", 1,
              "unsupported iSAM record type 'EDGE3'");
  expectError(GraphFormat::Isam, "EDGE2 0 1 1 0 0 1 0 0 1 0 1\nPOINT3 1 0 1 2 3 1 0 0 1 0 1\n", 2,
              "unsupported iSAM record type 'POINT3'");
  expectError(GraphFormat::Isam, "VERTEX2 0 0 0 0\n", 1, "it is a TORO record; read the file as toro");
  expectError(GraphFormat::Isam, "edge2 0 1 1 0 0 1 0 0 1 0 1\n", 1, "unknown record type 'edge2'");
}

TEST_F(PoseGraphErrors, MixedDimensions) {
  expectG2oError(std::string(kV0) + "VERTEX_SE3:QUAT 1 0 0 0 0 0 0 1\n", 2,
                 "3D record VERTEX_SE3:QUAT in a file whose records are 2D (since line 1)");
}

TEST_F(PoseGraphErrors, UnknownFormatName) {
  try {
    parseGraphFormat("graph");
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("unknown pose-graph format 'graph'"), std::string::npos);
  }
  EXPECT_EQ(parseGraphFormat("g2o"), GraphFormat::G2o);
  EXPECT_EQ(parseGraphFormat("toro"), GraphFormat::Toro);
  EXPECT_EQ(parseGraphFormat("isam"), GraphFormat::Isam);
}

}  // namespace
}  // namespace semslam
