// TUM, KITTI and EuRoC readers: what they accept, and that every malformed input throws InputError naming the
// file and the line.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "support/InputErrorTesting.h"
#include "support/TempFile.h"
#include "semslam/io/EurocFormat.h"
#include "semslam/io/KittiFormat.h"
#include "semslam/io/TrajectoryFormat.h"
#include "semslam/io/TumFormat.h"

namespace semslam {
namespace {

using test::expectInputError;
using test::expectInputErrorReading;
using test::TempFile;

constexpr const char* kIdentity12 = "1 0 0 0 0 1 0 0 0 0 1 0";

TEST(TumFormat, ReadsPosesCommentsBlankLinesAndCrlf) {
  const TempFile file(
      "# timestamp tx ty tz qx qy qz qw\n"
      "1.0 1 2 3 0 0 0 1\r\n"
      "\n"
      "  # indented comment\n"
      "1.5\t4 5 6  0 0 0.7071067811865476 0.7071067811865476\n"
      "1.5 7 8 9 0 0 0 2\n");  // equal stamps are accepted; a non-unit quaternion is normalised
  const Trajectory t = readTumTrajectory(file.path());
  ASSERT_EQ(t.size(), 3u);
  EXPECT_TRUE(t.hasTimestamps());
  EXPECT_DOUBLE_EQ(t.timestamp(1), 1.5);
  EXPECT_EQ(t.position(1), Vector3(4, 5, 6));
  const Matrix3 rz = t.pose(1).rotation().matrix();  // 90 degrees about z
  EXPECT_NEAR(rz(0, 1), -1.0, 1e-15);
  EXPECT_NEAR(rz(1, 0), 1.0, 1e-15);
  EXPECT_LT((t.pose(2).rotation().matrix() - Matrix3::Identity()).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(TumFormat, MalformedInputNamesFileAndLine) {
  const auto read = [](const std::string& path) { readTumTrajectory(path); };
  expectInputErrorReading(read, "# header\n1 0 0 0 0 0 0 1\n2 0 0 0 0 0 1\n", 3, "expected 8 numbers");
  expectInputErrorReading(read, "1 0 0 0 0 0 0 1 5\n", 1, "found 9");
  expectInputErrorReading(read, "1 0 0 0 0 0 0 1\n2 0 x 0 0 0 0 1\n", 2, "not a number");
  expectInputErrorReading(read, "1 0 0 0 0 0 0 1\n2 0 0 nan 0 0 0 1\n", 2, "not finite");
  expectInputErrorReading(read, "1 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 inf\n", 2, "not finite");
  expectInputErrorReading(read, "1 0 0 1e999 0 0 0 1\n", 1, "out of the range");
  expectInputErrorReading(read, "1 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 0\n", 2, "zero norm");
  expectInputErrorReading(read, "1 0 0 0 0 0 0 1\n3 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n", 3, "backwards");
  expectInputErrorReading(read, "", 0, "empty");
  expectInputErrorReading(read, "# only a comment\n\n", 0, "empty");
  expectInputErrorReading(read, "1.0.0 0 0 0 0 0 0 1\n", 1, "not a number");
  expectInputError([] { readTumTrajectory("/nonexistent/semslam/traj.txt"); }, "/nonexistent/semslam/traj.txt", 0,
                   "does not exist");
  const std::string dir = std::filesystem::temp_directory_path().string();
  expectInputError([&] { readTumTrajectory(dir); }, dir, 0, "directory");
}

TEST(TumFormat, WriteThenReadIsExact) {
  const TempFile source("100.25 1.5 -2.25 3.125 0.1 -0.2 0.3 0.9273618495495703\n200.5 0 0 0 0 0 0 1\n");
  const Trajectory original = readTumTrajectory(source.path());
  const TempFile copy("");
  writeTumTrajectory(copy.path(), original);
  const Trajectory back = readTumTrajectory(copy.path());
  ASSERT_EQ(back.size(), original.size());
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back.timestamp(i), original.timestamp(i));
    EXPECT_EQ(back.position(i), original.position(i));
    EXPECT_LT((back.pose(i).rotation().matrix() - original.pose(i).rotation().matrix()).cwiseAbs().maxCoeff(), 1e-15);
  }
}

TEST(KittiFormat, TwelveColumnsHaveNoTimestampsAndKeepRotationsAsWritten) {
  const TempFile f(std::string(kIdentity12) + "\n0.999999940 0 0 1.5 0 0.999999940 0 2.5 0 0 1 3.5\n");
  const Trajectory t = readKittiTrajectory(f.path());
  ASSERT_EQ(t.size(), 2u);
  EXPECT_FALSE(t.hasTimestamps());
  EXPECT_EQ(t.timestamp(1), 1.0);  // the index is the time
  EXPECT_EQ(t.position(1), Vector3(1.5, 2.5, 3.5));
  EXPECT_EQ(t.pose(1).rotation().matrix()(0, 0), 0.999999940);  // not re-orthonormalised
}

TEST(KittiFormat, ThirteenColumnsCarryATimestamp) {
  const TempFile f("0 " + std::string(kIdentity12) + "\n0.1037359 " + kIdentity12 + "\n");
  const Trajectory t = readKittiTrajectory(f.path());
  ASSERT_EQ(t.size(), 2u);
  EXPECT_TRUE(t.hasTimestamps());
  EXPECT_DOUBLE_EQ(t.timestamp(1), 0.1037359);
  EXPECT_EQ(t.position(1), Vector3::Zero());
}

TEST(KittiFormat, MalformedInputNamesFileAndLine) {
  const auto read = [](const std::string& path) { readKittiTrajectory(path); };
  expectInputErrorReading(read, "1 0 0 0 0 1 0 0 0 0 1\n", 1, "expected 12 numbers");
  expectInputErrorReading(read, std::string("# c\n") + kIdentity12 + "\n5 " + kIdentity12 + "\n", 3,
                          "like the first pose line");
  expectInputErrorReading(read, std::string(kIdentity12) + "\n2 0 0 0 0 1 0 0 0 0 1 0\n", 2, "not a rotation");
  // det −1: a reflection.
  expectInputErrorReading(read, std::string(kIdentity12) + "\n1 0 0 0 0 1 0 0 0 0 -1 0\n", 2, "not a rotation");
  expectInputErrorReading(read, "2 " + std::string(kIdentity12) + "\n1 " + kIdentity12 + "\n", 2, "backwards");
  expectInputErrorReading(read, std::string(kIdentity12) + "\n1 0 0 0 0 1 0 0 0 0 1 -nan\n", 2, "not finite");
  expectInputErrorReading(read, "\n\n", 0, "empty");
}

TEST(KittiFormat, WriteThenReadIsExact) {
  const TempFile source("0.5 0.999999940 -0.000000001 0.0000002 1.25 0 0.999999940 0 2.5 0 0 1 3.75\n");
  const Trajectory original = readKittiTrajectory(source.path());
  const TempFile copy("");
  writeKittiTrajectory(copy.path(), original, true);
  const Trajectory back = readKittiTrajectory(copy.path());
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back.timestamp(0), 0.5);
  EXPECT_EQ(back.pose(0).matrix(), original.pose(0).matrix());
}

TEST(EurocFormat, ReadsNanosecondsAndWFirstQuaternionSkippingExtraColumns) {
  const TempFile f(
      "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], q_RS_y [], q_RS_z [], v_x\n"
      "1403715524907143168,0.5,2.0,0.9,0.7071067811865476,0,0,0.7071067811865476,-0.002\n"
      "1403715524912143104, 0.6 ,2.1,1.0,1,0,0,0,0.1\n",
      ".csv");
  const Trajectory t = readEurocTrajectory(f.path());
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t.timestamp(0), 1403715524907143168.0 / 1e9);
  EXPECT_NEAR(t.timestamp(1) - t.timestamp(0), 0.005, 1e-6);
  EXPECT_EQ(t.position(1), Vector3(0.6, 2.1, 1.0));
  EXPECT_NEAR(t.pose(0).rotation().matrix()(1, 0), 1.0, 1e-15);  // w first: 90 degrees about z
}

