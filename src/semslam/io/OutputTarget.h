#pragma once
// Where an output may go. We run as root in CI and on lab machines, so a destination is checked before it is
// written: an output never replaces a device (`--out /dev/full` replaced the device with a regular file), never
// follows or replaces a symbolic link planted at the destination, and never overwrites one of the command's
// inputs (`--report` pointed at the input). Each refusal is an InputError naming the path (exit code 2).

#include <string>

namespace semslam {

/// A fresh name for a temporary file or folder beside `target`: ".NAME.tmp-" and 12 random characters from
/// getrandom (unpredictable, so no one can plant a link there first; create it with O_EXCL all the same).
std::string temporaryNameBeside(const std::string& target);

/// A file output may be written at `path`: nothing is there, or a regular file (not a symbolic link).
void requireReplaceableFile(const std::string& path);

/// `output` (a file, or a folder the command fills) is not `input`, and (a folder) does not hold it. `what` names
/// the output's option in the message ("--out").
void requireOutputSparesInput(const std::string& output, const std::string& input, const std::string& what);

}  // namespace semslam
