#pragma once
// Opening and reading an input file with bounded resources: every reader of the library goes through these, so a
// device (`/dev/zero`), a FIFO or a socket is refused before it is read, a line cannot grow past a limit, and a
// whole-file read cannot grow past another. Each problem throws InputError(path, line, problem).

#include <cstddef>
#include <fstream>
#include <istream>
#include <string>

namespace semslam {

/// The longest line a line-oriented reader accepts (measurement-log records, g2o/TORO/iSAM, TUM/KITTI/EuRoC,
/// converters' tables): 16 MiB.
inline constexpr std::size_t kMaxInputLineBytes = std::size_t{16} << 20;
/// The largest file read whole (scenario JSON, metrics.json, classifier tables): 64 MiB.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{64} << 20;

/// Throws InputError(path, 0, ...) unless `path` names an existing regular file (a symbolic link to one is fine):
/// "file does not exist", "is a directory, not a file", "is not a regular file (a device, FIFO or socket)".
void requireRegularInputFile(const std::string& path);

/// requireRegularInputFile, then opens `path` for binary reading (InputError when it cannot be opened).
std::ifstream openInputFile(const std::string& path);

/// Reads the next line of `in` into `line` (without its '\n'); false at the end of the stream (and no text
/// left). A line longer than `maxBytes` throws InputError(path, lineNumber, ...) naming the limit; `lineNumber`
/// is the number of the line being read. A read error throws InputError too.
bool readBoundedLine(std::istream& in, std::string& line, const std::string& path, std::size_t lineNumber,
                     std::size_t maxBytes = kMaxInputLineBytes);

/// The whole of the regular file `path`; a file larger than `maxBytes` throws InputError(path, 0, ...).
std::string readInputText(const std::string& path, std::size_t maxBytes = kMaxInputFileBytes);

}  // namespace semslam
