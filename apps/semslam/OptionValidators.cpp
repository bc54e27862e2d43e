#include "OptionValidators.h"

#include <algorithm>
#include <cctype>
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

namespace {

CLI::Validator makeDecimalInteger(bool isUnsigned) {
  return CLI::Validator(
      [isUnsigned](std::string& value) -> std::string {
        std::size_t start = 0;
        if (!value.empty() && (value[0] == '+' || value[0] == '-')) {
          if (isUnsigned && value[0] == '-') return "must be a non-negative whole number, found " + inputExcerpt(value);
          start = 1;
        }
        const std::string digits = value.substr(start);
        if (digits.size() > 1 && digits[0] == '0' && std::isalpha(static_cast<unsigned char>(digits[1]))) {
          return "must be a decimal whole number, found " + inputExcerpt(value);
        }
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return {};
        value = value.substr(0, start) + digits.substr(std::min(digits.find_first_not_of('0'), digits.size() - 1));
        return {};
      },
      "");
}

}  // namespace

const CLI::Validator& decimalInteger(bool isUnsigned) {
  static const CLI::Validator unsignedValidator = makeDecimalInteger(true);
  static const CLI::Validator signedValidator = makeDecimalInteger(false);
  return isUnsigned ? unsignedValidator : signedValidator;
}

void requireDecimalIntegers(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    if (type.rfind("UINT", 0) == 0) {
      option->transform(decimalInteger(true));
    } else if (type.rfind("INT", 0) == 0) {
      option->transform(decimalInteger(false));
    }
  }
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) requireDecimalIntegers(*command);
}

}  // namespace semslam::cli
