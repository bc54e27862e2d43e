#pragma once
// An output folder written completely or not at all. The folder is built in a staging folder beside the target
// (".NAME.tmp-" and 12 random characters: io/OutputTarget.h) and renamed into place whole by commit(); an
// interrupted or failed build removes the staging folder (io/InterruptCleanup.h), leaving the previous complete
// output or nothing.
//
// The target must be absent, an empty folder, or, with `overwrite`, a folder whose old contents are replaced as
// a whole (exchanged atomically with the staging folder, renameat2 RENAME_EXCHANGE, then removed): a stale file
// of an earlier run never sits beside the new ones. Refused (InputError naming the target, exit code 2): a
// symbolic link, a file or device where the folder should be, and a non-empty folder without `overwrite`.
//
// Usage: StagedFolder folder(out, overwrite); write every file under folder.path(); folder.commit().

#include <memory>
#include <string>

namespace semslam {

class TemporaryOutput;

class StagedFolder {
 public:
  StagedFolder(std::string target, bool overwrite);
  /// Not committed: removes the staging folder and everything in it.
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  /// The staging folder: write the output here.
  const std::string& path() const { return staging_; }
  const std::string& target() const { return target_; }

  /// Renames the staging folder into place (see above). Throws std::runtime_error when the rename fails (the
  /// staging folder is then removed and the target left as it was).
  void commit();

 private:
  std::string target_;
  std::string staging_;
  bool overwrite_ = false;
  bool committed_ = false;
  std::unique_ptr<TemporaryOutput> registration_;
};

}  // namespace semslam
