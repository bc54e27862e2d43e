#include "semslam/io/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <streambuf>

#include "semslam/io/InterruptCleanup.h"
#include "semslam/io/OutputTarget.h"

namespace semslam {

namespace {

/// An output stream buffer over an open file descriptor; remembers the first write error.
class DescriptorBuffer : public std::streambuf {
 public:
  explicit DescriptorBuffer(int fd) : fd_(fd) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (sync() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }

  int sync() override {
    const char* data = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    while (left > 0 && error_ == 0) {
      const ssize_t written = ::write(fd_, data, left);
      if (written < 0) {
        if (errno != EINTR) error_ = errno;
        continue;
      }
      data += written;
      left -= static_cast<std::size_t>(written);
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return error_ == 0 ? 0 : -1;
  }

 private:
  int fd_;
  int error_ = 0;
  std::array<char, 1 << 16> buffer_{};
};

/// Creates a new temporary file beside `path`; returns its descriptor and sets `temporary` to its name.
int createTemporaryBeside(const std::string& path, std::string& temporary) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    temporary = temporaryNameBeside(path);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST) {
      throw std::runtime_error("cannot write " + path + ": cannot create a temporary file beside it: " +
                               std::strerror(errno));
    }
  }
  throw std::runtime_error("cannot write " + path + ": no free temporary name beside it");
}

/// Writes the temporary file and renames it over `path`; the temporary file is registered for interruption
/// cleanup only while it exists.
void writeAndRename(const std::string& path, const std::function<void(std::ostream&)>& write) {
  std::string temporary;
  const int fd = createTemporaryBeside(path, temporary);
  const TemporaryOutput registration(temporary, path, false);
  const auto discard = [&temporary] { std::remove(temporary.c_str()); };
  DescriptorBuffer buffer(fd);
  std::ostream out(&buffer);
  try {
    write(out);
  } catch (...) {
    ::close(fd);
    discard();
    throw;
  }
  out.flush();
  const int writeError = buffer.error();
  if (::close(fd) != 0 || writeError != 0 || !out) {
    discard();
    throw std::runtime_error("cannot write " + path + ": write failed: " +
                             std::strerror(writeError != 0 ? writeError : errno));
  }
  try {
    requireReplaceableFile(path);  // again, just before replacing it
  } catch (...) {
    discard();
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    discard();
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(error));
  }
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  requireReplaceableFile(path);
  writeAndRename(path, write);
  noteCompletedOutputFile();
}

}  // namespace semslam
