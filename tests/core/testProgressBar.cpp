// ProgressBar off a terminal (a file here): a plain line every period and one at the end; nothing when quiet.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "semslam/core/ProgressBar.h"

namespace semslam {
namespace {

std::string written(std::FILE* file) {
  std::rewind(file);
  std::string text;
  for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) text += static_cast<char>(c);
  return text;
}

long lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

TEST(ProgressBar, QuietPrintsNothing) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  ProgressBar bar("quiet", 10, /*quiet=*/true, file);
  EXPECT_FALSE(bar.enabled());
  for (int i = 1; i <= 10; ++i) bar.update(i);
  EXPECT_EQ(written(file), "");
  std::fclose(file);
}

TEST(ProgressBar, AFastRunOffATerminalPrintsOnlyItsLastLine) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  ProgressBar bar("study", 100, false, file);  // period 5 s: the loop below takes microseconds
  for (int i = 1; i <= 100; ++i) bar.update(i);
  bar.update(100);  // nothing after the end
  const std::string text = written(file);
  EXPECT_EQ(lines(text), 1) << text;
  EXPECT_EQ(text.rfind("study: 100/100  ", 0), 0u) << text;
  std::fclose(file);
}

TEST(ProgressBar, ASlowRunOffATerminalPrintsALineEveryPeriod) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  ProgressBar bar("run mm-nh", 4, false, file, ProgressBar::Seconds(0.02));
  for (int i = 1; i <= 4; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    bar.update(i);
  }
  const std::string text = written(file);
  EXPECT_EQ(lines(text), 4) << text;
  EXPECT_NE(text.find("run mm-nh: 1/4  "), std::string::npos) << text;
  EXPECT_NE(text.find("s left\n"), std::string::npos) << text;
  EXPECT_NE(text.find("run mm-nh: 4/4  "), std::string::npos) << text;
  std::fclose(file);
}

}  // namespace
}  // namespace semslam
