#pragma once
// Aliased2dLayout: seeded object layouts for paper A's statistical study (docs/simulators.md, "Generated layouts").
//
// Paper A's scenario (sec. V, Fig. 3a) is "a set of scattered objects of the same class, i.e. objects differ in their
// position and orientation", N = 6, M = 2, and its study samples many tracks in one such layout. A generated layout
// is N = 2P objects of class 0 in P pairs that are translated copies of one another:
//     pair p = {a_p, a_p + d},   p = 0 … P−1,   d one offset shared by every pair,
// so a view that holds one pair (or one object) and nothing else fits every pair (every object) equally well:
// range and bearing depend only on x⁻¹ t_o, and the view from x of pair p is the view from x + (a_q − a_p) of pair q
// (objects renamed). Geometry alone cannot tell the pairs apart at first views; the initial pose prior (Σ_p, 10 m in
// position) barely can. What can is the viewpoint-dependent classifier (A, eq. 18): every object's heading is drawn
// on its own, so corresponding objects of two pairs generally show the camera different sides. (The default parking
// aisle is the special case a_p = (6p, 2), d = (2.5, −4), headings chosen by hand.)
//
// The rule, every draw from the layout seed's own stream (SimStream::Layout) through models/Sampling.h:
//   1. d: length uniform in [pairOffsetMin, pairOffsetMax] (both objects of a pair fit one view of the default
//      sensor: 6 m, 90°), direction uniform in [−π, π);
//   2. the anchors a_0, a_1, … in turn, uniform over the box positions that keep a_p + d in the box too, redrawn
//      until both of the pair's objects keep `pairSpacing` from every object of the pairs placed before; after
//      kAttemptsPerAnchor failures of one anchor the whole layout (d included) is drawn again. Every two objects
//      are then at least min(pairOffsetMin, pairSpacing) apart: 2 m by default, twice the tracks' clearance, so a
//      track can pass between any two;
//   3. the headings, uniform in [−π, π), object by object (pair 0's a_0, a_0 + d, then pair 1's, …).
// Object ids are 0 … N−1 in that order. A seed gives the same layout, bit for bit, with every standard library.

#include <cstdint>
#include <vector>

#include "semslam/sim/Aliased2dScenario.h"

namespace semslam {

struct Aliased2dLayoutRule {
  int pairs = 3;                  ///< P: N = 2P objects (paper A: N = 6)
  Point2 boxMin{0.0, -5.0};       ///< the box the objects stand in (the default aisle's length, 10 m wide)
  Point2 boxMax{15.0, 5.0};
  double pairOffsetMin = 2.0;     ///< |d|, metres
  double pairOffsetMax = 4.0;
  double pairSpacing = 3.0;       ///< metres between objects of different pairs
};

/// Throws std::invalid_argument for a rule that cannot hold: pairs < 1, an empty box, offsets outside
/// (0, box diagonal] or min > max, a negative or non-finite spacing.
void validateAliased2dLayoutRule(const Aliased2dLayoutRule& rule);

/// The objects of layout `layoutSeed` under `rule` (see above). Throws std::runtime_error when no layout was found in
/// kLayoutRounds rounds (a rule whose spacings do not fit its box).
std::vector<Aliased2dObject> generateAliased2dLayout(std::uint64_t layoutSeed, const Aliased2dLayoutRule& rule = {});

/// The built-in default scenario (priors, motion, sensor, classifier, start) with the objects of layout `layoutSeed`,
/// named "aliased2d-layout-<seed>", its arena centred on the box.
Aliased2dScenario generatedAliased2dScenario(std::uint64_t layoutSeed, const Aliased2dLayoutRule& rule = {});

}  // namespace semslam
