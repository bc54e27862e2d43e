#include "semslam/sim/SimulationStreams.h"

namespace semslam {

std::mt19937 simulationStream(std::uint64_t seed, std::uint32_t track, SimStream stream) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed & 0xffffffffu), static_cast<std::uint32_t>(seed >> 32), track,
                         static_cast<std::uint32_t>(stream), std::uint32_t{0x5e551a77u}};
  return std::mt19937(sequence);
}

}  // namespace semslam
