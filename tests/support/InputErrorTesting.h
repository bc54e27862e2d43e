#pragma once
// expectInputError: runs an action that must throw InputError, and checks that the error names the right file
// and (1-based) line and that its message contains a given fragment; expectInputErrorReading does the same for a
// reader given a temporary file with the content under test.

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "semslam/core/InputError.h"
#include "support/TempFile.h"

namespace semslam::test {

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

/// Writes `content` to a temporary file (name ending in `suffix`), reads it with `read` and expects an InputError for that file at `line`
/// whose problem mentions `fragment`.
inline void expectInputErrorReading(const std::function<void(const std::string& path)>& read,
                                    const std::string& content, std::size_t line, const std::string& fragment,
                                    const std::string& suffix = ".txt") {
  const TempFile file(content, suffix);
  expectInputError([&] { read(file.path()); }, file.path(), line, fragment);
}

}  // namespace semslam::test
