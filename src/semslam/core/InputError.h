#pragma once
// The one exception type for bad input: a malformed file, a non-finite number, an unknown key, inconsistent
// dimensions, empty data. It names where the problem is (file and line, when there is one) and what it is.
// The command-line tool turns it into a message on stderr and exit code 2.

#include <stdexcept>
#include <string>

namespace semslam {

class InputError : public std::runtime_error {
 public:
  /// A problem at `line` (1-based) of `file`; line 0 means the file as a whole.
  InputError(const std::string& file, std::size_t line, const std::string& problem)
      : std::runtime_error(format(file, line, problem)), file_(file), line_(line), problem_(problem) {}

  /// A problem with an input that is not a file (a command-line value, an in-memory structure).
  explicit InputError(const std::string& problem) : std::runtime_error(problem), problem_(problem) {}

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& problem() const { return problem_; }

 private:
  static std::string format(const std::string& file, std::size_t line, const std::string& problem) {
    return line == 0 ? file + ": " + problem : file + ":" + std::to_string(line) + ": " + problem;
  }

  std::string file_;
  std::size_t line_ = 0;
  std::string problem_;
};

}  // namespace semslam
