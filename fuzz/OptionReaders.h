#pragma once
// The command-line tool's numeric option parsing as a fuzz harness ("options"): CLI11 with semslam's validators
// (apps/semslam/OptionValidators.h), on one option of each numeric kind the tool has. Each input is a list of
// values, one a line (a trailing '\r' kept: it is part of the value); line k is given to option k of the list below
// (lines past the last option are ignored).
//
// The contract: CLI11 refuses the values with a CLI::ParseError (rethrown as InputError: `semslam` exits 2 with
// it), or accepts them and each value is what its text says: a seed or count equal to the decimal number written
// (no saturation at 2^64 - 1, no "-5" wrapped around, no "0467" read as octal 311), an integer inside its range, a positive or non-negative
// number that is so. Anything else (another exception, a value other than its text) is a finding.

#include <cstdint>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "../apps/semslam/OptionValidators.h"
#include "semslam/core/InputError.h"

namespace semslam::fuzz {

namespace detail {

/// The decimal digits of `text` without leading zeros ("0" for zeros only).
inline std::string canonicalDigits(const std::string& text) {
  const std::size_t first = text.find_first_not_of('0');
  return first == std::string::npos ? "0" : text.substr(first);
}

inline void require(bool holds, const std::string& what) {
  if (!holds) throw std::logic_error("option parsed to a value its text does not say: " + what);
}

}  // namespace detail

inline void parseNumericOptions(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> values;
  for (std::size_t start = 0; start <= text.size() && values.size() < 7;) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    values.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  static const char* const kNames[] = {"--seed", "--max-steps", "--steps", "--classes", "--delta", "--scale",
                                       "--sigmas"};
  CLI::App app("semslam numeric options");
  std::uint64_t seed = 0;
  std::size_t maxSteps = 0;
  int steps = 0, classes = 1;
  double delta = 1.0, scale = 0.0;
  std::vector<double> sigmas;
  app.add_option("--seed", seed)->check(cli::unsignedInteger64());
  app.add_option("--max-steps", maxSteps)->check(cli::unsignedInteger64());
  app.add_option("--steps", steps)->check(CLI::Range(0, 1000000));
  app.add_option("--classes", classes)->check(CLI::Range(1, 2048));
  app.add_option("--delta", delta)->check(CLI::PositiveNumber);
  app.add_option("--scale", scale)->check(CLI::NonNegativeNumber);
  app.add_option("--sigmas", sigmas)->delimiter(',');
  cli::requireDecimalIntegers(app);  // as the tool's main.cpp does
  std::vector<std::string> arguments;  // CLI11 takes them in reverse order
  for (std::size_t k = values.size(); k-- > 0;) {
    arguments.push_back(values[k]);
    arguments.push_back(kNames[k]);
  }
  try {
    app.parse(arguments);
  } catch (const CLI::ParseError& error) {
    throw InputError(path, 0, error.what());
  }
  if (values.size() > 0) detail::require(std::to_string(seed) == detail::canonicalDigits(values[0]), "--seed");
  if (values.size() > 1) detail::require(std::to_string(maxSteps) == detail::canonicalDigits(values[1]), "--max-steps");
  detail::require(steps >= 0 && steps <= 1000000, "--steps");
  if (values.size() > 2 && values[2].find_first_not_of("+0123456789") == std::string::npos && values[2].size() > 0) {
    const std::string digits = values[2][0] == '+' ? values[2].substr(1) : values[2];
    detail::require(std::to_string(steps) == detail::canonicalDigits(digits), "--steps");
  }
  detail::require(classes >= 1 && classes <= 2048, "--classes");
  detail::require(!(delta <= 0.0), "--delta");
  detail::require(!(scale < 0.0), "--scale");
}

}  // namespace semslam::fuzz
