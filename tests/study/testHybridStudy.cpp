// HybridStudy: a small seeded version of paper A's study (the full one runs from `make results`).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "semslam/study/HybridStudy.h"

using namespace semslam;

namespace {

HybridStudyOptions tinyStudy(int threads) {
  HybridStudyOptions options;
  options.tracks = 2;
  options.steps = 3;
  options.alphas = {0.0, 0.5};
  options.seed = 4;
  options.threads = threads;
  options.hybrid.samples = 100;
  return options;
}

}  // namespace

TEST(HybridStudy, ResultsDoNotDependOnTheThreadCount) {
  const std::vector<HybridStudyRow> one = runHybridStudy(tinyStudy(1)), two = runHybridStudy(tinyStudy(2));
  ASSERT_EQ(one.size(), 8u);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].model, two[i].model);
    EXPECT_EQ(one[i].track, two[i].track);
    EXPECT_EQ(one[i].entropy, two[i].entropy);
    EXPECT_EQ(one[i].errWmax, two[i].errWmax);
    EXPECT_EQ(one[i].detCov, two[i].detCov);
    EXPECT_TRUE(one[i].error.empty()) << one[i].error;
    EXPECT_GE(one[i].entropy, 0.0);
    EXPECT_GT(one[i].detCov, 0.0);
  }
}

TEST(HybridStudy, RunsOneByOneEqualTheStudy) {
  const HybridStudyOptions options = tinyStudy(1);
  const std::vector<HybridStudyRun> runs = hybridStudyRuns(options);
  const std::vector<HybridStudyRow> rows = runHybridStudy(options);
  ASSERT_EQ(runs.size(), rows.size());
  for (std::size_t i : {std::size_t{0}, rows.size() - 1}) {
    const HybridStudyRow row = runHybridStudyRun(options, runs[i]);
    EXPECT_EQ(row.model, rows[i].model);
    EXPECT_EQ(row.track, rows[i].track);
    EXPECT_EQ(row.entropy, rows[i].entropy);
    EXPECT_EQ(row.finalNees, rows[i].finalNees);
  }
  HybridStudyOptions none = options;
  none.tracks = 0;
  EXPECT_THROW(hybridStudyRuns(none), std::invalid_argument);
}

TEST(HybridStudy, WritesRunsSummaryNeesAndTimings) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "semslam_hybrid_study_test";
  std::filesystem::remove_all(dir);
  writeHybridStudy(dir.string(), runHybridStudy(tinyStudy(2)));
  std::ifstream summary(dir / "summary.csv");
  std::string header, line;
  std::getline(summary, header);
  EXPECT_EQ(header, "alpha,model,entropy,det_cov,err_wmax,err_wavg");
  int rows = 0;
  while (std::getline(summary, line)) ++rows;
  EXPECT_EQ(rows, 4);  // 2 alphas x 2 models
  std::ifstream runs(dir / "runs.csv");
  std::getline(runs, header);
  EXPECT_EQ(header.find("time_s"), std::string::npos) << header;  // wall-clock times: timings.csv only
  EXPECT_TRUE(std::filesystem::exists(dir / "nees.csv"));
  std::ifstream timings(dir / "timings.csv");
  std::getline(timings, header);
  EXPECT_EQ(header, "alpha,model,track,rank,sampling_s,time_s,threads,ranks,wall_time_s");
  rows = 0;
  while (std::getline(timings, line)) ++rows;
  EXPECT_EQ(rows, 8);
  std::filesystem::remove_all(dir);
}
