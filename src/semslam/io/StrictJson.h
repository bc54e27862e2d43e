#pragma once
// Parsing JSON text for a semslam format (a measurement-log line, a scenario file), strictly and with bounded
// resources. Refused, with InputError(file, line, problem):
//   - nesting deeper than kMaxJsonNesting (checked by a linear scan before parsing: the parser recurses per level);
//   - an object with more than kMaxJsonObjectKeys keys (nlohmann's ordered objects insert in linear time, so the
//     count bounds the parse's quadratic term; no semslam object has more than 20 keys);
//   - a key appearing twice in one object (found with a hash set per open object: linear time);
//   (the last two by a SAX pass that builds nothing, before the plain parser builds the value: nlohmann's callback
//   parser is quadratic in the length of an array of objects);
//   - invalid JSON, with nlohmann's message shortened and escaped (it quotes the last token read, unbounded).
// The line of a problem is `firstLine` plus the newlines before it; for a key problem (the parser does not say
// where a key is) the line of the refused key, found by counting keys in a linear scan of the text.
//
// Internal to the io layer, like JsonField.h.

#include <cstddef>
#include <string>

#include "semslam/io/JsonField.h"

namespace semslam::jsonio {

/// The most keys one JSON object may have.
inline constexpr std::size_t kMaxJsonObjectKeys = 1000;

Json parseStrictJson(const std::string& text, const std::string& file, std::size_t firstLine);

/// nlohmann's exception message without its "[json.exception.parse_error.101] parse error at line L, " prefix
/// ("column C: syntax error ..."), bounded and escaped (core/InputExcerpt.h).
std::string jsonProblem(const std::string& what);

}  // namespace semslam::jsonio
