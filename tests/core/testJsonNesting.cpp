// The nesting pre-scan: refuses JSON deeper than the limit at the line of the offending bracket, in linear time,
// and does not count brackets inside strings.

#include <gtest/gtest.h>

#include <string>

#include "semslam/core/JsonNesting.h"
#include "support/InputErrorTesting.h"

namespace semslam {
namespace {

using test::expectInputError;

TEST(JsonNesting, AcceptsNestingUpToTheLimit) {
  const std::string text = std::string(kMaxJsonNesting, '[') + std::string(kMaxJsonNesting, ']');
  EXPECT_NO_THROW(requireJsonNestingAtMost(text, "f.json", 1));
}

TEST(JsonNesting, RefusesOneLevelMoreAtTheLineOfTheBracket) {
  const std::string text = "{\"a\":\n" + std::string(kMaxJsonNesting, '[');
  expectInputError([&] { requireJsonNestingAtMost(text, "f.json", 1); }, "f.json", 2, "nested deeper than 64");
}

TEST(JsonNesting, RefusesAHundredThousandOpenBracketsAtTheFirstLineGiven) {
  const std::string text(100'000, '[');
  expectInputError([&] { requireJsonNestingAtMost(text, "log.jsonl", 7); }, "log.jsonl", 7, "nested deeper");
}

TEST(JsonNesting, IgnoresBracketsInsideStringsAndEscapedQuotes) {
  const std::string text = "{\"k\": \"\\\"" + std::string(1000, '[') + "\"}";
  EXPECT_NO_THROW(requireJsonNestingAtMost(text, "f.json", 1));
}

}  // namespace
}  // namespace semslam
