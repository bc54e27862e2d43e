#include "semslam/core/JsonNesting.h"

#include "semslam/core/InputError.h"

namespace semslam {

void requireJsonNestingAtMost(std::string_view text, const std::string& file, std::size_t firstLine,
                              std::size_t maxDepth) {
  std::size_t depth = 0;
  std::size_t line = firstLine;
  bool inString = false;
  bool escaped = false;
  for (const char c : text) {
    if (c == '\n') ++line;
    if (inString) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        inString = false;
      }
      continue;
    }
    if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > maxDepth) {
        throw InputError(file, line,
                         "JSON nested deeper than " + std::to_string(maxDepth) + " levels (the deepest accepted)");
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

}  // namespace semslam
