#include "semslam/io/StrictJson.h"

#include <algorithm>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "semslam/core/InputError.h"
#include "semslam/core/InputExcerpt.h"
#include "semslam/core/JsonNesting.h"

namespace semslam::jsonio {

namespace {

/// The longest parser message kept: enough for nlohmann's explanation and a short excerpt of the token.
constexpr std::size_t kMaxProblemBytes = 200;

std::size_t lineOfByte(const std::string& text, std::size_t byte, std::size_t firstLine) {
  const std::size_t end = std::min(byte, text.size());
  return firstLine + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(end), '\n'));
}

/// A SAX pass that builds nothing: stops at the first parse error, duplicate key, or object with too many keys.
/// (nlohmann's callback parser is quadratic in the length of an array of objects: after every object it scans the
/// enclosing array for discarded values. 200,000 detections took 18 s. The plain parser afterwards is linear.)
class KeyChecker {
 public:
  std::string keyProblem;
  std::size_t keysSeen = 0;  // keys read so far, the refused one included
  std::size_t errorByte = 0;  // 1-based, as nlohmann counts; 0: none
  std::string errorWhat;

  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(Json::number_integer_t) { return true; }
  bool number_unsigned(Json::number_unsigned_t) { return true; }
  bool number_float(Json::number_float_t, const std::string&) { return true; }
  bool string(std::string&) { return true; }
  bool binary(Json::binary_t&) { return true; }
  bool start_object(std::size_t) {
    keys_.emplace_back();
    return true;
  }
  bool end_object() {
    keys_.pop_back();
    return true;
  }
  bool start_array(std::size_t) { return true; }
  bool end_array() { return true; }
  bool key(std::string& key) {
    ++keysSeen;
    if (keys_.back().size() == kMaxJsonObjectKeys) {
      keyProblem = "an object with more than " + std::to_string(kMaxJsonObjectKeys) + " keys (the most accepted)";
      return false;
    }
    if (!keys_.back().insert(key).second) {
      keyProblem = "duplicate key " + inputExcerpt(key) + " (every key appears once)";
      return false;
    }
    return true;
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& error) {
    errorByte = position;  // also for an out_of_range error (a number overflowing a double)
    errorWhat = error.what();
    return false;
  }

 private:
  std::vector<std::unordered_set<std::string>> keys_;  // the keys seen so far in each open object
};

/// The byte where the n-th key (1-based, in document order) of valid JSON text starts: a key is a string followed,
/// after white space, by ':'. A linear scan (the SAX parser does not say where a key is).
std::size_t byteOfKey(const std::string& text, std::size_t n) {
  std::size_t keys = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '"') continue;
    const std::size_t start = i;
    for (++i; i < text.size() && text[i] != '"'; ++i) {
      if (text[i] == '\\') ++i;  // an escaped character, '"' included
    }
    std::size_t next = i + 1;
    while (next < text.size() && (text[next] == ' ' || text[next] == '\t' || text[next] == '\n' || text[next] == '\r')) {
      ++next;
    }
    if (next < text.size() && text[next] == ':' && ++keys == n) return start;
  }
  return text.size();
}

}  // namespace

std::string jsonProblem(const std::string& what) {
  std::string text = what;
  if (text.rfind("[json.exception.", 0) == 0) {
    const auto end = text.find("] ");
    if (end != std::string::npos) text = text.substr(end + 2);
  }
  if (text.rfind("parse error at line ", 0) == 0) {  // the line is the error's own: keep the column
    const auto comma = text.find(", ");
    if (comma != std::string::npos) text = text.substr(comma + 2);
  } else if (text.rfind("parse error", 0) == 0) {
    const auto colon = text.find(": ");
    if (colon != std::string::npos) text = text.substr(colon + 2);
  }
  return boundedMessage(text, kMaxProblemBytes);
}

Json parseStrictJson(const std::string& text, const std::string& file, std::size_t firstLine) {
  requireJsonNestingAtMost(text, file, firstLine);
  KeyChecker checker;
  if (!Json::sax_parse(text, &checker)) {
    if (!checker.keyProblem.empty()) {
      throw InputError(file, lineOfByte(text, byteOfKey(text, checker.keysSeen), firstLine), checker.keyProblem);
    }
    throw InputError(file, lineOfByte(text, checker.errorByte == 0 ? 0 : checker.errorByte - 1, firstLine),
                     "not valid JSON: " + jsonProblem(checker.errorWhat));
  }
  return Json::parse(text);
}

}  // namespace semslam::jsonio
