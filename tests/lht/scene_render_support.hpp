#pragma once
// A lattice scene's text rendered in one arithmetic on two threads, its
// tables built quietly: the picture the lattice suites compare between forms,
// caches and traversal paths.
#include <filesystem>
#include <string>

#include "loader/lattice_scene_loader.hpp"
#include "render/renderer.hpp"

namespace lattice::testing {

template <typename T>
RgbImage renderLatticeScene(const std::string& text, const std::filesystem::path& file, lht::TableSettings tables = {}) {
  tables.progress = false;
  const lht::SceneWithLattices loaded = lht::parseSceneWithLattices(text, file, tables);
  RenderSettings settings;
  settings.threads = 2;
  Renderer<T> renderer(loaded.scene, settings);
  return renderImage(renderer);
}

}  // namespace lattice::testing
