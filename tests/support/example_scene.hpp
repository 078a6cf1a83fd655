#pragma once
// The example scenes of scenes/ as the end-to-end suites render them: loaded
// with the lattice section and types (hook.toml holds a lattice leaf), then a
// double-precision renderer at a small test size on two threads. Header-only:
// only test binaries that link lattice_render and lattice_lht include it.
#include <string>

#include "loader/lattice_scene_loader.hpp"
#include "render/renderer.hpp"
#include "tests/support/golden.hpp"

namespace lattice::testing {

inline SceneDesc loadExampleScene(const std::string& fileName) {
  return lht::loadSceneWithLattices(sourcePath("scenes/" + fileName)).scene;
}

inline Renderer<double> makeTestRenderer(const SceneDesc& scene, int width, int height) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.threads = 2;
  return Renderer<double>(scene, settings);
}

}  // namespace lattice::testing
