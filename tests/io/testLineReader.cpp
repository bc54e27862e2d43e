// LineReader: records, line numbers, field counts and checked numbers.

#include <gtest/gtest.h>

#include <array>
#include <string_view>

#include "IoTesting.h"
#include "semslam/io/LineReader.h"

namespace semslam {
namespace {

using test::TempDir;

constexpr std::array<std::string_view, 3> kThree = {"id", "x", "y"};

TEST(LineReader, SkipsBlankAndCommentLinesAndCountsLines) {
  TempDir dir;
  const std::string file = dir.write("a.txt", "# header\n\n   \nA 1 2\r\n\t# indented comment\n  B\t3   4.5  \n");
  LineReader reader(file);
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.lineNumber(), 4u);
  EXPECT_EQ(reader.tag(), "A");
  EXPECT_EQ(reader.valueCount(), 2u);
  EXPECT_EQ(reader.text(2), "2");  // the '\r' of a CRLF line is not part of the field
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.lineNumber(), 6u);
  EXPECT_EQ(reader.tag(), "B");
  EXPECT_DOUBLE_EQ(reader.number(2), 4.5);
  EXPECT_FALSE(reader.next());
  EXPECT_EQ(reader.recordCount(), 2u);
}

TEST(LineReader, MissingFileAndDirectory) {
  TempDir dir;
  EXPECT_INPUT_ERROR(LineReader(dir.path("none.txt")), dir.path("none.txt"), 0, "does not exist");
  EXPECT_INPUT_ERROR(LineReader(dir.path("")), dir.path(""), 0, "directory");
}

TEST(LineReader, FieldCounts) {
  TempDir dir;
  const std::string file = dir.write("a.txt", "T 1 2\nT 1 2 3 4\nT 1 2 3\nF\n");
  LineReader reader(file);
  ASSERT_TRUE(reader.next());
  EXPECT_INPUT_ERROR(reader.requireValueCount(kThree), file, 1,
                     "truncated T record: expected 3 values after the tag (id x y), found 2");
  ASSERT_TRUE(reader.next());
  EXPECT_INPUT_ERROR(reader.requireValueCount(kThree), file, 2,
                     "extra fields in T record: expected 3 values after the tag (id x y), found 4");
  ASSERT_TRUE(reader.next());
  EXPECT_NO_THROW(reader.requireValueCount(kThree));
  ASSERT_TRUE(reader.next());
  EXPECT_INPUT_ERROR(reader.requireAtLeast(1, "id"), file, 4, "expected at least 1 value after the tag (id), found 0");
}

TEST(LineReader, Numbers) {
  TempDir dir;
  const std::string file = dir.write("a.txt", "N 1.5 -2e-3 +7 .25 0x10 1.5abc nan inf -INF 1e999 - 12,5\n");
  LineReader reader(file);
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.number(1), 1.5);
  EXPECT_EQ(reader.number(2), -2e-3);
  EXPECT_EQ(reader.number(3), 7.0);
  EXPECT_EQ(reader.number(4), 0.25);
  EXPECT_INPUT_ERROR(reader.number(5), file, 1, "N field 5 (value) '0x10' is not a number");
  EXPECT_INPUT_ERROR(reader.number(6), file, 1, "'1.5abc' is not a number");
  EXPECT_INPUT_ERROR(reader.number(7), file, 1, "N field 7 (value) is not finite: 'nan'");
  EXPECT_INPUT_ERROR(reader.number(8), file, 1, "is not finite: 'inf'");
  EXPECT_INPUT_ERROR(reader.number(9), file, 1, "is not finite: '-INF'");
  EXPECT_INPUT_ERROR(reader.number(10), file, 1, "'1e999' is out of the range of a double");
  EXPECT_INPUT_ERROR(reader.number(11), file, 1, "'-' is not a number");
  EXPECT_INPUT_ERROR(reader.number(12), file, 1, "'12,5' is not a number");
}

TEST(LineReader, NamedFieldsInMessages) {
  TempDir dir;
  const std::string file = dir.write("a.txt", "P 3 x 1\n");
  LineReader reader(file);
  ASSERT_TRUE(reader.next());
  reader.requireValueCount(kThree);
  EXPECT_EQ(reader.describe(2), "P field 2 (x)");
  EXPECT_INPUT_ERROR(reader.number(2), file, 1, "P field 2 (x) 'x' is not a number");
}

TEST(LineReader, Ids) {
  TempDir dir;
  const std::string file =
      dir.write("a.txt", "I 0 72057594037927935 -1 1.0 x3 72057594037927936 99999999999999999999\n");
  LineReader reader(file);
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.id(1), 0u);
  EXPECT_EQ(reader.id(2), (std::uint64_t{1} << 56) - 1);
  EXPECT_INPUT_ERROR(reader.id(3), file, 1, "'-1' is not a non-negative integer id");
  EXPECT_INPUT_ERROR(reader.id(4), file, 1, "'1.0' is not a non-negative integer id");
  EXPECT_INPUT_ERROR(reader.id(5), file, 1, "'x3' is not a non-negative integer id");
  EXPECT_INPUT_ERROR(reader.id(6), file, 1, "is too large for an id");
  EXPECT_INPUT_ERROR(reader.id(7), file, 1, "is too large for an id");
}

}  // namespace
}  // namespace semslam
