// StudyRowBytes: a study's rows survive the trip through bytes bit for bit (NaN, absent optionals, errors
// included), and bytes that are not a record are refused.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "semslam/study/StudyRowBytes.h"

namespace semslam {
namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(StudyRowBytes, HybridRowRoundTripsBitForBit) {
  HybridStudyRow row;
  row.layout = 9;
  row.alpha = 0.1;
  row.model = "geometric";
  row.track = 7;
  row.entropy = 1.0 / 3.0;
  row.detCov = 1e-300;
  row.errWmax = -0.0;
  row.errWavg = std::numeric_limits<double>::quiet_NaN();
  row.ess = 2.5;
  row.components = 12;
  row.finalNees = 3.25;
  row.heaviestComponentCorrect = true;
  row.mixtureNees = 2.0 / 3.0;
  row.assocWeightAtStep = 0.95;
  row.disambiguatedAtStep = true;
  row.heaviestHistoryCorrect = false;
  row.gateLostMass = 1e-9;
  row.analyticTotalVariation = 0.125;
  row.sampledCandidates = 123456789012LL;
  row.samplingSeconds = 0.5;
  row.seconds = 1.75;
  row.error = "a failure, with\nnewlines";
  const HybridStudyRow back = decodeHybridStudyRow(encodeHybridStudyRow(row));
  EXPECT_EQ(back.layout, row.layout);
  EXPECT_EQ(back.model, row.model);
  EXPECT_EQ(back.track, row.track);
  EXPECT_EQ(back.heaviestComponentCorrect, row.heaviestComponentCorrect);
  for (auto member : {&HybridStudyRow::alpha, &HybridStudyRow::entropy, &HybridStudyRow::detCov,
                      &HybridStudyRow::errWmax, &HybridStudyRow::errWavg, &HybridStudyRow::ess,
                      &HybridStudyRow::finalNees, &HybridStudyRow::mixtureNees, &HybridStudyRow::assocWeightAtStep, &HybridStudyRow::gateLostMass,
                      &HybridStudyRow::analyticTotalVariation, &HybridStudyRow::samplingSeconds,
                      &HybridStudyRow::seconds}) {
    EXPECT_TRUE(sameBits(back.*member, row.*member));
  }
  EXPECT_EQ(back.components, row.components);
  EXPECT_EQ(back.disambiguatedAtStep, row.disambiguatedAtStep);
  EXPECT_EQ(back.heaviestHistoryCorrect, row.heaviestHistoryCorrect);
  EXPECT_EQ(back.sampledCandidates, row.sampledCandidates);
  EXPECT_EQ(back.error, row.error);
}

TEST(StudyRowBytes, RobustnessRowsRoundTripBitForBit) {
  std::vector<RobustnessRow> rows(3);
  rows[0].axis = RobustnessAxis::Misclassification;
  rows[0].level = 0.3;
  rows[0].seed = 4;
  rows[0].method = "mm-nh";
  rows[0].ateRmse = 0.1 + 0.2;
  rows[0].landmarksEstimated = 17;
  rows[0].landmarksTrue = 15;
  rows[0].stuck = false;
  rows[1].method = "known";
  rows[1].ateRmse = rows[1].rotRmse = std::numeric_limits<double>::quiet_NaN();
  rows[1].error = "singular system";
  rows[2].stuck = true;
  const std::vector<RobustnessRow> back = decodeRobustnessRows(encodeRobustnessRows(rows));
  ASSERT_EQ(back.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(back[i].axis, rows[i].axis);
    EXPECT_TRUE(sameBits(back[i].level, rows[i].level));
    EXPECT_EQ(back[i].seed, rows[i].seed);
    EXPECT_EQ(back[i].method, rows[i].method);
    for (auto member : {&RobustnessRow::ateRmse, &RobustnessRow::rotRmse, &RobustnessRow::daAccuracy,
                        &RobustnessRow::daAccuracyReal, &RobustnessRow::timeSeconds}) {
      EXPECT_TRUE(sameBits(back[i].*member, rows[i].*member));
    }
    EXPECT_EQ(back[i].landmarksEstimated, rows[i].landmarksEstimated);
    EXPECT_EQ(back[i].landmarksTrue, rows[i].landmarksTrue);
    EXPECT_EQ(back[i].stuck, rows[i].stuck);
    EXPECT_EQ(back[i].error, rows[i].error);
  }
  EXPECT_EQ(robustnessCsv(back), robustnessCsv(rows));
}

TEST(StudyRowBytes, RefusesBytesItDidNotWrite) {
  const std::string bytes = encodeRobustnessRows(std::vector<RobustnessRow>(2));
  EXPECT_THROW(decodeRobustnessRows(bytes.substr(0, bytes.size() - 1)), std::runtime_error);
  EXPECT_THROW(decodeRobustnessRows(bytes + "x"), std::runtime_error);
  EXPECT_THROW(decodeHybridStudyRow(""), std::runtime_error);
}

}  // namespace
}  // namespace semslam
