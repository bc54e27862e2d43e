#pragma once
// Helpers shared by the simulator tests: a scratch folder per test, whole-file reads, and the sampling-error
// tolerances of moment checks.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "semslam/geometry/Matrix.h"
#include "semslam/io/MeasurementLogFile.h"

namespace semslam::test {

/// A fresh folder for the running test, removed when the object goes.
class ScratchFolder {
 public:
  ScratchFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() / ("semslam_sim_" + std::string(info->test_suite_name()) + "_" +
                                                      info->name() + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline std::string fileBytes(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  std::ostringstream contents;
  contents << stream.rdbuf();
  return contents.str();
}

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream stream(path, std::ios::binary);
  stream << text;
}

/// The bytes writeMeasurementLog produces for `log`.
inline std::string logBytes(const MeasurementLog& log, const ScratchFolder& folder, const std::string& name) {
  const std::string path = folder.file(name);
  writeMeasurementLog(path, log);
  return fileBytes(path);
}

/// Accumulates zero-mean samples and checks their covariance against an expected one, entry by entry, within
/// `sigmas` standard errors of the sample covariance: sd(S_ij) = sqrt((Σ_ii Σ_jj + Σ_ij²) / n); the sample mean
/// within `sigmas` sqrt(Σ_ii / n).
class MomentCheck {
 public:
  explicit MomentCheck(int dimension) : sum_(Vector::Zero(dimension)), outer_(Matrix::Zero(dimension, dimension)) {}
  void add(const Vector& sample) {
    sum_ += sample;
    outer_ += sample * sample.transpose();
    ++n_;
  }
  int count() const { return n_; }
  Matrix covariance() const { return outer_ / n_; }

  void expectMoments(const Matrix& expected, double sigmas = 5.0, const std::string& what = "") const {
    ASSERT_GT(n_, 0) << what;
    const Vector mean = sum_ / n_;
    const Matrix S = covariance();
    for (int i = 0; i < expected.rows(); ++i) {
      EXPECT_NEAR(mean(i), 0.0, sigmas * std::sqrt(expected(i, i) / n_)) << what << " mean(" << i << ")";
      for (int j = 0; j < expected.cols(); ++j) {
        const double sd = std::sqrt((expected(i, i) * expected(j, j) + expected(i, j) * expected(i, j)) / n_);
        EXPECT_NEAR(S(i, j), expected(i, j), sigmas * sd)
            << what << " covariance(" << i << ", " << j << "), n = " << n_;
      }
    }
  }

 private:
  Vector sum_;
  Matrix outer_;
  int n_ = 0;
};

}  // namespace semslam::test
