#include "semslam/core/InputFile.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "semslam/core/InputError.h"

namespace semslam {

namespace {

std::string mebibytes(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

}  // namespace

void requireRegularInputFile(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) {
    if (errno == ENOENT || errno == ENOTDIR) throw InputError(path, 0, "file does not exist");
    throw InputError(path, 0, std::string("cannot open file: ") + std::strerror(errno));
  }
  if (S_ISDIR(status.st_mode)) throw InputError(path, 0, "is a directory, not a file");
  if (!S_ISREG(status.st_mode)) {
    throw InputError(path, 0, "is not a regular file (a device, FIFO or socket): refusing to read it");
  }
}

std::ifstream openInputFile(const std::string& path) {
  requireRegularInputFile(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open file: ") + std::strerror(errno));
  return in;
}

bool readBoundedLine(std::istream& in, std::string& line, const std::string& path, std::size_t lineNumber,
                     std::size_t maxBytes) {
  line.clear();
  std::streambuf* buffer = in.rdbuf();
  bool any = false;
  for (;;) {
    const int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      if (in.bad()) throw InputError(path, lineNumber, std::string("read error: ") + std::strerror(errno));
      in.setstate(std::ios::eofbit);
      return any;
    }
    any = true;
    if (c == '\n') return true;
    if (line.size() == maxBytes) {
      throw InputError(path, lineNumber,
                       "line longer than " + mebibytes(maxBytes) + " (the longest line a reader accepts)");
    }
    line.push_back(static_cast<char>(c));
  }
}

std::string readInputText(const std::string& path, std::size_t maxBytes) {
  std::ifstream in = openInputFile(path);
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    if (text.size() + static_cast<std::size_t>(in.gcount()) > maxBytes) {
      throw InputError(path, 0, "larger than " + mebibytes(maxBytes) + " (the largest file read whole)");
    }
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError(path, 0, std::string("read error: ") + std::strerror(errno));
  return text;
}

}  // namespace semslam
