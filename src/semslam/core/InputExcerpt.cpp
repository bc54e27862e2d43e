#include "semslam/core/InputExcerpt.h"

namespace semslam {

namespace {

bool isPrintable(unsigned char c) { return c >= 0x20 && c < 0x7f; }

void appendEscaped(std::string& out, unsigned char c) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += "\\x";
  out += kHex[c >> 4];
  out += kHex[c & 0xf];
}

}  // namespace

std::string inputExcerpt(std::string_view text, std::size_t maxBytes) {
  const std::string_view shown = text.substr(0, maxBytes);
  std::string out = "'";
  for (const char byte : shown) {
    const auto c = static_cast<unsigned char>(byte);
    if (isPrintable(c) && c != '\\' && c != '\'') {
      out += byte;
    } else {
      appendEscaped(out, c);
    }
  }
  out += '\'';
  if (shown.size() < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string boundedMessage(std::string_view message, std::size_t maxBytes) {
  std::string kept;
  if (message.size() > maxBytes) {
    const std::size_t half = maxBytes / 2;
    kept = std::string(message.substr(0, half)) + " [... " + std::to_string(message.size() - 2 * half) +
           " bytes left out ...] " + std::string(message.substr(message.size() - half));
  } else {
    kept = std::string(message);
  }
  std::string out;
  out.reserve(kept.size());
  for (const char byte : kept) {
    const auto c = static_cast<unsigned char>(byte);
    if (isPrintable(c) || c == '\n') {
      out += byte;
    } else {
      appendEscaped(out, c);
    }
  }
  return out;
}

}  // namespace semslam