TEST(EurocFormat, MalformedInputNamesFileAndLine) {
  const auto read = [](const std::string& path) { readEurocTrajectory(path); };
  expectInputErrorReading(read, "#h\n1,0,0,0,1,0,0\n", 2, "at least 8 fields", ".csv");
  expectInputErrorReading(read, "1,0,0,0,1,0,0,0\n2,0,0,0,1,0,0,0,5\n", 2, "like the first data line", ".csv");
  expectInputErrorReading(read, "1,0,0,0,1,0,0,0\n2,0,,0,1,0,0,0\n", 2, "empty", ".csv");
  expectInputErrorReading(read, "1,0,0,0,1,0,0,0\n2,0,0,0,one,0,0,0\n", 2, "not a number", ".csv");
  expectInputErrorReading(read, "1,0,0,0,1,0,0,0,\n", 1, "empty", ".csv");  // trailing delimiter: evo rejects it too
  expectInputErrorReading(read, "5,0,0,0,1,0,0,0\n4,0,0,0,1,0,0,0\n", 2, "backwards", ".csv");
  expectInputErrorReading(read, "#only a header\n", 0, "empty", ".csv");
}

TEST(TrajectoryFormat, ParsesNamesAndDispatches) {
  EXPECT_EQ(parseTrajectoryFormat("tum"), TrajectoryFormat::Tum);
  EXPECT_EQ(parseTrajectoryFormat("kitti"), TrajectoryFormat::Kitti);
  EXPECT_EQ(parseTrajectoryFormat("euroc"), TrajectoryFormat::Euroc);
  EXPECT_THROW(parseTrajectoryFormat("TUM "), InputError);
  const TempFile f(std::string(kIdentity12) + "\n");
  EXPECT_EQ(readTrajectory(f.path(), TrajectoryFormat::Kitti).size(), 1u);
  expectInputError([&] { readTrajectory(f.path(), TrajectoryFormat::Tum); }, f.path(), 1, "expected 8 numbers");
}

}  // namespace
}  // namespace semslam
