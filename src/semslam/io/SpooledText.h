#pragma once
// SpooledText: text produced while a long computation runs (hypotheses.jsonl: one line per step of a hybrid run)
// held in an unnamed temporary file (std::tmpfile: deleted by the system when closed, even on a crash) instead of
// in memory, then copied to its destination when the results are written. Its size is on disk, not in the process.
//
// Move-only. Throws std::runtime_error when the temporary file cannot be created, written or read back.

#include <cstddef>
#include <cstdio>
#include <memory>
#include <ostream>
#include <string_view>

namespace semslam {

class SpooledText {
 public:
  SpooledText();

  void append(std::string_view text);
  /// Bytes appended so far.
  std::size_t bytes() const { return bytes_; }
  /// Writes everything appended so far to `out`.
  void copyTo(std::ostream& out) const;

 private:
  struct Close {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  std::unique_ptr<std::FILE, Close> file_;
  std::size_t bytes_ = 0;
};

}  // namespace semslam
