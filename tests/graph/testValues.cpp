#include <gtest/gtest.h>

#include "semslam/graph/Key.h"
#include "semslam/graph/Values.h"

using namespace semslam;

TEST(Key, SymbolsRoundTripThroughStrings) {
  EXPECT_EQ(keyToString(poseKey(12)), "x12");
  EXPECT_EQ(keyToString(landmarkKey(3)), "l3");
  EXPECT_EQ(keyToString(42), "42");
  EXPECT_EQ(keyFromString("x12"), poseKey(12));
  EXPECT_EQ(keyFromString("l3"), landmarkKey(3));
  EXPECT_EQ(keyFromString("42"), Key{42});
  EXPECT_NE(poseKey(3), landmarkKey(3));
  EXPECT_EQ(Symbol(poseKey(7)).tag(), 'x');
  EXPECT_EQ(Symbol(poseKey(7)).index(), 7u);
  EXPECT_THROW(keyFromString("x"), std::invalid_argument);
  EXPECT_THROW(keyFromString("12a"), std::invalid_argument);
  EXPECT_THROW(keyFromString(""), std::invalid_argument);
}

TEST(Values, InsertAtUpdateAndTypeChecks) {
  Values values;
  values.insert(poseKey(0), SE2(1.0, 2.0, 0.3));
  values.insert(landmarkKey(0), Point2(4.0, 5.0));
  EXPECT_EQ(values.size(), 2u);
  EXPECT_EQ(values.totalDimension(), 5);
  EXPECT_DOUBLE_EQ(values.at<SE2>(poseKey(0)).x(), 1.0);
  EXPECT_THROW(values.insert(poseKey(0), SE2()), std::invalid_argument);
  EXPECT_THROW(values.at<SE3>(poseKey(0)), std::out_of_range);
  EXPECT_THROW(values.at<SE2>(poseKey(5)), std::out_of_range);
  values.update(landmarkKey(0), Point2(1.0, 1.0));
  EXPECT_DOUBLE_EQ(values.at<Point2>(landmarkKey(0)).x(), 1.0);
  EXPECT_THROW(values.update(poseKey(9), SE2()), std::out_of_range);
  EXPECT_EQ(typeName(values.value(poseKey(0))), "SE2");
  const std::vector<Key> keys = values.keys();
  EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
}

TEST(Values, RetractIsTheRightPerturbation) {
  const SE2 pose(1.0, 2.0, 0.3);
  const Vector3 delta(0.1, -0.2, 0.05);
  const Value moved = retract(Value(pose), delta);
  EXPECT_TRUE(std::get<SE2>(moved).equals(pose * SE2::Exp(delta), 1e-15));
  const Value point = retract(Value(Point3(1.0, 2.0, 3.0)), Vector3(1.0, 1.0, 1.0));
  EXPECT_TRUE(std::get<Point3>(point).isApprox(Point3(2.0, 3.0, 4.0)));
  EXPECT_EQ(dimension(Value(SE3())), 6);
  EXPECT_EQ(dimension(Value(SO2())), 1);
}
