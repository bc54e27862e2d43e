#include "semslam/core/ProgressBar.h"

#include <unistd.h>

#include <algorithm>

namespace semslam {

ProgressBar::ProgressBar(std::string label, int total, bool quiet, std::FILE* stream, Seconds period)
    : label_(std::move(label)),
      total_(std::max(total, 1)),
      quiet_(quiet),
      stream_(stream),
      terminal_(isatty(fileno(stream)) != 0),
      period_(period),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_) {}

void ProgressBar::update(int done) {
  if (quiet_ || finished_) return;
  done = std::clamp(done, 0, total_);
  const auto now = std::chrono::steady_clock::now();
  const bool last = done == total_;
  const auto sinceDraw = now - lastDraw_;
  // On a terminal the first draw comes at once; off it, the first plain line after one period.
  const bool due = terminal_ ? (sinceDraw >= std::chrono::milliseconds(100) || lastDraw_ == start_)
                             : sinceDraw >= period_;
  if (!last && !due) return;
  lastDraw_ = now;
  finished_ = last;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (terminal_) {
    drawBar(done, elapsed, last);
  } else {
    printLine(done, elapsed, last);
  }
  std::fflush(stream_);
}

void ProgressBar::drawBar(int done, double elapsed, bool last) {
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(static_cast<long long>(done) * kWidth / total_);
  std::string bar(filled, '#');
  bar.append(kWidth - filled, '.');
  std::fprintf(stream_, "\r%s [%s] %d/%d  %.1f s", label_.c_str(), bar.c_str(), done, total_, elapsed);
  if (done > 0 && !last) std::fprintf(stream_, ", ~%.0f s left  ", elapsed * (total_ - done) / done);
  if (last) std::fprintf(stream_, "              \n");
}

void ProgressBar::printLine(int done, double elapsed, bool last) {
  std::fprintf(stream_, "%s: %d/%d  %.1f s", label_.c_str(), done, total_, elapsed);
  if (done > 0 && !last) std::fprintf(stream_, ", ~%.0f s left", elapsed * (total_ - done) / done);
  std::fprintf(stream_, "\n");
}

}  // namespace semslam
