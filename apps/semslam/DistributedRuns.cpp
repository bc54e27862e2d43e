#include "DistributedRuns.h"

#include <chrono>
#include <cstdlib>
#include <stdexcept>

#include "semslam/study/ParallelJobs.h"

#ifdef SEMSLAM_WITH_MPI
#include <mpi.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#endif

namespace semslam::cli {

bool launchedByMpiLauncher() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"}) {
    if (std::getenv(variable) != nullptr) return true;
  }
  return false;
}

bool isGatheringRank() {
  for (const char* variable : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}) {
    if (const char* rank = std::getenv(variable)) return std::strtol(rank, nullptr, 10) == 0;
  }
  return true;
}

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

DistributedResults runInThisProcess(std::size_t count, int threads,
                                    const std::function<std::string(std::size_t)>& job,
                                    const std::function<void(int, int)>& progress) {
  const auto start = Clock::now();
  DistributedResults out;
  out.results.resize(count);
  runParallelJobs(count, threads, [&](std::size_t i) { out.results[i] = job(i); }, progress);
  out.layout.threads = threads;
  out.layout.jobRanks.assign(count, 0);
  out.layout.wallSeconds = secondsSince(start);
  return out;
}

#ifdef SEMSLAM_WITH_MPI

// Messages between a helper rank (> 0) and rank 0. A result carries its job index (8 bytes) and the job's bytes;
// an assignment carries an index, or -1 for "no more".
enum Tag : int { kResult = 1, kRequest = 2, kAssign = 3, kDone = 4 };

bool staticSchedule() {
  const char* schedule = std::getenv("SEMSLAM_MPI_SCHEDULE");
  if (schedule == nullptr || std::strcmp(schedule, "queue") == 0) return false;
  if (std::strcmp(schedule, "static") == 0) return true;
  throw std::runtime_error(std::string("SEMSLAM_MPI_SCHEDULE: '") + schedule + "' is neither queue nor static");
}

/// The n of SEMSLAM_TEST_RANK1_EXIT_AT_JOB (0: unset).
long rankExitHook() {
  const char* value = std::getenv("SEMSLAM_TEST_RANK1_EXIT_AT_JOB");
  return value == nullptr ? 0 : std::strtol(value, nullptr, 10);
}

class MpiProcess {
 public:
  MpiProcess() {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
      int provided = 0;
      // Only the main thread talks to MPI; worker threads run jobs (FUNNELED).
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
      owned_ = true;
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiProcess() {
    if (owned_) MPI_Finalize();
  }
  MpiProcess(const MpiProcess&) = delete;
  MpiProcess& operator=(const MpiProcess&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  bool owned_ = false;
  int rank_ = 0, size_ = 1;
};

/// The job indices this process's worker threads take, one at a time: a shared counter over every index (rank 0
/// of the work queue, which hands the same counter's indices to the other ranks), a fixed list (the static
/// partition), or indices the main thread receives from rank 0 (a helper of the work queue).
class JobFeed {
 public:
  JobFeed(std::size_t count, std::atomic<std::size_t>* shared) : count_(count), shared_(shared) {}

  std::optional<std::size_t> next() {
    if (shared_ != nullptr) {
      const std::size_t index = (*shared_)++;
      return index < count_ ? std::optional<std::size_t>(index) : std::nullopt;
    }
    std::unique_lock<std::mutex> lock(mutex_);
    ready_.wait(lock, [this] { return !queue_.empty() || closed_; });
    if (queue_.empty()) return std::nullopt;
    const std::size_t index = queue_.front();
    queue_.pop_front();
    return index;
  }
  void push(std::size_t index) {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(index);
    ready_.notify_one();
  }
  void close() {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
    ready_.notify_all();
  }

 private:
  std::size_t count_;
  std::atomic<std::size_t>* shared_;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::size_t> queue_;
  bool closed_ = false;
};

/// What the worker threads hand to the main thread: finished results, the first failure, and when all are done.
class Outbox {
 public:
  struct Finished {
    std::size_t index;
    std::string bytes;
  };
  void put(std::size_t index, std::string bytes) {
    std::lock_guard<std::mutex> lock(mutex_);
    finished_.push_back({index, std::move(bytes)});
    changed_.notify_one();
  }
  void fail(std::size_t index, const std::string& message) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!failure_) failure_ = "job " + std::to_string(index) + ": " + message;
    changed_.notify_one();
  }
  void workerStopped() {
    std::lock_guard<std::mutex> lock(mutex_);
    ++stopped_;
    changed_.notify_one();
  }
  /// Waits up to `timeout` for something new, then takes what finished.
  std::vector<Finished> take(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, timeout, [this] { return !finished_.empty() || failure_ || stopped_ > seenStopped_; });
    seenStopped_ = stopped_;
    std::vector<Finished> out;
    out.swap(finished_);
    return out;
  }
  std::optional<std::string> failure() {
    std::lock_guard<std::mutex> lock(mutex_);
    return failure_;
  }
  int stopped() {
    std::lock_guard<std::mutex> lock(mutex_);
    return stopped_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<Finished> finished_;
  std::optional<std::string> failure_;
  int stopped_ = 0, seenStopped_ = 0;
};

