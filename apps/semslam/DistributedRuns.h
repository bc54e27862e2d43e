#pragma once
// DistributedRuns: a study's jobs (independent runs, or cells of runs) spread over the processes that mpirun (or
// Slurm's srun) started, each process running its share on its own `threads` worker threads (N ranks x T threads),
// and gathered on rank 0, which alone gets the results back and writes the study's folder. Launched without mpirun
// (or built without MPI) it is the studies' one thread pool in this process (study/ParallelJobs.h).
//
// Contract, whatever the layout:
//   - job(i) is called exactly once for every i in [0, count), on some rank, from a worker thread; it returns run
//     i's result encoded (study/StudyRowBytes.h). A job's result depends on its index only (its seed is derived
//     from the index, never from the rank or the arrival order), so rank 0 holds the same results, in index
//     order, for any number of ranks and threads: the folder is byte-identical but for timings.csv.
//   - Rank 0 also runs jobs (it hands them out from its main thread while its worker threads run). The schedule
//     is a work queue: every worker thread of every rank takes the next index from rank 0 when it is free, so
//     uneven run times (high noise levels run longer) balance out; SEMSLAM_MPI_SCHEDULE=static makes it a fixed
//     round-robin partition instead (rank r runs r, r + N, ...), the alternative measured in docs/studies.md.
//   - progress(done, count) is called on rank 0 only, from one thread, counting jobs finished on every rank.
//   - A job that throws fails the study: without MPI the exception propagates (as runParallelJobs); under MPI the
//     failing rank prints "semslam: failed: job I on rank R: ..." and aborts every rank (MPI_Abort, exit 1), so
//     nothing waits forever. A rank that dies (killed, crashed) makes mpirun end the whole job with an error; rank
//     0 writes nothing, so the output folder is never half new.
//   - MPI_Init runs only when the environment says a launcher started this process (OMPI_COMM_WORLD_SIZE,
//     PMIX_RANK, PMI_RANK); MPI stays in apps/: the library never links libmpi.
//
// Test hook (tests/cli/testStudyMpi.cpp): SEMSLAM_TEST_RANK1_EXIT_AT_JOB=n makes rank 1 exit abruptly (exit code
// 3, no MPI_Finalize) when it starts its n-th job (n >= 1), as a crashed process would.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "semslam/study/StudyLayout.h"

namespace semslam::cli {

struct DistributedResults {
  bool gathered = true;              ///< this process holds the results (rank 0, or the only process)
  std::vector<std::string> results;  ///< by job index; empty where !gathered
  StudyLayout layout;                ///< threads, ranks, the rank of every job (where gathered)
};

/// Whether a launcher (mpirun, srun) started this process: its environment names a rank.
bool launchedByMpiLauncher();

/// Whether this process will hold the results (rank 0 by its environment, or no launcher), known before MPI_Init:
/// a helper rank draws no progress.
bool isGatheringRank();

DistributedResults runDistributed(std::size_t count, int threads,
                                  const std::function<std::string(std::size_t)>& job,
                                  const std::function<void(int done, int total)>& progress = {});

}  // namespace semslam::cli
