#pragma once
// SimulationStreams: the random number streams of the simulators, derived from one user seed.
//
// Every simulated quantity has its own stream (controls, motion noise, priors, geometric noise, semantic noise,
// ...), and every track of a multi-track run its own set, so that
//   - the same (seed, track) gives the same bytes, whatever else is simulated alongside;
//   - changing one part of a simulation leaves the others alone: a different classifier alpha changes the class
//     scores only, not the tracks, the priors or the range-bearing noise (paper A's alpha study, Fig. 5, compares
//     alphas on the same tracks), and a different clutter rate leaves the true detections unchanged.
//
// A stream is std::mt19937 seeded through std::seed_seq with the words
//     (seed mod 2³², seed div 2³², track, stream id, 0x5e551a77)
// Both std::seed_seq::generate and mt19937's seeding from a seed sequence are specified exactly by the C++
// standard, and the simulators draw only through models/Sampling.h (raw engine outputs), so a seed gives the
// same numbers with every standard library.

#include <cstdint>
#include <random>

namespace semslam {

/// What a stream is used for; the numeric values are part of the output's definition: never renumber them.
enum class SimStream : std::uint32_t {
  Controls = 1,     // aliased2d: the random turns of the track-sampling policy
  MotionNoise = 2,  // the motion (odometry) noise
  Priors = 3,       // prior means drawn around the truth
  Geometry = 4,     // range-bearing(-elevation) measurement noise
  Semantic = 5,     // classifier scores or labels
  Landmarks = 6,    // semantic: landmark placement and classes
  Path = 7,         // semantic: the shape of a generated path
  Detection = 8,    // semantic: missed detections
  Clutter = 9,      // semantic: false detections
  Layout = 10,      // aliased2d: a generated object layout (track 0 of the layout seed)
  Lift3d = 11,      // aliased 3D lift: the objects' map heights and the 3D geometric noise
};

/// The stream `stream` of track `track` for the user seed `seed`.
std::mt19937 simulationStream(std::uint64_t seed, std::uint32_t track, SimStream stream);

}  // namespace semslam
