// Regression replay: every input under fuzz/corpus/<harness>/ and fuzz/findings/<harness>/ (hand-made edge cases,
// and every input a fuzzer ever found) goes through the normal Release readers. The contract, as the libFuzzer
// harnesses hold it: each input parses, or throws InputError; anything else (a crash, another exception) fails
// here. A harness folder without a reader in fuzz/FuzzReaders.h fails too, so a new corpus is never skipped.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../../fuzz/FuzzReaders.h"
#include "semslam/core/InputError.h"

namespace semslam {
namespace {

namespace fs = std::filesystem;

using fuzz::readers;

const fs::path kFuzz = fs::path(SEMSLAM_SOURCE_DIR) / "fuzz";

TEST(CorpusReplay, EveryInputParsesOrThrowsInputError) {
  std::size_t replayed = 0;
  for (const char* collection : {"corpus", "findings"}) {
    if (!fs::exists(kFuzz / collection)) continue;
    for (const auto& harness : fs::directory_iterator(kFuzz / collection)) {
      const std::string name = harness.path().filename().string();
      const auto reader = readers().find(name);
      ASSERT_NE(reader, readers().end()) << harness.path() << ": no reader for this harness";
      for (const auto& input : fs::directory_iterator(harness.path())) {
        SCOPED_TRACE(input.path().string());
        try {
          reader->second(input.path().string());
        } catch (const InputError&) {
          // the contract: a clear error
        } catch (const std::exception& error) {
          ADD_FAILURE() << "not an InputError: " << error.what();
        }
        ++replayed;
      }
    }
  }
  EXPECT_GE(replayed, readers().size()) << "the corpus is missing";
}

}  // namespace
}  // namespace semslam
