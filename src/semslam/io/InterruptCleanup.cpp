#include "semslam/io/InterruptCleanup.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace semslam {

namespace {

constexpr std::size_t kPathBytes = 4096;

enum SlotState : int { kFree = 0, kFilling = 1, kReady = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  bool folder = false;
  char temporary[kPathBytes] = {};
  char target[kPathBytes] = {};
};

std::array<Slot, TemporaryOutput::kMaxTemporaryOutputs> slots;

void copyPath(char* destination, const std::string& path) {
  if (path.size() >= kPathBytes) throw std::runtime_error("path too long for an output: " + path.substr(0, 200));
  std::memcpy(destination, path.c_str(), path.size() + 1);
}

void writeText(const char* text) {
  const std::size_t length = std::strlen(text);
  std::size_t done = 0;
  while (done < length) {
    const ssize_t written = ::write(STDERR_FILENO, text + done, length - done);
    if (written <= 0) return;
    done += static_cast<std::size_t>(written);
  }
}

/// Removes the entries of the open folder `dir` (recursing into subfolders up to `depth` levels).
bool emptyFolder(int dir, int depth) {
  alignas(8) char buffer[4096];
  bool removedAll = true;
  for (bool removedSome = true; removedSome;) {  // rescan until a pass removes nothing: unlinking shifts entries
    removedSome = false;
    ::lseek(dir, 0, SEEK_SET);
    for (;;) {
      const long bytes = ::syscall(SYS_getdents64, dir, buffer, sizeof buffer);
      if (bytes <= 0) break;
      for (long offset = 0; offset < bytes;) {
        struct Entry {
          ino64_t inode;
          off64_t next;
          unsigned short length;
          unsigned char type;
          char name[1];
        };
        const auto* entry = reinterpret_cast<const Entry*>(buffer + offset);
        offset += entry->length;
        const char* name = entry->name;
        if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
        if (::unlinkat(dir, name, 0) == 0) {
          removedSome = true;
          continue;
        }
        if (errno != EISDIR || depth == 0) {
          removedAll = false;
          continue;
        }
        const int child = ::openat(dir, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (child < 0) {
          removedAll = false;
          continue;
        }
        const bool emptied = emptyFolder(child, depth - 1);
        ::close(child);
        if (emptied && ::unlinkat(dir, name, AT_REMOVEDIR) == 0) {
          removedSome = true;
        } else {
          removedAll = false;
        }
      }
    }
  }
  return removedAll;
}

extern "C" void onInterrupt(int signal) {
  const char* name = signal == SIGTERM ? "SIGTERM" : "SIGINT";
  writeText("\nsemslam: interrupted by ");
  writeText(name);
  writeText("; removed the partial output\n");
  for (std::size_t k = slots.size(); k-- > 0;) {
    Slot& slot = slots[k];
    if (slot.state.load() != kReady) continue;
    if (slot.folder) {
      removeFolderTree(slot.temporary);
    } else {
      ::unlink(slot.temporary);
    }
    writeText("semslam: not written: ");
    writeText(slot.target);
    writeText("\n");
  }
  ::_exit(128 + signal);
}

std::atomic<long> completedFiles{0};

}  // namespace

bool removeFolderTree(const char* path) {
  const int dir = ::open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (dir < 0) return errno == ENOENT;
  const bool emptied = emptyFolder(dir, 16);
  ::close(dir);
  return emptied && ::rmdir(path) == 0;
}

void installInterruptCleanup() {
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

TemporaryOutput::TemporaryOutput(const std::string& temporary, const std::string& target, bool folder) {
  for (std::size_t k = 0; k < slots.size(); ++k) {
    int expected = kFree;
    if (!slots[k].state.compare_exchange_strong(expected, kFilling)) continue;
    try {
      copyPath(slots[k].temporary, temporary);
      copyPath(slots[k].target, target);
    } catch (...) {
      slots[k].state.store(kFree);
      throw;
    }
    slots[k].folder = folder;
    slots[k].state.store(kReady);
    slot_ = k;
    return;
  }
  throw std::runtime_error("more than " + std::to_string(kMaxTemporaryOutputs) + " outputs written at once");
}

TemporaryOutput::~TemporaryOutput() { slots[slot_].state.store(kFree); }

void noteCompletedOutputFile() {
  static const long interruptAfter = [] {
    const char* setting = std::getenv("SEMSLAM_TEST_INTERRUPT_AFTER_FILES");
    return setting == nullptr ? 0L : std::strtol(setting, nullptr, 10);
  }();
  static const int signal = [] {
    const char* setting = std::getenv("SEMSLAM_TEST_INTERRUPT_AFTER_FILES");
    return setting != nullptr && std::strstr(setting, ":TERM") != nullptr ? SIGTERM : SIGINT;
  }();
  if (++completedFiles == interruptAfter) std::raise(signal);
}

}  // namespace semslam
