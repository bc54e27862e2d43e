#pragma once
// EXPECT_MATRIX_NEAR(actual, expected, tol): the two matrices have the same shape and
//   max_ij |actual_ij − expected_ij| ≤ tol · max(1, max_ij |expected_ij|),
// i.e. an absolute max-norm tolerance that turns relative once the expected entries exceed 1. On failure both
// matrices are printed.

#include <gtest/gtest.h>

#include <algorithm>

#include "semslam/geometry/Matrix.h"

namespace semslam::test {

inline ::testing::AssertionResult MatricesNear(const char* actualExpr, const char* expectedExpr, const char*,
                                               const Matrix& actual, const Matrix& expected, double tol) {
  if (actual.rows() != expected.rows() || actual.cols() != expected.cols()) {
    return ::testing::AssertionFailure() << actualExpr << " is " << actual.rows() << "x" << actual.cols() << ", "
                                         << expectedExpr << " is " << expected.rows() << "x" << expected.cols();
  }
  const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
  const double error = (actual - expected).cwiseAbs().maxCoeff();
  if (error <= tol * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << actualExpr << " differs from " << expectedExpr << " by " << error
                                       << " > " << tol << " * " << scale << "\n"
                                       << actualExpr << " =\n"
                                       << actual << "\n"
                                       << expectedExpr << " =\n"
                                       << expected;
}

}  // namespace semslam::test

#define EXPECT_MATRIX_NEAR(actual, expected, tol) \
  EXPECT_PRED_FORMAT3(::semslam::test::MatricesNear, actual, expected, tol)
