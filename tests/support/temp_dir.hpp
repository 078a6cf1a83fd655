#pragma once
// A scratch directory for one test, removed when the test ends however it
// ends (a failed REQUIRE throws past any cleanup written at the end).
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>
#include <string_view>

namespace lattice::testing {

class TempDir {
 public:
  // `label` names the test in the directory's name; the process id and a
  // counter keep parallel test processes and successive cases apart.
  explicit TempDir(std::string_view label) {
    static std::atomic<unsigned> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("lattice-" + std::string(label) + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // A file in the directory, as a string: ready for fmt and for command lines.
  std::string operator/(std::string_view name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace lattice::testing
