// One libFuzzer harness per reader (fuzz/FuzzReaders.h), chosen at compile time by SEMSLAM_FUZZ_HARNESS ("g2o"):
// each input is written to a private file and read. The contract: the reader parses it or throws InputError
// (caught here); a crash, a sanitizer report, any other exception (uncaught: libFuzzer reports it), or time or
// memory past libFuzzer's per-input limits (-timeout, -rss_limit_mb) is a finding.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "FuzzReaders.h"
#include "semslam/core/InputError.h"

namespace {

const std::string& inputPath() {
  static const std::string path = (std::filesystem::temp_directory_path() /
                                   ("semslam-fuzz-" SEMSLAM_FUZZ_HARNESS "-" + std::to_string(::getpid())))
                                      .string();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const semslam::fuzz::Reader& read = semslam::fuzz::readers().at(SEMSLAM_FUZZ_HARNESS);
  std::FILE* file = std::fopen(inputPath().c_str(), "wb");
  if (file == nullptr) return 0;
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  try {
    read(inputPath());
  } catch (const semslam::InputError&) {
    // the contract: a clear error
  }
  return 0;
}
