#include "semslam/sim/Aliased2dLayout.h"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "semslam/models/Sampling.h"
#include "semslam/sim/SimulationStreams.h"

namespace semslam {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kAttemptsPerAnchor = 1000;
constexpr int kLayoutRounds = 100;

double uniform(double low, double high, std::mt19937& rng) { return low + (high - low) * uniform01(rng); }

bool finitePoint(const Point2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

/// One try at steps 1-2 of the rule: the 2P object positions, or an empty vector when an anchor found no place.
std::vector<Point2> drawPositions(const Aliased2dLayoutRule& rule, std::mt19937& rng) {
  const double length = uniform(rule.pairOffsetMin, rule.pairOffsetMax, rng);
  const double direction = uniform(-kPi, kPi, rng);
  const Point2 offset(length * std::cos(direction), length * std::sin(direction));
  // Anchors a with a and a + d in the box: a in [max(lo, lo − d), min(hi, hi − d)] per axis.
  const Point2 low = rule.boxMin.cwiseMax(rule.boxMin - offset);
  const Point2 high = rule.boxMax.cwiseMin(rule.boxMax - offset);
  if ((high - low).minCoeff() < 0.0) return {};  // d does not fit the box
  std::vector<Point2> positions;
  for (int pair = 0; pair < rule.pairs; ++pair) {
    bool placed = false;
    for (int attempt = 0; attempt < kAttemptsPerAnchor && !placed; ++attempt) {
      const Point2 anchor(uniform(low.x(), high.x(), rng), uniform(low.y(), high.y(), rng));
      placed = true;
      for (std::size_t other = 0; other < positions.size() && placed; ++other) {  // all of earlier pairs
        placed = (positions[other] - anchor).norm() >= rule.pairSpacing &&
                 (positions[other] - (anchor + offset)).norm() >= rule.pairSpacing;
      }
      if (placed) {
        positions.push_back(anchor);
        positions.push_back(anchor + offset);
      }
    }
    if (!placed) return {};
  }
  return positions;
}

}  // namespace

void validateAliased2dLayoutRule(const Aliased2dLayoutRule& rule) {
  const auto fail = [](const std::string& problem) { throw std::invalid_argument("layout rule: " + problem); };
  if (rule.pairs < 1) fail("at least one pair is needed");
  if (!finitePoint(rule.boxMin) || !finitePoint(rule.boxMax) || (rule.boxMax - rule.boxMin).minCoeff() <= 0.0) {
    fail("the box must be finite with max > min on both axes");
  }
  const double diagonal = (rule.boxMax - rule.boxMin).norm();
  if (!(rule.pairOffsetMin > 0.0 && rule.pairOffsetMin <= rule.pairOffsetMax && rule.pairOffsetMax <= diagonal)) {
    fail("pair offsets must satisfy 0 < min <= max <= the box's diagonal");
  }
  if (!(rule.pairSpacing >= 0.0 && std::isfinite(rule.pairSpacing))) fail("the pair spacing must be finite and >= 0");
}

std::vector<Aliased2dObject> generateAliased2dLayout(std::uint64_t layoutSeed, const Aliased2dLayoutRule& rule) {
  validateAliased2dLayoutRule(rule);
  std::mt19937 rng = simulationStream(layoutSeed, 0, SimStream::Layout);
  for (int round = 0; round < kLayoutRounds; ++round) {
    const std::vector<Point2> positions = drawPositions(rule, rng);
    if (positions.empty()) continue;
    std::vector<Aliased2dObject> objects;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const double heading = uniform(-kPi, kPi, rng);
      objects.push_back({static_cast<int>(i), 0, SE2(positions[i].x(), positions[i].y(), heading)});
    }
    return objects;
  }
  throw std::runtime_error("no layout of seed " + std::to_string(layoutSeed) + " fits the rule in " +
                           std::to_string(kLayoutRounds) + " rounds: its spacings do not fit its box");
}

Aliased2dScenario generatedAliased2dScenario(std::uint64_t layoutSeed, const Aliased2dLayoutRule& rule) {
  Aliased2dScenario scenario = defaultAliased2dScenario();
  scenario.name = "aliased2d-layout-" + std::to_string(layoutSeed);
  scenario.objects = generateAliased2dLayout(layoutSeed, rule);
  scenario.motion.arenaCenter = (rule.boxMin + rule.boxMax) / 2.0;
  validateAliased2dScenario(scenario);
  return scenario;
}

}  // namespace semslam
