#pragma once
// Locating the shared datasets from tests: they live at ../shared/data beside the repository and are never copied
// into it. A test that needs one calls SEMSLAM_REQUIRE_DATA, which skips the test with a clear message when the
// file is absent.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace semslam::test {

inline std::filesystem::path sharedDataPath(const std::string& relative) {
  return std::filesystem::path(SEMSLAM_SHARED_DATA) / relative;
}

}  // namespace semslam::test

/// Declares `variable` as the path of a shared dataset file, or skips the test when it is missing.
#define SEMSLAM_REQUIRE_DATA(variable, relative)                                                        \
  const std::filesystem::path variable = ::semslam::test::sharedDataPath(relative);                    \
  if (!std::filesystem::exists(variable)) {                                                             \
    GTEST_SKIP() << "shared dataset not found: " << variable.string()                                   \
                 << " (expected ../shared/data beside the repository)";                                 \
  }
