#pragma once
// Interrupted runs leave the previous complete output or nothing. Every temporary path an output is being built
// in (a file's temporary copy, a folder's staging folder) is registered here while it exists; on SIGINT or
// SIGTERM, once installInterruptCleanup() has run, the handler removes every registered temporary path (a folder
// with everything in it), prints on stderr each output that was not written, and exits with 128 + the signal
// (130, 143). The handler does only async-signal-safe work: registration keeps fixed-size slots, and folders are
// removed with getdents64/unlinkat.
//
// Test hook: when the environment variable SEMSLAM_TEST_INTERRUPT_AFTER_FILES is "N" (or "N:TERM"), the process
// raises SIGINT (SIGTERM) on itself right after its N-th completed file (io/AtomicFile.h), so a test can interrupt
// a command at a chosen point of its output deterministically.

#include <cstddef>
#include <string>

namespace semslam {

/// Installs the SIGINT and SIGTERM handlers (the command-line tool calls this once, first).
void installInterruptCleanup();

/// A temporary path registered for removal on interruption while this object lives. `target` is the output it
/// will become, named in the "not written" message. At most kMaxTemporaryOutputs are registered at once; beyond
/// that registration throws std::runtime_error.
class TemporaryOutput {
 public:
  static constexpr std::size_t kMaxTemporaryOutputs = 64;

  TemporaryOutput(const std::string& temporary, const std::string& target, bool folder);
  ~TemporaryOutput();
  TemporaryOutput(const TemporaryOutput&) = delete;
  TemporaryOutput& operator=(const TemporaryOutput&) = delete;

 private:
  std::size_t slot_;
};

/// Counts a completed output file; the test hook above raises its signal at the configured count.
void noteCompletedOutputFile();

/// Removes the folder `path` and everything in it without following symbolic links; false if something could
/// not be removed. Async-signal-safe.
bool removeFolderTree(const char* path);

}  // namespace semslam
