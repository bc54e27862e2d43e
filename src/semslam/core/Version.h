#pragma once
// Version: semslam's release version, the CMake project VERSION (top-level CMakeLists.txt), so that one number is
// shown by `semslam --version`, recorded as "version" in every report and metrics JSON the tool writes (a result
// file says which release made it), installed in the CMake package (semslamConfigVersion.cmake) and in semslam.pc.
// The build writes it into a generated Version.cpp (from Version.cpp.in), so changing it recompiles one file.

#include <string_view>

namespace semslam {

/// The release version, "MAJOR.MINOR.PATCH" (e.g. "0.1.0"); CHANGELOG.md lists what each release holds.
std::string_view version();

}  // namespace semslam
