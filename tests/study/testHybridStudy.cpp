// HybridStudy: a small seeded version of paper A's study (the full one runs from `make results`).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

#include "semslam/study/HybridStudy.h"

using namespace semslam;

namespace {

HybridStudyOptions tinyStudy(int threads) {
  HybridStudyOptions options;
  options.layouts = generatedHybridStudyLayouts(1, 2);
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
  ASSERT_EQ(one.size(), 12u);  // 2 layouts x 2 tracks x (2 alphas with the classifier + 1 geometric)
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].layout, two[i].layout);
    EXPECT_EQ(one[i].model, two[i].model);
    EXPECT_EQ(one[i].track, two[i].track);
    EXPECT_EQ(one[i].entropy, two[i].entropy);
    EXPECT_EQ(one[i].errWmax, two[i].errWmax);
    EXPECT_EQ(one[i].detCov, two[i].detCov);
    EXPECT_EQ(one[i].mixtureNees, two[i].mixtureNees);
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
  const HybridStudyOptions options = tinyStudy(2);
  writeHybridStudy(dir.string(), options, runHybridStudy(options));
  std::ifstream summary(dir / "summary.csv");
  std::string header, line;
  std::getline(summary, header);
  EXPECT_EQ(header, "alpha,model,entropy,det_cov,err_wmax,err_wavg,heaviest_correct");
  int rows = 0;
  while (std::getline(summary, line)) ++rows;
  EXPECT_EQ(rows, 4);  // 2 alphas x 2 models
  std::ifstream runs(dir / "runs.csv");
  std::getline(runs, header);
  EXPECT_EQ(header.find("time_s"), std::string::npos) << header;  // wall-clock times: timings.csv only
  EXPECT_TRUE(std::filesystem::exists(dir / "nees.csv"));
  std::ifstream timings(dir / "timings.csv");
  std::getline(timings, header);
  EXPECT_EQ(header, "layout,alpha,model,track,rank,sampling_s,time_s,threads,ranks,wall_time_s");
  rows = 0;
  while (std::getline(timings, line)) ++rows;
  EXPECT_EQ(rows, 12);  // one per run
  rows = 0;
  while (std::getline(runs, line)) ++rows;
  EXPECT_EQ(rows, 16);  // 2 layouts x 2 alphas x 2 tracks x 2 models
  EXPECT_TRUE(std::filesystem::exists(dir / "layouts.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "layouts" / "layout_1.json"));
  std::filesystem::remove_all(dir);
}

TEST(HybridStudy, TheGeometricRunDoesNotDependOnAlpha) {
  // The premise of running the geometric model once per track: alpha changes only the class scores, which the
  // geometric model does not read. The same run (same seed) at two alphas gives the same row, bit for bit, while
  // the classifier's differs.
  for (WeightMethod weights : {WeightMethod::Sampled, WeightMethod::Importance, WeightMethod::Analytic}) {
    SCOPED_TRACE(static_cast<int>(weights));
    HybridStudyOptions low = tinyStudy(1);
    low.steps = 8;  // long enough that every track sees objects (the classifier's rows then differ)
    low.hybrid.weights = weights;
    HybridStudyOptions high = low;
    low.alphas = {0.0};
    high.alphas = {0.5};
    for (const HybridStudyRun& run : hybridStudyRuns(low)) {
      const HybridStudyRow a = runHybridStudyRun(low, run), b = runHybridStudyRun(high, run);
      ASSERT_TRUE(a.error.empty()) << a.error;
      if (run.classifier) {
        EXPECT_TRUE(a.entropy != b.entropy || a.errWmax != b.errWmax || a.detCov != b.detCov)
            << "track " << run.track;
        continue;
      }
      EXPECT_EQ(a.entropy, b.entropy) << "track " << run.track;
      EXPECT_EQ(a.detCov, b.detCov);
      EXPECT_EQ(a.errWmax, b.errWmax);
      EXPECT_EQ(a.errWavg, b.errWavg);
      EXPECT_EQ(a.finalNees, b.finalNees);
      EXPECT_EQ(a.mixtureNees, b.mixtureNees);
      EXPECT_EQ(a.components, b.components);
      EXPECT_EQ(a.heaviestHistoryCorrect, b.heaviestHistoryCorrect);
    }
  }
}

TEST(HybridStudy, TheTablePairsEveryAlphasClassifierRunWithTheTracksGeometricRun) {
  const HybridStudyOptions options = tinyStudy(2);
  const std::vector<HybridStudyRun> runs = hybridStudyRuns(options);
  const std::vector<HybridStudyRow> executed = runHybridStudy(options);
  const std::vector<HybridStudyRow> table = hybridStudyTable(options, executed);
  ASSERT_EQ(table.size(), 16u);
  // The executed row of each run, by (layout, alpha index, track, model).
  std::map<std::tuple<int, std::size_t, int, bool>, const HybridStudyRow*> ran;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    ran[{static_cast<int>(runs[r].layout), runs[r].alphaIndex, runs[r].track, runs[r].classifier}] = &executed[r];
  }
  // runs.csv's order: layouts, alphas inside, tracks inside, the classifier then the geometric model; each alpha's
  // classifier row is that alpha's run, each geometric row the track's one run (at the first alpha), relabelled.
  std::size_t i = 0;
  for (int layout = 0; layout < 2; ++layout) {
    for (std::size_t a = 0; a < options.alphas.size(); ++a) {
      for (int track = 0; track < options.tracks; ++track) {
        for (bool classifier : {true, false}) {
          const HybridStudyRow& row = table[i++];
          const HybridStudyRow& source = *ran.at({layout, classifier ? a : 0, track, classifier});
          EXPECT_EQ(row.layout, layout);
          EXPECT_EQ(row.alpha, options.alphas[a]);
          EXPECT_EQ(row.track, track);
          EXPECT_EQ(row.model, classifier ? "classifier" : "geometric");
          EXPECT_EQ(row.entropy, source.entropy) << "row " << i - 1;
          EXPECT_EQ(row.errWmax, source.errWmax) << "row " << i - 1;
          EXPECT_EQ(row.finalNees, source.finalNees) << "row " << i - 1;
        }
      }
    }
  }
  EXPECT_THROW(hybridStudyTable(options, std::vector<HybridStudyRow>(3)), std::invalid_argument);
}