/// `threads` worker threads taking indices from the feed and running them into the outbox.
class Workers {
 public:
  Workers(int threads, int rank, JobFeed& feed, Outbox& outbox, const std::function<std::string(std::size_t)>& job)
      : threads_(threads) {
    const long exitAt = rank == 1 ? rankExitHook() : 0;
    for (int t = 0; t < threads; ++t) {
      pool_.emplace_back([&feed, &outbox, &job, exitAt, this] {
        while (const std::optional<std::size_t> index = feed.next()) {
          if (exitAt > 0 && ++started_ == exitAt) {
            std::fprintf(stderr, "semslam: rank 1 exits at its job %ld (test hook SEMSLAM_TEST_RANK1_EXIT_AT_JOB)\n",
                         exitAt);
            std::fflush(stderr);
            std::_Exit(3);
          }
          try {
            outbox.put(*index, job(*index));
          } catch (const std::exception& error) {
            outbox.fail(*index, error.what());
            break;
          }
        }
        outbox.workerStopped();
      });
    }
  }
  ~Workers() {
    for (std::thread& thread : pool_) thread.join();
  }
  int threads() const { return threads_; }

 private:
  int threads_;
  std::atomic<long> started_{0};
  std::vector<std::thread> pool_;
};

[[noreturn]] void abortStudy(const MpiProcess& mpi, const std::string& failure) {
  std::fprintf(stderr, "semslam: failed on rank %d: %s; aborting every rank\n", mpi.rank(), failure.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::_Exit(1);
}

constexpr std::chrono::milliseconds kPoll{1};

/// Rank 0: runs jobs, answers the helpers' requests, stores every result by index.
DistributedResults gatherOnRankZero(const MpiProcess& mpi, std::size_t count, int threads, bool partitioned,
                                    const std::function<std::string(std::size_t)>& job,
                                    const std::function<void(int, int)>& progress) {
  const auto start = Clock::now();
  DistributedResults out;
  out.results.resize(count);
  out.layout.threads = threads;
  out.layout.ranks = mpi.size();
  out.layout.jobRanks.assign(count, -1);
  std::size_t done = 0;
  const auto store = [&](std::size_t index, std::string bytes, int rank) {
    if (index >= count || out.layout.jobRanks[index] != -1) {
      throw std::runtime_error("distributed runs: job " + std::to_string(index) + " reported twice or unknown");
    }
    out.results[index] = std::move(bytes);
    out.layout.jobRanks[index] = rank;
    ++done;
    if (progress) progress(static_cast<int>(done), static_cast<int>(count));
  };

  std::atomic<std::size_t> nextIndex{0};
  JobFeed feed(count, partitioned ? nullptr : &nextIndex);
  if (partitioned) {
    for (std::size_t i = 0; i < count; i += static_cast<std::size_t>(mpi.size())) feed.push(i);
    feed.close();
  }
  Outbox outbox;
  int helpersDone = 0;
  {
    Workers workers(threads, 0, feed, outbox, job);
    std::vector<char> buffer;
    while (helpersDone < mpi.size() - 1 || outbox.stopped() < threads || done < count) {
      // A worker puts its last result before it stops: read the count first, so that a check against it below
      // never misses a result put between the two.
      const int stopped = outbox.stopped();
      for (Outbox::Finished& finished : outbox.take(kPoll)) store(finished.index, std::move(finished.bytes), 0);
      if (const auto failure = outbox.failure()) abortStudy(mpi, *failure);
      int arrived = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
      while (arrived) {
        int size = 0;
        MPI_Get_count(&status, MPI_BYTE, &size);
        buffer.resize(static_cast<std::size_t>(size));
        MPI_Recv(buffer.data(), size, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        if (status.MPI_TAG == kResult) {
          std::uint64_t index = 0;
          std::memcpy(&index, buffer.data(), sizeof index);
          store(index, std::string(buffer.begin() + sizeof index, buffer.end()), status.MPI_SOURCE);
        } else if (status.MPI_TAG == kRequest) {
          const std::size_t index = nextIndex++;
          const std::int64_t assigned = index < count ? static_cast<std::int64_t>(index) : -1;
          MPI_Send(&assigned, sizeof assigned, MPI_BYTE, status.MPI_SOURCE, kAssign, MPI_COMM_WORLD);
        } else if (status.MPI_TAG == kDone) {
          ++helpersDone;
        }
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
      }
      // A helper sends its DONE after its last result (MPI keeps one sender's messages in order).
      if (stopped == threads && helpersDone == mpi.size() - 1 && done < count) {
        throw std::runtime_error("distributed runs: every rank finished but " + std::to_string(count - done) +
                                 " jobs are missing");
      }
    }
  }
  out.layout.wallSeconds = secondsSince(start);
  return out;
}

/// A rank > 0: runs the jobs it is given (or its partition), sends each result to rank 0 as it finishes.
void helpRankZero(const MpiProcess& mpi, std::size_t count, int threads, bool partitioned,
                  const std::function<std::string(std::size_t)>& job) {
  JobFeed feed(count, nullptr);
  int outstanding = 0;  // requests rank 0 has not answered yet
  bool exhausted = partitioned;
  const auto request = [&] {
    MPI_Send(nullptr, 0, MPI_BYTE, 0, kRequest, MPI_COMM_WORLD);
    ++outstanding;
  };
  if (partitioned) {
    for (std::size_t i = static_cast<std::size_t>(mpi.rank()); i < count; i += static_cast<std::size_t>(mpi.size())) {
      feed.push(i);
    }
    feed.close();
  } else {
    for (int t = 0; t < threads; ++t) request();
  }
  Outbox outbox;
  {
    Workers workers(threads, mpi.rank(), feed, outbox, job);
    std::vector<char> message;
    for (bool last = false; !last;) {
      // Every worker stopped before the outbox is emptied: nothing more can come (a worker puts its last result
      // before it stops), so this is the last round once every request is answered.
      last = outbox.stopped() == threads;
      for (Outbox::Finished& finished : outbox.take(kPoll)) {
        const std::uint64_t index = finished.index;
        message.resize(sizeof index + finished.bytes.size());
        std::memcpy(message.data(), &index, sizeof index);
        std::memcpy(message.data() + sizeof index, finished.bytes.data(), finished.bytes.size());
        MPI_Send(message.data(), static_cast<int>(message.size()), MPI_BYTE, 0, kResult, MPI_COMM_WORLD);
        if (!exhausted) request();  // the thread that finished wants its next job
      }
      if (const auto failure = outbox.failure()) abortStudy(mpi, *failure);
      int arrived = 0;
      MPI_Iprobe(0, kAssign, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE);
      while (arrived) {
        std::int64_t assigned = 0;
        MPI_Recv(&assigned, sizeof assigned, MPI_BYTE, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        --outstanding;
        if (assigned >= 0) {
          feed.push(static_cast<std::size_t>(assigned));
        } else if (!exhausted) {
          exhausted = true;
          feed.close();
        }
        MPI_Iprobe(0, kAssign, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE);
      }
      last = last && outstanding == 0;
    }
  }
  MPI_Send(nullptr, 0, MPI_BYTE, 0, kDone, MPI_COMM_WORLD);
}

#endif  // SEMSLAM_WITH_MPI

}  // namespace

DistributedResults runDistributed(std::size_t count, int threads, const std::function<std::string(std::size_t)>& job,
                                  const std::function<void(int, int)>& progress) {
  if (!launchedByMpiLauncher()) return runInThisProcess(count, threads, job, progress);
#ifdef SEMSLAM_WITH_MPI
  const bool partitioned = staticSchedule();
  const MpiProcess mpi;
  if (mpi.size() == 1) return runInThisProcess(count, threads, job, progress);
  // An error on one rank must not leave the others waiting for it (MPI_Finalize waits for every rank).
  try {
    if (mpi.rank() == 0) return gatherOnRankZero(mpi, count, threads, partitioned, job, progress);
    helpRankZero(mpi, count, threads, partitioned, job);
  } catch (const std::exception& error) {
    abortStudy(mpi, error.what());
  }
  DistributedResults helper;
  helper.gathered = false;
  return helper;
#else
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (size != nullptr && std::strtol(size, nullptr, 10) > 1) {
    throw std::runtime_error(
        "started by mpirun, but this semslam was built without MPI (cmake -DSEMSLAM_WITH_MPI=ON, with "
        "libopenmpi-dev installed): every process would run the whole study");
  }
  return runInThisProcess(count, threads, job, progress);
#endif
}

}  // namespace semslam::cli
