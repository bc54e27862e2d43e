// hypotheses.jsonl (io/HypothesesJsonl.h): every component's history is written once, as β_k and the index of its
// ancestor on the previous line. Following the ancestors back gives, at every step, exactly the histories the
// belief held then, and the association marginal's entries name components with their histories. The lines go
// through SpooledText (io/SpooledText.h), which gives back what was appended.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "semslam/eval/HypothesisMetrics.h"
#include "semslam/hybrid/HybridRun.h"
#include "semslam/io/HypothesesJsonl.h"
#include "semslam/io/SpooledText.h"
#include "semslam/sim/Aliased2dSimulator.h"

namespace semslam {
namespace {

using Steps = std::vector<std::vector<int>>;

TEST(SpooledText, GivesBackWhatWasAppendedAndTakesMoreAfterACopy) {
  SpooledText spool;
  spool.append("first line\n");
  spool.append("");
  spool.append(std::string(100000, 'x') + "\n");
  std::ostringstream once, twice;
  spool.copyTo(once);
  EXPECT_EQ(once.str(), "first line\n" + std::string(100000, 'x') + "\n");
  spool.append("third\n");
  spool.copyTo(twice);
  EXPECT_EQ(twice.str(), once.str() + "third\n");
  EXPECT_EQ(spool.bytes(), twice.str().size());
}

// β_1:k of component i of line k, following ancestors back.
Steps historyFromLines(const std::vector<nlohmann::json>& lines, int k, int i) {
  Steps steps;
  for (; k >= 0; --k) {
    const nlohmann::json& component = lines[static_cast<std::size_t>(k)]["components"][static_cast<std::size_t>(i)];
    steps.insert(steps.begin(), component["beta"].get<std::vector<int>>());
    i = component["ancestor"].get<int>();
  }
  EXPECT_EQ(i, -1) << "the first line's components have no ancestor";
  return steps;
}

TEST(HypothesesJsonl, AncestorsGiveBackEveryHistoryTheBeliefHeldAtEveryStep) {
  // Aliased bays without the classifier: several histories stay alive and branch from each other.
  const MeasurementLog log = simulateAliased2dTrack(defaultAliased2dScenario(), /*seed=*/2, /*track=*/4, /*steps=*/6);
  HybridOptions options;
  options.useSemantics = false;
  options.weights = WeightMethod::Analytic;
  std::vector<std::vector<Steps>> held;  // per step, per component
  std::vector<std::vector<Steps>> marginalHistories;
  std::vector<nlohmann::json> lines;
  runHybrid(log, options, {}, [&](const HybridStepRecord& record) {
    held.emplace_back();
    for (const HypothesisComponent& c : record.marginals.components) held.back().push_back(c.associations.steps());
    marginalHistories.emplace_back();
    for (const AssociationHypothesis& a : record.marginals.association) {
      marginalHistories.back().push_back(a.associations.steps());
    }
    const HypothesisMetrics metrics = evaluateHypotheses(record.marginals.components, std::nullopt);
    lines.push_back(nlohmann::json::parse(hypothesesJsonLine(record, metrics)));
  });
  ASSERT_EQ(lines.size(), log.steps.size());
  std::size_t most = 0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    EXPECT_EQ(lines[k]["step"].get<std::size_t>(), k);
    const nlohmann::json& components = lines[k]["components"];
    ASSERT_EQ(components.size(), held[k].size());
    most = std::max(most, held[k].size());
    for (std::size_t i = 0; i < components.size(); ++i) {
      EXPECT_EQ(historyFromLines(lines, static_cast<int>(k), static_cast<int>(i)), held[k][i])
          << "step " << k << ", component " << i;
    }
    const nlohmann::json& marginal = lines[k]["association_marginal"];
    ASSERT_EQ(marginal.size(), marginalHistories[k].size());
    for (std::size_t a = 0; a < marginal.size(); ++a) {
      EXPECT_EQ(historyFromLines(lines, static_cast<int>(k), marginal[a]["component"].get<int>()),
                marginalHistories[k][a]);
    }
  }
  EXPECT_GT(most, 1u) << "the test needs a belief with several components";
}

}  // namespace
}  // namespace semslam
