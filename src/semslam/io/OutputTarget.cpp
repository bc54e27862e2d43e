#include "semslam/io/OutputTarget.h"

#include <sys/random.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "semslam/core/InputError.h"

namespace semslam {

namespace {

/// 12 characters from [a-z0-9], from the kernel's random source.
std::string randomSuffix() {
  static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::array<unsigned char, 12> bytes{};
  std::size_t filled = 0;
  while (filled < bytes.size()) {
    const ssize_t got = ::getrandom(bytes.data() + filled, bytes.size() - filled, 0);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("getrandom failed: ") + std::strerror(errno));
    }
    filled += static_cast<std::size_t>(got);
  }
  std::string suffix;
  for (const unsigned char b : bytes) suffix += kAlphabet[b % (sizeof kAlphabet - 1)];
  return suffix;
}

}  // namespace

std::string temporaryNameBeside(const std::string& target) {
  std::filesystem::path path(target);
  if (path.filename().empty()) path = path.parent_path();  // "out/" names "out"
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp-";
  name += randomSuffix();
  return (path.parent_path() / name).string();
}

void requireReplaceableFile(const std::string& path) {
  struct stat status {};
  if (::lstat(path.c_str(), &status) != 0) {
    if (errno == ENOENT) return;
    throw InputError(path, 0, std::string("cannot write here: ") + std::strerror(errno));
  }
  if (S_ISLNK(status.st_mode)) {
    throw InputError(path, 0, "is a symbolic link: refusing to follow or replace it (remove it, or write elsewhere)");
  }
  if (S_ISDIR(status.st_mode)) throw InputError(path, 0, "is a folder: expected a file to write");
  if (!S_ISREG(status.st_mode)) {
    throw InputError(path, 0, "is not a regular file (a device, FIFO or socket): refusing to replace it");
  }
}

void requireOutputSparesInput(const std::string& output, const std::string& input, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::path out = fs::weakly_canonical(output, error);
  if (error) return;
  if (out.filename().empty()) out = out.parent_path();  // "runs/" is the folder "runs"
  const fs::path in = fs::weakly_canonical(input, error);
  if (error) return;
  if (out == in || fs::equivalent(output, input, error)) {
    throw InputError(output, 0, what + " is also an input of the command: refusing to overwrite it");
  }
  const auto [outEnd, inAt] = std::mismatch(out.begin(), out.end(), in.begin(), in.end());
  if (outEnd == out.end()) {
    throw InputError(output, 0, what + " is a folder holding an input of the command (" + input +
                                    "): refusing to replace it");
  }
}

}  // namespace semslam
