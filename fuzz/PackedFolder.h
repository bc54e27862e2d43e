#pragma once
// A dataset folder packed into one file, for the converters' fuzz harnesses (fuzz/ConverterReaders.h): sections,
// each a line "==> NAME <==" (as `head` prints several files) followed by that file's bytes up to the next such
// line. Bytes before the first section are ignored. Only names in the harness's list are written, so nothing of the
// input reaches the file system as a path; a name given twice keeps its last section; a name not given is absent.
//
// PackedFolder unpacks into a fresh private folder under the temporary directory and removes it when destroyed.

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>

namespace semslam::fuzz {

class PackedFolder {
 public:
  PackedFolder(const std::string& packedPath, const std::set<std::string>& names) {
    static std::atomic<unsigned> counter{0};
    folder_ = std::filesystem::temp_directory_path() /
              ("semslam-fuzz-folder-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
    std::ifstream in(packedPath, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::map<std::string, std::string> files;
    std::string* current = nullptr;
    std::size_t start = 0;
    while (start < text.size()) {
      std::size_t end = text.find('\n', start);
      const std::size_t next = end == std::string::npos ? text.size() : end + 1;
      const std::string line = text.substr(start, (end == std::string::npos ? text.size() : end) - start);
      if (line.size() > 8 && line.rfind("==> ", 0) == 0 && line.compare(line.size() - 4, 4, " <==") == 0) {
        const std::string name = line.substr(4, line.size() - 8);
        current = names.contains(name) ? &(files[name] = std::string()) : nullptr;
      } else if (current != nullptr) {
        current->append(text, start, next - start);
      }
      start = next;
    }
    for (const auto& [name, bytes] : files) {
      std::filesystem::create_directories((folder_ / name).parent_path());
      std::ofstream(folder_ / name, std::ios::binary) << bytes;
    }
  }
  ~PackedFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
  }
  PackedFolder(const PackedFolder&) = delete;
  PackedFolder& operator=(const PackedFolder&) = delete;

  std::string path() const { return folder_.string(); }
  std::string path(const std::string& name) const { return (folder_ / name).string(); }

 private:
  std::filesystem::path folder_;
};

}  // namespace semslam::fuzz
