#include "semslam/io/StagedFolder.h"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "semslam/core/InputError.h"
#include "semslam/io/InterruptCleanup.h"
#include "semslam/io/OutputTarget.h"

namespace semslam {

namespace {

namespace fs = std::filesystem;

/// Whether `target` holds an existing folder (true), nothing (false), or throws for anything else.
bool existingFolder(const std::string& target, bool overwrite) {
  struct stat status {};
  if (::lstat(target.c_str(), &status) != 0) {
    if (errno == ENOENT) return false;
    throw InputError(target, 0, std::string("cannot write here: ") + std::strerror(errno));
  }
  if (S_ISLNK(status.st_mode)) {
    throw InputError(target, 0, "is a symbolic link: refusing to follow or replace it (remove it, or write elsewhere)");
  }
  if (!S_ISDIR(status.st_mode)) throw InputError(target, 0, "exists and is not a folder: expected an output folder");
  std::error_code error;
  if (!overwrite && !fs::is_empty(target, error)) {
    throw InputError(target, 0, "the output folder exists and is not empty: pass --overwrite to replace it whole");
  }
  return true;
}

}  // namespace

StagedFolder::StagedFolder(std::string target, bool overwrite) : target_(std::move(target)), overwrite_(overwrite) {
  existingFolder(target_, overwrite_);
  const fs::path parent = fs::path(temporaryNameBeside(target_)).parent_path();
  if (!parent.empty()) fs::create_directories(parent);
  for (int attempt = 0; staging_.empty(); ++attempt) {
    std::string name = temporaryNameBeside(target_);
    if (::mkdir(name.c_str(), 0777) == 0) {  // the umask applies, as to any folder the command makes
      staging_ = std::move(name);
    } else if (errno != EEXIST || attempt == 15) {
      throw std::runtime_error("cannot write " + target_ + ": cannot create a staging folder beside it: " +
                               std::strerror(errno));
    }
  }
  registration_ = std::make_unique<TemporaryOutput>(staging_, target_, true);
}

StagedFolder::~StagedFolder() {
  if (!committed_) removeFolderTree(staging_.c_str());
}

void StagedFolder::commit() {
  const bool replacing = existingFolder(target_, overwrite_);
  if (!replacing || fs::is_empty(target_)) {
    if (::rename(staging_.c_str(), target_.c_str()) != 0) {
      throw std::runtime_error("cannot write " + target_ + ": " + std::strerror(errno));
    }
  } else if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0) {
    throw std::runtime_error("cannot replace " + target_ + ": " + std::strerror(errno));
  }
  // Now the staging path holds the old folder (or nothing): the new output is in place, and whatever remains at
  // the staging path is removed, here or by the interruption handler.
  committed_ = true;
  removeFolderTree(staging_.c_str());
  registration_.reset();
}

}  // namespace semslam
