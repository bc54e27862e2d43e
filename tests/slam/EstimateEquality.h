#pragma once
// Bit-for-bit equality of two estimates, shared by the tests of runs that must reproduce one another (a fork's
// continuation, a branched run without a split).

#include <gtest/gtest.h>

#include "semslam/graph/Values.h"

namespace semslam {

/// Bit-for-bit equality of two estimates: the same keys, and each value the same type with equal stored coordinates.
inline void expectSameEstimate(const Values& a, const Values& b) {
  ASSERT_EQ(a.keys(), b.keys());
  for (Key key : a.keys()) {
    const Value& x = a.value(key);
    const Value& y = b.value(key);
    ASSERT_EQ(x.index(), y.index()) << "key " << key;
    if (const auto* p = std::get_if<SE2>(&x)) {
      const SE2& q = std::get<SE2>(y);
      EXPECT_EQ(p->x(), q.x()) << "key " << key;
      EXPECT_EQ(p->y(), q.y()) << "key " << key;
      EXPECT_EQ(p->rotation().c(), q.rotation().c()) << "key " << key;
      EXPECT_EQ(p->rotation().s(), q.rotation().s()) << "key " << key;
    } else if (const auto* p = std::get_if<Point2>(&x)) {
      EXPECT_EQ(p->x(), std::get<Point2>(y).x()) << "key " << key;
      EXPECT_EQ(p->y(), std::get<Point2>(y).y()) << "key " << key;
    } else {
      ADD_FAILURE() << "SE2 poses and Point2 landmarks only; key " << key;
    }
  }
}

}  // namespace semslam
