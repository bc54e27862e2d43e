#include "OptionValidators.h"

#include <charconv>
#include <cstdint>
#include <string>

#include "semslam/core/InputExcerpt.h"

namespace semslam::cli {

const CLI::Validator& unsignedInteger64() {
  static const CLI::Validator validator(
      [](std::string& value) -> std::string {
        std::uint64_t parsed = 0;
        const char* end = value.data() + value.size();
        const auto [stop, error] = std::from_chars(value.data(), end, parsed);
        if (error == std::errc::result_out_of_range) {
          return "must be at most 18446744073709551615 (2^64 - 1), found " + inputExcerpt(value);
        }
        if (value.empty() || error != std::errc() || stop != end) {
          return "must be a non-negative whole number, found " + inputExcerpt(value);
        }
        return {};
      },
      "UINT64");
  return validator;
}

}  // namespace semslam::cli
