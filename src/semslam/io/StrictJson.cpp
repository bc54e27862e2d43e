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

/// Thrown from inside the parse callback to stop at the first key problem.
struct KeyProblem {
  std::string problem;
};

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
  std::vector<std::unordered_set<std::string>> keys;  // the keys seen so far in each open object
  const Json::parser_callback_t callback = [&keys](int, Json::parse_event_t event, Json& parsed) {
    if (event == Json::parse_event_t::object_start) {
      keys.emplace_back();
    } else if (event == Json::parse_event_t::key) {
      std::string key = parsed.get<std::string>();
      if (keys.back().size() == kMaxJsonObjectKeys) {
        throw KeyProblem{"an object with more than " + std::to_string(kMaxJsonObjectKeys) +
                         " keys (the most accepted)"};
      }
      if (!keys.back().insert(key).second) {
        throw KeyProblem{"duplicate key " + inputExcerpt(key) + " (every key appears once)"};
      }
    } else if (event == Json::parse_event_t::object_end) {
      keys.pop_back();
    }
    return true;
  };
  const bool oneLine = text.find('\n') == std::string::npos;
  try {
    return Json::parse(text, callback);
  } catch (const KeyProblem& error) {
    throw InputError(file, oneLine ? firstLine : 0, error.problem);
  } catch (const Json::parse_error& error) {
    throw InputError(file, lineOfByte(text, error.byte == 0 ? 0 : error.byte - 1, firstLine),
                     "not valid JSON: " + jsonProblem(error.what()));
  } catch (const Json::exception& error) {
    throw InputError(file, oneLine ? firstLine : 0, "not valid JSON: " + jsonProblem(error.what()));
  }
}

}  // namespace semslam::jsonio
