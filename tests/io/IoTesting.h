#pragma once
// Helpers for the io tests: small files in a private temporary directory, and a check that a call throws an
// InputError naming a given file, line and problem.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "semslam/core/InputError.h"

namespace semslam::test {

/// A fresh directory, removed with everything in it when the object goes away.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = std::string("semslam-io-") + (info ? info->test_suite_name() : "suite") + "-" +
                             (info ? info->name() : "test") + "-" + std::to_string(::getpid());
    dir_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// Writes `contents` to the file `name` in the directory and returns its path.
  std::string write(const std::string& name, const std::string& contents) const {
    const std::string file = path(name);
    std::ofstream out(file, std::ios::binary);
    out << contents;
    return file;
  }

 private:
  std::filesystem::path dir_;
};

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace semslam::test

/// Expects `statement` to throw an InputError at `file_` line `line_` whose problem contains `part`, and whose
/// message names the file and the line ("file:line: problem", or "file: problem" for line 0).
#define EXPECT_INPUT_ERROR(statement, file_, line_, part)                                                      \
  do {                                                                                                         \
    try {                                                                                                      \
      statement;                                                                                               \
      ADD_FAILURE() << "expected an InputError from: " #statement;                                             \
    } catch (const ::semslam::InputError& error_) {                                                            \
      const std::string message_ = error_.what();                                                              \
      EXPECT_EQ(error_.file(), (file_));                                                                       \
      EXPECT_EQ(error_.line(), static_cast<std::size_t>(line_));                                               \
      EXPECT_NE(error_.problem().find(part), std::string::npos)                                                \
          << "problem \"" << error_.problem() << "\" lacks \"" << (part) << "\"";                              \
      const std::string where_ =                                                                               \
          (line_) == 0 ? std::string(file_) + ": " : std::string(file_) + ":" + std::to_string(line_) + ": ";  \
      EXPECT_EQ(message_.rfind(where_, 0), 0u) << "message \"" << message_ << "\" lacks \"" << where_ << "\""; \
    }                                                                                                          \
  } while (false)
