#pragma once
// ProgressBar: the one progress display of every long command (run, simulate, study hybrid, study robustness),
// on a stream (stderr by default), the same on and off a terminal:
//   on a terminal   one line rewritten in place (carriage return) at most every 0.1 s, ended at the last update:
//                     "study robustness [#########.....................]  45/100  12.3 s, ~15 s left"
//   elsewhere       (a log file, a pipe, CI) one plain line every `period` (5 s by default) and one at the end:
//                     "study robustness: 45/100  12.3 s, ~15 s left"
//                     "study robustness: 100/100  27.0 s"
// so a long command is never silent for more than `period`. `quiet` (the commands' --quiet) prints nothing.
// update() is not thread-safe: call it from one thread at a time (the studies serialise their progress callback,
// study/ParallelJobs.h).

#include <chrono>
#include <cstdio>
#include <string>

namespace semslam {

class ProgressBar {
 public:
  using Seconds = std::chrono::duration<double>;

  ProgressBar(std::string label, int total, bool quiet = false, std::FILE* stream = stderr,
              Seconds period = Seconds(5.0));

  /// `done` of `total` finished (clamped to [0, total]); done == total prints the last line.
  void update(int done);
  bool enabled() const { return !quiet_; }

 private:
  void drawBar(int done, double elapsed, bool last);
  void printLine(int done, double elapsed, bool last);

  std::string label_;
  int total_;
  bool quiet_;
  std::FILE* stream_;
  bool terminal_;
  Seconds period_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace semslam
