#pragma once
// Results are written completely or not at all, and never through a planted link:
//   - the destination must be absent or a regular file (io/OutputTarget.h: never a symbolic link, a device, a
//     FIFO or a folder);
//   - the contents go to a temporary file created beside it with O_CREAT|O_EXCL|O_NOFOLLOW under an unpredictable
//     name (".NAME.tmp-XXXXXXXXXXXX", 12 random characters from getrandom), registered for removal if the
//     process is interrupted (io/InterruptCleanup.h);
//   - the temporary file is then renamed over `path` (atomic on POSIX file systems).
// On failure nothing is left at `path` but what was there before, the temporary file is removed, and the error
// names `path`: InputError for a destination that must not be written, std::runtime_error otherwise.

#include <functional>
#include <ostream>
#include <string>

namespace semslam {

/// Calls `write` on a stream to a temporary file beside `path`, then renames it into place.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace semslam
