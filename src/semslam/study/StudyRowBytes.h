#pragma once
// StudyRowBytes: a study's result rows as bytes, so that a run done in another process (an MPI rank,
// apps/semslam/DistributedRuns.h) reaches the process that writes the folder bit for bit: every double travels as
// its 8 bytes (no text round trip, NaN kept), strings with their length, optionals with a presence byte.
// The bytes are native-endian with native type sizes: every process of one study runs the same binary on the
// same kind of machine (a homogeneous cluster). decode* throws std::runtime_error on bytes it did not write
// (a wrong length).

#include <string>
#include <vector>

#include "semslam/study/HybridStudy.h"
#include "semslam/study/RobustnessStudy.h"

namespace semslam {

std::string encodeHybridStudyRow(const HybridStudyRow& row);
HybridStudyRow decodeHybridStudyRow(const std::string& bytes);

/// One robustness cell's rows (every method on the cell).
std::string encodeRobustnessRows(const std::vector<RobustnessRow>& rows);
std::vector<RobustnessRow> decodeRobustnessRows(const std::string& bytes);

}  // namespace semslam
