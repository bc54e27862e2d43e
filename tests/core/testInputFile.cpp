// Reading input with bounded resources: devices and FIFOs refused before a byte is read, over-long lines and
// over-large whole-file reads refused with the file and line.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "semslam/core/InputError.h"
#include "semslam/core/InputFile.h"
#include "support/InputErrorTesting.h"
#include "support/TempFile.h"

namespace semslam {
namespace {

using test::expectInputError;

TEST(InputFile, RefusesADeviceAFolderAndAMissingFile) {
  expectInputError([] { openInputFile("/dev/zero"); }, "/dev/zero", 0, "not a regular file");
  const std::string folder = std::filesystem::temp_directory_path().string();
  expectInputError([&] { openInputFile(folder); }, folder, 0, "is a directory");
  expectInputError([] { openInputFile("/nonexistent/semslam.txt"); }, "/nonexistent/semslam.txt", 0,
                   "does not exist");
}

TEST(InputFile, RefusesAFifo) {
  const std::string fifo =
      (std::filesystem::temp_directory_path() / ("semslam_fifo_" + std::to_string(::getpid()))).string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectInputError([&] { readInputText(fifo); }, fifo, 0, "not a regular file");
  std::filesystem::remove(fifo);
}

TEST(InputFile, ReadsLinesWithAndWithoutAFinalNewline) {
  std::istringstream in("a b\n\nlast");
  std::string line;
  ASSERT_TRUE(readBoundedLine(in, line, "f", 1));
  EXPECT_EQ(line, "a b");
  ASSERT_TRUE(readBoundedLine(in, line, "f", 2));
  EXPECT_EQ(line, "");
  ASSERT_TRUE(readBoundedLine(in, line, "f", 3));
  EXPECT_EQ(line, "last");
  EXPECT_FALSE(readBoundedLine(in, line, "f", 4));
}

TEST(InputFile, RefusesALineLongerThanTheLimitNamingItsLine) {
  std::istringstream in("short\n" + std::string(101, 'x') + "\n");
  std::string line;
  ASSERT_TRUE(readBoundedLine(in, line, "f.txt", 1, 100));
  expectInputError([&] { readBoundedLine(in, line, "f.txt", 2, 100); }, "f.txt", 2, "line longer than");
}

TEST(InputFile, RefusesAWholeFileLargerThanTheLimit) {
  const test::TempFile file(std::string(1000, 'x'));
  EXPECT_EQ(readInputText(file.path(), 1000).size(), 1000u);
  expectInputError([&] { readInputText(file.path(), 999); }, file.path(), 0, "larger than");
}

}  // namespace
}  // namespace semslam
