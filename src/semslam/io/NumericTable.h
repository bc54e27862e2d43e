#pragma once
// Reading a text table of numbers, one record per line: the common front end of the trajectory readers
// (TUM, KITTI, EuRoC). evo reads these files with Python's csv module and numpy's float conversion; this reader
// accepts the same files and rejects, with file and line, what evo would reject or silently mis-read.
//
// Rules:
//  - a line whose first non-blank character is '#' is a comment; blank lines are skipped;
//  - a UTF-8 byte-order mark at the start of the file and a trailing '\r' (CRLF files) are ignored;
//  - Separator::Whitespace splits on runs of spaces and tabs; Separator::Comma splits on ',' and trims blanks
//    around each field (an empty field is an error);
//  - every field must be a complete decimal number (std::from_chars syntax, which is what strtod/Python accept
//    for plain numbers); "nan", "inf" and anything non-numeric throw InputError(file, line, problem).
// An unreadable file throws InputError(file, 0, ...). The table may be empty; the readers decide whether that is
// an error.

#include <cstddef>
#include <string>
#include <vector>

namespace semslam {

enum class Separator { Whitespace, Comma };

struct NumericRow {
  std::size_t line = 0;        ///< 1-based line number in the file
  std::vector<double> values;  ///< the parsed fields, all finite
};

/// Parses every data line of `path`.
std::vector<NumericRow> readNumericTable(const std::string& path, Separator separator);

}  // namespace semslam
