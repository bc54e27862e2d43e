#pragma once
// ProgressBar: a one-line progress bar on a stream (stderr by default) for long runs such as the robustness study:
//   "study robustness [#########...........]  45/100  12.3 s, ~15 s left"
// On a terminal the line is rewritten in place (carriage return) at most every 0.1 s and at the end; elsewhere it
// prints nothing unless forced, and then one plain line per tenth of the work. update() is not thread-safe: call
// it from one thread at a time (RobustnessStudy serialises its progress callback).

#include <chrono>
#include <cstdio>
#include <string>

namespace semslam {

class ProgressBar {
 public:
  enum class Mode { Auto, Always, Never };  ///< Auto: only when the stream is a terminal

  ProgressBar(std::string label, int total, Mode mode = Mode::Auto, std::FILE* stream = stderr);

  /// `done` of `total` finished.
  void update(int done);
  bool enabled() const { return enabled_; }

 private:
  std::string label_;
  int total_;
  std::FILE* stream_;
  bool enabled_;
  bool terminal_;
  int printedTenths_ = -1;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace semslam
