#include "semslam/io/NumericTable.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "semslam/core/InputError.h"
#include "semslam/core/InputExcerpt.h"
#include "semslam/core/InputFile.h"

namespace semslam {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
  while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> splitFields(std::string_view line, Separator separator) {
  std::vector<std::string_view> fields;
  if (separator == Separator::Whitespace) {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && isBlank(line[i])) ++i;
      const std::size_t start = i;
      while (i < line.size() && !isBlank(line[i])) ++i;
      if (i > start) fields.push_back(line.substr(start, i - start));
    }
  } else {
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line.find(',', start);
      fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                                : comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
  }
  return fields;
}

double parseNumber(std::string_view field, const std::string& path, std::size_t line, std::size_t column) {
  const std::string where = "field " + std::to_string(column);
  if (field.empty()) throw InputError(path, line, where + " is empty");
  // from_chars rejects a leading '+', which strtod and Python accept: allow it for compatibility.
  std::string_view digits = field;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range) {
    throw InputError(path, line, where + " " + inputExcerpt(field) + " is out of the range of a double");
  }
  if (error != std::errc() || end != digits.data() + digits.size()) {
    throw InputError(path, line, where + " " + inputExcerpt(field) + " is not a number");
  }
  if (!std::isfinite(value)) {
    throw InputError(path, line, where + " " + inputExcerpt(field) + " is not finite");
  }
  return value;
}

}  // namespace

std::vector<NumericRow> readNumericTable(const std::string& path, Separator separator) {
  std::ifstream in = openInputFile(path);
  std::vector<NumericRow> rows;
  std::string text;
  std::size_t lineNumber = 0;
  while (readBoundedLine(in, text, path, lineNumber + 1)) {
    ++lineNumber;
    std::string_view line = text;
    if (lineNumber == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string_view content = trim(line);
    if (content.empty() || content.front() == '#') continue;
    NumericRow row;
    row.line = lineNumber;
    const std::vector<std::string_view> fields = splitFields(content, separator);
    row.values.reserve(fields.size());
    for (std::size_t i = 0; i < fields.size(); ++i) row.values.push_back(parseNumber(fields[i], path, lineNumber, i + 1));
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace semslam
