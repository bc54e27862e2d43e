// ProgressBar: silent when not asked and not on a terminal; forced, one plain line per tenth plus the end.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "semslam/core/ProgressBar.h"

namespace semslam {
namespace {

std::string written(std::FILE* file) {
  std::rewind(file);
  std::string text;
  for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) text += static_cast<char>(c);
  return text;
}

TEST(ProgressBar, SilentUnlessATerminalOrForced) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  ProgressBar bar("quiet", 10, ProgressBar::Mode::Auto, file);  // a file is not a terminal
  EXPECT_FALSE(bar.enabled());
  for (int i = 1; i <= 10; ++i) bar.update(i);
  EXPECT_EQ(written(file), "");
  std::fclose(file);
}

TEST(ProgressBar, ForcedPrintsOneLinePerTenth) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  ProgressBar bar("study", 100, ProgressBar::Mode::Always, file);
  for (int i = 1; i <= 100; ++i) bar.update(i);
  const std::string text = written(file);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 11);  // 0/10 .. 10/10 tenths: 1, 10, 20, ..., 100
  EXPECT_NE(text.find("study: 100/100"), std::string::npos);
  std::fclose(file);
}

}  // namespace
}  // namespace semslam
