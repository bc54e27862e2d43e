// Outputs that cannot be hijacked or left half-written: a file goes through an unpredictable O_EXCL|O_NOFOLLOW
// temporary beside it and is renamed into place only over nothing or a regular file; a folder is staged and
// renamed into place whole (issue 16).

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <vector>
#include <string>

#include "IoTesting.h"
#include "semslam/io/AtomicFile.h"
#include "semslam/io/OutputTarget.h"
#include "semslam/io/StagedFolder.h"

namespace semslam {
namespace {

namespace fs = std::filesystem;
using test::readText;
using test::TempDir;

void writeText(const std::string& path, const std::string& text) {
  writeFileAtomically(path, [&text](std::ostream& out) { out << text; });
}

/// The names in `folder`, sorted, as one string: "a b c".
std::string listing(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : " ") + name;
  return joined;
}

TEST(SafeOutput, ASymlinkPlantedAtTheDestinationIsNeitherFollowedNorReplaced) {
  const TempDir dir;
  const std::string victim = dir.write("victim.txt", "precious");
  const std::string out = dir.path("out.g2o");
  fs::create_symlink(victim, out);
  EXPECT_INPUT_ERROR(writeText(out, "hijacked"), out, 0, "symbolic link");
  EXPECT_EQ(readText(victim), "precious");
  EXPECT_TRUE(fs::is_symlink(out));
  EXPECT_EQ(listing(dir.path("")), "out.g2o victim.txt");  // no temporary left behind
}

TEST(SafeOutput, ADeviceIsNeverReplaced) {
  // optimize --out /dev/full exited 0 and the rename replaced the device with a regular file.
  EXPECT_INPUT_ERROR(writeText("/dev/full", "x"), "/dev/full", 0, "not a regular file");
  struct stat status {};
  ASSERT_EQ(::lstat("/dev/full", &status), 0);
  EXPECT_TRUE(S_ISCHR(status.st_mode));
}

TEST(SafeOutput, AFailedWriteLeavesThePreviousFileAndNoTemporary) {
  const TempDir dir;
  const std::string out = dir.write("metrics.json", "old");
  EXPECT_THROW(writeFileAtomically(out, [](std::ostream& o) {
                 o << "half";
                 throw std::runtime_error("stop");
               }),
               std::runtime_error);
  EXPECT_EQ(readText(out), "old");
  EXPECT_EQ(listing(dir.path("")), "metrics.json");
  writeText(out, "new");
  EXPECT_EQ(readText(out), "new");
  EXPECT_EQ(listing(dir.path("")), "metrics.json");
}

TEST(SafeOutput, TemporaryNamesAreFreshAndBesideTheTarget) {
  const std::string a = temporaryNameBeside("/some/folder/out.tum");
  const std::string b = temporaryNameBeside("/some/folder/out.tum");
  EXPECT_NE(a, b);
  EXPECT_EQ(a.rfind("/some/folder/.out.tum.tmp-", 0), 0u) << a;
  EXPECT_EQ(a.size(), std::string("/some/folder/.out.tum.tmp-").size() + 12);
}

TEST(SafeOutput, AnOutputEqualToOrHoldingAnInputIsRefused) {
  const TempDir dir;
  const std::string input = dir.write("graph.g2o", "x");
  EXPECT_INPUT_ERROR(requireOutputSparesInput(input, input, "--report"), input, 0, "--report is also an input");
  EXPECT_INPUT_ERROR(requireOutputSparesInput(dir.path(""), input, "--out"), dir.path(""), 0, "holding an input");
  EXPECT_NO_THROW(requireOutputSparesInput(dir.path("report.json"), input, "--report"));
}

TEST(StagedFolder, IsInvisibleUntilCommittedAndRemovedWhenNot) {
  const TempDir dir;
  const std::string target = dir.path("run");
  {
    StagedFolder folder(target, false);
    writeText(folder.path() + "/metrics.json", "{}");
    EXPECT_FALSE(fs::exists(target));
  }
  EXPECT_EQ(listing(dir.path("")), "");
  StagedFolder folder(target, false);
  writeText(folder.path() + "/metrics.json", "{}");
  fs::create_directories(folder.path() + "/known");
  writeText(folder.path() + "/known/metrics.json", "{}");
  folder.commit();
  EXPECT_EQ(listing(target), "known metrics.json");
  EXPECT_EQ(listing(dir.path("")), "run");
}

TEST(StagedFolder, ANonEmptyFolderIsRefusedUnlessOverwriteWhichReplacesItWhole) {
  // A stale hypotheses.jsonl stayed beside an mm-nh run; 7 stale tracks after --tracks 10 then --tracks 3.
  const TempDir dir;
  const std::string target = dir.path("run");
  fs::create_directories(target);
  writeText(target + "/hypotheses.jsonl", "stale");
  EXPECT_INPUT_ERROR(StagedFolder(target, false), target, 0, "pass --overwrite");
  StagedFolder folder(target, true);
  writeText(folder.path() + "/metrics.json", "{}");
  folder.commit();
  EXPECT_EQ(listing(target), "metrics.json");
  EXPECT_EQ(listing(dir.path("")), "run");
}

TEST(StagedFolder, AnEmptyFolderIsFilledAndALinkOrFileIsRefused) {
  const TempDir dir;
  const std::string empty = dir.path("empty");
  fs::create_directories(empty);
  StagedFolder folder(empty, false);
  writeText(folder.path() + "/a.txt", "a");
  folder.commit();
  EXPECT_EQ(listing(empty), "a.txt");
  const std::string link = dir.path("link");
  fs::create_directory_symlink(empty, link);
  EXPECT_INPUT_ERROR(StagedFolder(link, true), link, 0, "symbolic link");
  const std::string file = dir.write("file", "x");
  EXPECT_INPUT_ERROR(StagedFolder(file, true), file, 0, "not a folder");
}

}  // namespace
}  // namespace semslam
