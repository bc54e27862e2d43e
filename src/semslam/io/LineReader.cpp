#include "semslam/io/LineReader.h"

#include <charconv>
#include <cmath>

#include "semslam/core/InputError.h"
#include "semslam/core/InputExcerpt.h"
#include "semslam/core/InputFile.h"
#include "semslam/graph/Key.h"

namespace semslam {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string joinNames(FieldNames names) {
  std::string joined;
  for (std::string_view name : names) {
    if (!joined.empty()) joined += ' ';
    joined += name;
  }
  return joined;
}

std::string plural(std::size_t n, const char* noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }

}  // namespace

LineReader::LineReader(std::string path) : path_(std::move(path)), stream_(openInputFile(path_)) {}

bool LineReader::next() {
  while (readBoundedLine(stream_, line_, path_, lineNumber_ + 1)) {
    ++lineNumber_;
    fields_.clear();
    names_ = {};
    genericName_ = "value";
    const char* data = line_.data();
    const std::size_t size = line_.size();
    std::size_t pos = 0;
    while (pos < size && isBlank(data[pos])) ++pos;
    if (pos == size || data[pos] == '#') continue;
    while (pos < size) {
      const std::size_t start = pos;
      while (pos < size && !isBlank(data[pos])) ++pos;
      fields_.emplace_back(data + start, pos - start);
      while (pos < size && isBlank(data[pos])) ++pos;
    }
    ++records_;
    return true;
  }
  fields_.clear();
  return false;
}

void LineReader::requireValueCount(FieldNames names) {
  names_ = names;
  const std::size_t found = valueCount();
  if (found == names.size()) return;
  const std::string expected = "expected " + plural(names.size(), "value") + " after the tag (" + joinNames(names) +
                               "), found " + std::to_string(found);
  if (found < names.size()) fail("truncated " + std::string(tag()) + " record: " + expected);
  fail("extra fields in " + std::string(tag()) + " record: " + expected);
}

void LineReader::requireAtLeast(std::size_t minimum, std::string_view what) {
  names_ = {};
  genericName_ = what;
  if (valueCount() >= minimum) return;
  fail("truncated " + std::string(tag()) + " record: expected at least " + plural(minimum, "value") +
       " after the tag (" + std::string(what) + "), found " + std::to_string(valueCount()));
}

double LineReader::number(std::size_t i) const {
  std::string_view text = fields_.at(i);
  const std::string_view original = text;
  // std::from_chars takes no leading '+', which C's strtod and every file writer may produce.
  if (text.size() > 1 && text.front() == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range) {
    fail(describe(i) + " " + inputExcerpt(original) + " is out of the range of a double");
  }
  if (error != std::errc() || end != text.data() + text.size()) {
    fail(describe(i) + " " + inputExcerpt(original) + " is not a number");
  }
  if (!std::isfinite(value)) fail(describe(i) + " is not finite: " + inputExcerpt(original));
  return value;
}

std::vector<double> LineReader::numbers(std::size_t first, std::size_t count) const {
  std::vector<double> values(count);
  for (std::size_t k = 0; k < count; ++k) values[k] = number(first + k);
  return values;
}

std::uint64_t LineReader::id(std::size_t i) const {
  const std::string_view text = fields_.at(i);
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range ||
      (error == std::errc() && end == text.data() + text.size() && value > Symbol::kIndexMask)) {
    fail(describe(i) + " " + inputExcerpt(text) + " is too large for an id (ids must be below 2^56)");
  }
  if (error != std::errc() || end != text.data() + text.size()) {
    fail(describe(i) + " " + inputExcerpt(text) + " is not a non-negative integer id");
  }
  return value;
}

void LineReader::fail(const std::string& problem) const { throw InputError(path_, lineNumber_, problem); }

std::string LineReader::describe(std::size_t i) const {
  const std::string_view name = i >= 1 && i <= names_.size() ? names_[i - 1] : genericName_;
  return std::string(tag()) + " field " + std::to_string(i) + " (" + std::string(name) + ")";
}

}  // namespace semslam
