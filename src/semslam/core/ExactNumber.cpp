#include "semslam/core/ExactNumber.h"

#include <charconv>
#include <cstdio>

namespace semslam {

std::string shortestExactNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string seventeenDigitNumber(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace semslam
