#include "semslam/io/SpooledText.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace semslam {
namespace {

std::runtime_error spoolError(const char* what, int error) {
  return std::runtime_error(std::string("temporary file for spooled output: ") + what + ": " + std::strerror(error));
}

}  // namespace

SpooledText::SpooledText() : file_(std::tmpfile()) {
  if (!file_) throw spoolError("cannot create", errno);
}

void SpooledText::append(std::string_view text) {
  if (std::fwrite(text.data(), 1, text.size(), file_.get()) != text.size()) throw spoolError("cannot write", errno);
  bytes_ += text.size();
}

void SpooledText::copyTo(std::ostream& out) const {
  if (std::fflush(file_.get()) != 0) throw spoolError("cannot write", errno);
  // Reads from the start, then puts the position back at the end, where further appends go.
  if (std::fseek(file_.get(), 0, SEEK_SET) != 0) throw spoolError("cannot read back", errno);
  std::vector<char> buffer(1 << 16);
  std::size_t copied = 0;
  while (copied < bytes_) {
    const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), file_.get());
    if (n == 0) break;
    out.write(buffer.data(), static_cast<std::streamsize>(n));
    copied += n;
  }
  const int readError = std::ferror(file_.get()) ? errno : 0;
  std::fseek(file_.get(), 0, SEEK_END);
  if (copied != bytes_) throw spoolError("cannot read back", readError != 0 ? readError : EIO);
}

}  // namespace semslam
