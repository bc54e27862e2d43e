#pragma once
// Helpers for the eval tests: temporary files with given content, and checking that an InputError names the
// right file and line.

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "semslam/core/InputError.h"

namespace semslam::test {

/// A file in the temporary directory, removed when the object goes out of scope.
class TempFile {
 public:
  explicit TempFile(const std::string& content, const std::string& suffix = ".txt") {
    static std::atomic<int> counter{0};
    path_ = (std::filesystem::temp_directory_path() /
             ("semslam_eval_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + suffix))
                .string();
    std::ofstream(path_, std::ios::binary) << content;
  }
  ~TempFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// Runs `action`, expecting an InputError for `file` at `line` whose problem mentions `fragment`.
inline void expectInputError(const std::function<void()>& action, const std::string& file, std::size_t line,
                             const std::string& fragment = "") {
  try {
    action();
    ADD_FAILURE() << "expected InputError at " << file << ":" << line;
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file) << error.what();
    EXPECT_EQ(error.line(), line) << error.what();
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos)
        << "message '" << error.what() << "' lacks '" << fragment << "'";
  }
}

}  // namespace semslam::test
