#pragma once
// Helpers for the dataset converter tests: the raw files read independently of the converters' code path (plain
// stream parsing), a write-and-read-back round trip, and comparisons of two logs.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/IoTesting.h"
#include "semslam/io/MeasurementLogFile.h"
#include "semslam/models/MeasurementLog.h"

namespace semslam::test {

/// The numeric rows of a whitespace-separated text file, skipping blank lines and lines starting with '#'.
inline std::vector<std::vector<double>> rawRows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    std::vector<double> row;
    double value = 0.0;
    while (fields >> value) row.push_back(value);
    rows.push_back(row);
  }
  return rows;
}

/// The lines of a text file whose first field is `tag`.
inline std::size_t countTagged(const std::string& path, const std::string& tag) {
  std::ifstream in(path);
  std::size_t count = 0;
  std::string line, first;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    if (fields >> first && first == tag) ++count;
  }
  return count;
}

/// Writes `log` into `dir`, reads it back with readMeasurementLog (which must accept it) and returns the bytes.
inline std::string writeAndReadBack(const MeasurementLog& log, const TempDir& dir, const std::string& name,
                                    MeasurementLog* readBack = nullptr) {
  const std::string path = dir.path(name);
  writeMeasurementLog(path, log);
  MeasurementLog read;
  EXPECT_NO_THROW(read = readMeasurementLog(path)) << path;
  if (readBack != nullptr) *readBack = std::move(read);
  return readText(path);
}

inline bool samePose(const Pose& a, const Pose& b) {
  if (a.index() != b.index()) return false;
  if (const auto* p = std::get_if<SE2>(&a)) return p->equals(std::get<SE2>(b), 0.0);
  return std::get<SE3>(a).equals(std::get<SE3>(b), 0.0);
}

inline std::size_t detectionCount(const MeasurementLog& log) {
  std::size_t n = 0;
  for (const TimeStep& step : log.steps) n += step.detections.size();
  return n;
}

/// Expects the two logs to agree in everything but the detections' labels and the header's source text, and
/// returns the number of detections whose labels differ.
inline std::size_t expectSameExceptLabels(const MeasurementLog& a, const MeasurementLog& b) {
  EXPECT_EQ(a.header.dimension, b.header.dimension);
  EXPECT_EQ(a.header.classes, b.header.classes);
  EXPECT_EQ(a.header.semantic, b.header.semantic);
  EXPECT_EQ(a.header.landmarkTruth.size(), b.header.landmarkTruth.size());
  std::size_t differentLabels = 0;
  EXPECT_EQ(a.steps.size(), b.steps.size());
  if (a.steps.size() != b.steps.size()) return 0;
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    const TimeStep& s = a.steps[k];
    const TimeStep& t = b.steps[k];
    EXPECT_EQ(s.time, t.time);
    EXPECT_EQ(s.odometry.has_value(), t.odometry.has_value());
    if (s.odometry && t.odometry) {
      EXPECT_TRUE(samePose(s.odometry->increment, t.odometry->increment)) << "step " << k;
      EXPECT_EQ(s.odometry->covariance, t.odometry->covariance) << "step " << k;
    }
    EXPECT_EQ(s.truePose.has_value(), t.truePose.has_value());
    if (s.truePose && t.truePose) {
      EXPECT_TRUE(samePose(*s.truePose, *t.truePose));
    }
    EXPECT_EQ(s.detections.size(), t.detections.size());
    if (s.detections.size() != t.detections.size()) continue;
    for (std::size_t i = 0; i < s.detections.size(); ++i) {
      const Detection& d = s.detections[i];
      const Detection& e = t.detections[i];
      EXPECT_EQ(d.geometry, e.geometry);
      EXPECT_EQ(d.covariance, e.covariance);
      EXPECT_EQ(d.truthId, e.truthId);
      EXPECT_EQ(d.label.has_value(), e.label.has_value());
      if (d.label != e.label) ++differentLabels;
    }
  }
  return differentLabels;
}

}  // namespace semslam::test
