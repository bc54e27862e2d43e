#include "semslam/graph/Key.h"

#include <cctype>
#include <charconv>
#include <stdexcept>

namespace semslam {

std::string keyToString(Key key) {
  const Symbol symbol(key);
  if (symbol.tag() == 0) return std::to_string(symbol.index());
  return std::string(1, symbol.tag()) + std::to_string(symbol.index());
}

Key keyFromString(const std::string& text) {
  if (text.empty()) throw std::invalid_argument("empty key");
  const bool typed = std::isalpha(static_cast<unsigned char>(text.front())) != 0;
  const char* first = text.data() + (typed ? 1 : 0);
  const char* last = text.data() + text.size();
  std::uint64_t index = 0;
  const auto [end, error] = std::from_chars(first, last, index);
  if (first == last || error != std::errc() || end != last || index > Symbol::kIndexMask) {
    throw std::invalid_argument("not a key: '" + text + "' (expected a number or a letter and a number, e.g. x12)");
  }
  return typed ? Symbol(text.front(), index).key() : index;
}

}  // namespace semslam
