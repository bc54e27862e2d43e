#pragma once
// runParallelJobs: the one thread pool of the studies (HybridStudy, RobustnessStudy). Jobs 0 .. count−1 are handed
// out in index order, one at a time, to `threads` workers (the calling thread is one of them); each index runs
// exactly once. A job writes only its own result slot, so the results do not depend on the thread count or on the
// schedule (the studies are bit-for-bit deterministic).
//
// After each finished job, `progress(done, count)` is called with the number of finished jobs, serialised (never
// two calls at once). The first exception a job throws stops the hand-out (jobs already running finish), and is
// rethrown on the calling thread once every worker has joined.

#include <cstddef>
#include <functional>

namespace semslam {

/// Runs job(i) for every i in [0, count) on min(threads, count) threads (threads < 1 counts as 1).
void runParallelJobs(std::size_t count, int threads, const std::function<void(std::size_t)>& job,
                     const std::function<void(int done, int total)>& progress = {});

}  // namespace semslam
