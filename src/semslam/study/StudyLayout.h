#pragma once
// StudyLayout: what differs between two runs of the same study with the same arguments: how the runs were laid
// out (worker threads per process, processes, which process ran each run) and how long the study took. A study
// folder keeps these in timings.csv, together with every run's own times, apart from the results, so that every
// other file of the folder is byte-identical for any --threads, for `mpirun -np N` and for a plain launch
// (docs/studies.md).

#include <vector>

namespace semslam {

struct StudyLayout {
  int threads = 1;            ///< worker threads per process
  int ranks = 1;              ///< processes (MPI ranks); 1 without mpirun
  std::vector<int> jobRanks;  ///< per job (a study's unit of distribution), the rank that ran it; empty: all rank 0
  double wallSeconds = 0.0;   ///< the whole study, on the process that gathered the results

  /// The rank that ran job `index` (0 when jobRanks does not say).
  int rankOf(std::size_t index) const { return index < jobRanks.size() ? jobRanks[index] : 0; }
};

}  // namespace semslam
