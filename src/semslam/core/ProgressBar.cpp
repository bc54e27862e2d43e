#include "semslam/core/ProgressBar.h"

#include <unistd.h>

#include <algorithm>

namespace semslam {

ProgressBar::ProgressBar(std::string label, int total, Mode mode, std::FILE* stream)
    : label_(std::move(label)),
      total_(std::max(total, 1)),
      stream_(stream),
      terminal_(isatty(fileno(stream)) != 0),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_ - std::chrono::seconds(1)) {
  enabled_ = mode == Mode::Always || (mode == Mode::Auto && terminal_);
}

void ProgressBar::update(int done) {
  if (!enabled_) return;
  done = std::clamp(done, 0, total_);
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const bool last = done == total_;
  if (terminal_) {
    if (!last && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;
    constexpr int kWidth = 30;
    const int filled = done * kWidth / total_;
    std::string bar(filled, '#');
    bar.append(kWidth - filled, '.');
    std::fprintf(stream_, "\r%s [%s] %d/%d  %.1f s", label_.c_str(), bar.c_str(), done, total_, elapsed);
    if (done > 0 && !last) std::fprintf(stream_, ", ~%.0f s left  ", elapsed * (total_ - done) / done);
    if (last) std::fprintf(stream_, "              \n");
  } else {
    const int tenths = done * 10 / total_;
    if (tenths <= printedTenths_) return;
    printedTenths_ = tenths;
    std::fprintf(stream_, "%s: %d/%d  %.1f s\n", label_.c_str(), done, total_, elapsed);
  }
  std::fflush(stream_);
}

}  // namespace semslam