TEST(HybridStudy, LayoutsHaveTheirOwnTracks) {
  // The same seed and track in two layouts draws two different tracks: layouts do not share track shapes.
  EXPECT_NE(layoutTrackSeed(1, 0), layoutTrackSeed(1, 1));
  EXPECT_NE(layoutTrackSeed(1, 0), layoutTrackSeed(2, 0));
  EXPECT_EQ(layoutTrackSeed(5, 3), layoutTrackSeed(5, 3));
  const std::vector<Aliased2dScenario> layouts = generatedHybridStudyLayouts(4, 3);
  ASSERT_EQ(layouts.size(), 3u);
  EXPECT_EQ(layouts[2].name, "aliased2d-layout-6");
  EXPECT_THROW(generatedHybridStudyLayouts(1, 0), std::invalid_argument);
}

TEST(HybridStudy, NeesIsSplitByWhetherTheHeaviestHistoryIsCorrect) {
  // Hand-made rows: the heaviest component's NEES is 3 on the runs whose history is right and 300 on the one that is
  // wrong; the mixture's is 2. A failed run (NaN) and a mixture without a unique mean (NaN) are left out.
  // Each track's geometric run (NEES 1000, wrong: it must not leak into the classifier's subsets) follows it, in
  // the order of hybridStudyRuns.
  std::vector<HybridStudyRow> rows;
  const auto add = [&](int track, double nees, bool correct, double mixture) {
    HybridStudyRow row;
    row.alpha = 0.25;
    row.model = "classifier";
    row.track = track;
    row.finalNees = nees;
    row.heaviestComponentCorrect = correct;
    row.mixtureNees = mixture;
    rows.push_back(row);
    row.model = "geometric";
    row.finalNees = row.mixtureNees = 1000.0;
    row.heaviestComponentCorrect = false;
    rows.push_back(row);
  };
  add(0, 3.0, true, 2.0);
  add(1, 3.0, true, 2.0);
  add(2, 300.0, false, 2.0);
  add(3, 3.0, true, std::numeric_limits<double>::quiet_NaN());
  add(4, std::numeric_limits<double>::quiet_NaN(), true, std::numeric_limits<double>::quiet_NaN());
  rows[rows.size() - 2].error = "failed";  // track 4's classifier run (its geometric run follows it)
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "semslam_hybrid_study_nees_split";
  std::filesystem::remove_all(dir);
  HybridStudyOptions options;
  options.layouts = generatedHybridStudyLayouts(1, 1);
  options.alphas = {0.25};
  options.tracks = 5;
  writeHybridStudy(dir.string(), options, rows);
  std::ifstream nees(dir / "nees.csv");
  std::string line;
  std::getline(nees, line);
  EXPECT_EQ(line, "alpha,model,subset,nees_mean,count,lower,upper");
  std::map<std::string, std::pair<double, int>> subsets;
  while (std::getline(nees, line)) {
    std::stringstream fields(line);
    std::string alpha, model, subset, mean, count;
    std::getline(fields, alpha, ',');
    std::getline(fields, model, ',');
    std::getline(fields, subset, ',');
    std::getline(fields, mean, ',');
    std::getline(fields, count, ',');
    if (model == "classifier") subsets[subset] = {std::stod(mean), std::stoi(count)};
  }
  EXPECT_EQ(subsets["heaviest"], std::make_pair(309.0 / 4.0, 4));
  EXPECT_EQ(subsets["heaviest_correct"], std::make_pair(3.0, 3));
  EXPECT_EQ(subsets["heaviest_wrong"], std::make_pair(300.0, 1));
  EXPECT_EQ(subsets["mixture"], std::make_pair(2.0, 3));
  std::filesystem::remove_all(dir);
}
