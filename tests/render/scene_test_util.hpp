#pragma once
// Scene text for tests: written to a real temporary file so errors name a
// real path, exactly as `lattice render` users see them.
#include <fmt/format.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "loader/scene_loader.hpp"

namespace lattice::testing {

class TempScene {
 public:
  explicit TempScene(const std::string& text) {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            fmt::format("lattice-scene-test-{}-{}.toml", ::getpid(), counter.fetch_add(1));
    std::ofstream(path_) << text;
  }
  ~TempScene() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  TempScene(const TempScene&) = delete;
  TempScene& operator=(const TempScene&) = delete;
  const std::filesystem::path& path() const { return path_; }
  SceneDesc load(const SceneFormat& format = builtinSceneFormat()) const { return loadScene(path_, format); }

 private:
  std::filesystem::path path_;
};

}  // namespace lattice::testing
