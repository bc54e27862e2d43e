// core/Version.h: the release version is the CMake project VERSION, MAJOR.MINOR.PATCH. The CLI's `--version`
// output is checked against the project VERSION itself by the ctest cli.version (tests/CMakeLists.txt).

#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "semslam/core/Version.h"

namespace semslam {
namespace {

TEST(Version, IsMajorMinorPatch) {
  const std::string text(version());
  EXPECT_TRUE(std::regex_match(text, std::regex(R"([0-9]+\.[0-9]+\.[0-9]+)"))) << text;
}

}  // namespace
}  // namespace semslam
