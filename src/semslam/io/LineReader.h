#pragma once
// LineReader: a line-oriented text file read record by record, with every field checked.
//
// A record is a non-blank line whose first non-blank character is not '#'; its fields are separated by spaces,
// tabs (and a stray '\r' of a CRLF file). Field 0 is the record's tag ("EDGE_SE2"); values are numbered from 1.
// Every accessor checks what it returns and throws InputError(file, line, problem) naming the record's tag,
// the field's position and name, and what is wrong with it (missing, extra, not a number, not finite, not an id).

#include <cstdint>
#include <fstream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace semslam {

/// Names of a record's values after its tag, in order, for messages: {"i", "j", "dx", ...}. The reader keeps
/// the span, so it must outlive the record (static constexpr arrays do).
using FieldNames = std::span<const std::string_view>;

class LineReader {
 public:
  /// Opens `path`; throws InputError(path, 0, ...) if it does not exist or cannot be read.
  explicit LineReader(std::string path);

  /// Advances to the next record; false at the end of the file.
  bool next();

  const std::string& path() const { return path_; }
  /// 1-based line number of the current record.
  std::size_t lineNumber() const { return lineNumber_; }
  /// Number of records read so far.
  std::size_t recordCount() const { return records_; }

  std::string_view tag() const { return fields_.front(); }
  /// Number of values after the tag.
  std::size_t valueCount() const { return fields_.size() - 1; }
  /// The raw text of value i (1-based, after the tag).
  std::string_view text(std::size_t i) const { return fields_.at(i); }

  /// Requires exactly names.size() values after the tag (otherwise throws naming the expected fields) and
  /// names the values in later messages.
  void requireValueCount(FieldNames names);
  /// Requires at least `minimum` values after the tag, all described as `what` ("id") in messages.
  void requireAtLeast(std::size_t minimum, std::string_view what);

  /// Value i as a finite double (decimal or scientific notation, optional sign).
  double number(std::size_t i) const;
  /// Values first, first + 1, ..., first + count - 1 as finite doubles.
  std::vector<double> numbers(std::size_t first, std::size_t count) const;
  /// Value i as a non-negative integer id that fits a Key's 56-bit index.
  std::uint64_t id(std::size_t i) const;
  /// "EDGE_SE2 field 2 (j)": value i of the current record, for messages.
  std::string describe(std::size_t i) const;

  /// Throws InputError at the current record.
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  std::string path_;
  std::ifstream stream_;
  std::string line_;
  std::vector<std::string_view> fields_;
  FieldNames names_;
  std::string_view genericName_ = "value";
  std::size_t lineNumber_ = 0;
  std::size_t records_ = 0;
};

}  // namespace semslam
