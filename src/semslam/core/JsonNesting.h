#pragma once
// The nesting depth of JSON text, checked by a linear scan before the text reaches a JSON parser: nlohmann's
// parser recurses per level (a line of 100,000 '[' overflows the stack), and no semslam format nests deeper than
// a few levels (a step's detections' covariance rows: 5).

#include <cstddef>
#include <string>
#include <string_view>

namespace semslam {

/// The deepest nesting of arrays and objects any JSON input may have.
inline constexpr std::size_t kMaxJsonNesting = 64;

/// Throws InputError(file, line, ...) when `text` opens more than `maxDepth` arrays or objects inside one another
/// (brackets inside strings do not count); `line` is `firstLine` plus the newlines before the offending bracket.
/// Does not validate the JSON otherwise.
void requireJsonNestingAtMost(std::string_view text, const std::string& file, std::size_t firstLine,
                              std::size_t maxDepth = kMaxJsonNesting);

}  // namespace semslam
