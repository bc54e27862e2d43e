#pragma once
// Results are written completely or not at all: the contents go to `path.tmp`, which is then renamed over
// `path` (atomic on POSIX file systems). On failure nothing is left at `path` and std::runtime_error names it.

#include <functional>
#include <ostream>
#include <string>

namespace semslam {

/// Calls `write` on a stream to a temporary file beside `path`, then renames it into place.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace semslam
