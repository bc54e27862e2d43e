// What a message may quote of its input: a short excerpt, every byte outside printable ASCII escaped.

#include <gtest/gtest.h>

#include <string>

#include "semslam/core/InputExcerpt.h"

namespace semslam {
namespace {

TEST(InputExcerpt, QuotesShortPrintableTextAsItIs) { EXPECT_EQ(inputExcerpt("1.5e3x"), "'1.5e3x'"); }

TEST(InputExcerpt, EscapesTerminalControlBytesQuotesAndBackslashes) {
  EXPECT_EQ(inputExcerpt("\x1b[2J'\\\xff"), "'\\x1b[2J\\x27\\x5c\\xff'");
}

TEST(InputExcerpt, CutsALongTokenAndSaysHowLongItWas) {
  const std::string token(50'000'000, '7');
  const std::string excerpt = inputExcerpt(token);
  EXPECT_EQ(excerpt, "'" + std::string(kInputExcerptBytes, '7') + "'... (50000000 bytes)");
}

TEST(BoundedMessage, KeepsAShortMessageAndEscapesControlBytesButNewlines) {
  EXPECT_EQ(boundedMessage("line 1\nbad \x1b]0;title\x07"), "line 1\nbad \\x1b]0;title\\x07");
}

TEST(BoundedMessage, CutsALongMessageInTheMiddle) {
  const std::string message = "start " + std::string(100'000, 'x') + " end";
  const std::string bounded = boundedMessage(message, 100);
  EXPECT_LT(bounded.size(), 200u);
  EXPECT_EQ(bounded.substr(0, 6), "start ");
  EXPECT_EQ(bounded.substr(bounded.size() - 4), " end");
  EXPECT_NE(bounded.find("bytes left out"), std::string::npos);
}

}  // namespace
}  // namespace semslam
