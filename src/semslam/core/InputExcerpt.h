#pragma once
// What an error message may quote of its input: a short, escaped excerpt. Input is hostile until validated: a
// 50 MB token must not become a 50 MB message, and a terminal escape sequence must not reach the user's terminal.

#include <cstddef>
#include <string>
#include <string_view>

namespace semslam {

/// The longest excerpt of input quoted in a message, in input bytes (an escaped byte takes up to 4 characters).
inline constexpr std::size_t kInputExcerptBytes = 40;

/// `text` between single quotes, every byte outside printable ASCII (and the backslash and quote) written as \xHH,
/// cut to its first `maxBytes` bytes followed by "... (N bytes)" when it is longer.
std::string inputExcerpt(std::string_view text, std::size_t maxBytes = kInputExcerptBytes);

/// A whole message made safe to print: bytes outside printable ASCII (but newline) escaped as \xHH, and a message
/// longer than `maxBytes` cut in the middle. For messages built by code that quotes input unbounded (a parser
/// library's message).
std::string boundedMessage(std::string_view message, std::size_t maxBytes = 1000);

}  // namespace semslam
