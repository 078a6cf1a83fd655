// What `lattice export pov` writes: the camera's vectors, the light falloff,
// materials, CSG, lattices declared once and placed per instance, and errors
// that name the file and line (exporter/pov_export.hpp).
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cstring>
#include <string>

#include "exporter/pov_export.hpp"
#include "foundation/system/atomic_file.hpp"
#include "foundation/error.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

using namespace lattice;
using lattice::exporter::povText;

namespace {

const char* kScene = R"(
[options]
width = 5
height = 3
ambient = 0.2
K = 0.5

[camera]
type = "thesis"
distance = 2.0
width = 1.0
height = 0.5

[materials.red]
ambient = [0.5, 0.1, 0.1]
diffuse = [0.6, 0.0, 0.2]
specular = [0.5, 0.25, 0.75]
shininess = 20

[[lights]]
position = [1.0, 2.0, -3.0]
intensity = 4.0

[[lattices]]
name = "hair"
spacing = 0.05
shadows = false
object = { type = "polyline", radius = 0.02, points = [[0, 0, 0], [0, 0, 0.2], [0.1, 0, 0.3]] }

[[objects]]
type = "difference"
material = "red"
children = [ { type = "sphere", radius = 1.0 }, { type = "cylinder", radius = 0.3 } ]

[[objects]]
type = "lattice_scatter"
lattice = "hair"
count = 3
radius = 1.0

[[objects]]
type = "torus"
major = 1.0
minor = 0.25
translate = [0, 3, 0]
)";

// A leaf type that does not say what it is made of.
class Secret final : public LeafTemplate<Secret> {
 public:
  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d&, MaterialId, const BuildOptions&) const {
    return nullptr;
  }
  Bounds<double> objectBounds() const override { return {Vec3d(-1.0), Vec3d(1.0)}; }
  std::string describe() const override { return "a secret leaf"; }
};

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

exporter::PovText exportText(const std::string& scene, const exporter::PovExportOptions& options = {}) {
  return povText(lht::parseSceneWithLattices(scene, "test.toml").scene, options);
}

}  // namespace

TEST_CASE("exporter: the thesis camera's corner pixels land on the display's corners") {
  const std::string text = exportText(kScene).text;
  // right = W Nx / (Nx - 1) = 1.25, up = H Ny / (Ny - 1) = 0.75, direction (0, 0, D).
  CHECK_THAT(text, Catch::Contains("location <0, 0, -2>"));
  CHECK_THAT(text, Catch::Contains("direction <0, 0, 2>"));
  CHECK_THAT(text, Catch::Contains("right <1.25, 0, 0>"));
  CHECK_THAT(text, Catch::Contains("up <0, 0.75, 0>"));
  // The vectors follow the size asked for: 11 pixels wide gives 1.1.
  exporter::PovExportOptions wide;
  wide.width = 11;
  const std::string wideText = exportText(kScene, wide).text;
  const auto at = wideText.find("right <");
  REQUIRE(at != std::string::npos);
  CHECK(std::stod(wideText.substr(at + 7)) == Approx(1.1).epsilon(1e-14));
}

TEST_CASE("exporter: lights fade as I_inc / (D + K) and materials carry eq. 2.3's coefficients") {
  const exporter::PovText out = exportText(kScene);
  // colour I / (2 K) = 4, fade_distance K = 0.5.
  CHECK_THAT(out.text, Catch::Contains("light_source { <1, 2, -3> rgb <4, 4, 4> fade_distance 0.5 fade_power 1 }"));
  CHECK_THAT(out.text, Catch::Contains("ambient_light rgb <0.2, 0.2, 0.2>"));
  // Pigment k_diff (a zero channel kept tiny), ambient k_amb / k_diff, mean phong.
  CHECK_THAT(out.text, Catch::Contains("pigment { rgb <0.6, 1e-09, 0.2> }"));
  CHECK_THAT(out.text, Catch::Contains("ambient rgb <0.8333333333333334, 1"));
  CHECK_THAT(out.text, Catch::Contains("phong 0.5 phong_size 20"));
  REQUIRE(out.notes.size() == 1);
  CHECK_THAT(out.notes[0], Catch::Contains("'red'") && Catch::Contains("differ by channel"));
}

TEST_CASE("exporter: CSG stays CSG, closed forms are POV's own, a lattice is declared once") {
  const std::string text = exportText(kScene).text;
  CHECK(count(text, "difference {") == 1);
  CHECK_THAT(text, Catch::Contains("sphere { <0, 0, 0>, 1 texture { Material1 } }"));
  CHECK(count(text, "quadric {") == 1);
  CHECK(count(text, "torus { 1, 0.25 sturm") == 1);
  // Three instances of one lattice: one declaration (3 spheres, 2 cylinders), three objects, no shadows.
  CHECK(count(text, "#declare Lattice0 = union {") == 1);
  CHECK(count(text, "#declare Lattice") == 1);
  CHECK(count(text, "object { Lattice0 matrix <") == 3);
  CHECK(count(text, "no_shadow") == 3);
  CHECK(count(text, "cylinder {") == 2);
  CHECK(count(text, "sphere { <") == 3 + 1);
  exporter::PovExportOptions sweep;
  sweep.sphereSweep = true;
  const std::string swept = exportText(kScene, sweep).text;
  CHECK(count(swept, "sphere_sweep { linear_spline 3, <0, 0, 0>, 0.02, <0, 0, 0.2>, 0.02, <0.1, 0, 0.3>, 0.02") == 1);
  CHECK(count(swept, "cylinder {") == 0);
}

TEST_CASE("exporter: a scatter's instances hold no place of their own and are written with the scatter's") {
  const SceneDesc scene = lht::parseSceneWithLattices(kScene, "test.toml").scene;
  const NodeDesc* scatter = nullptr;
  for (const NodeDesc& object : scene.root.children)
    if (object.children.size() == 3) scatter = &object;
  REQUIRE(scatter);
  CHECK(scatter->origin == "test.toml:35:1");
  // One copy of the place, not one per instance (thousands on Plate 7).
  for (const NodeDesc& instance : scatter->children) CHECK(instance.origin.empty());
  CHECK_THAT(exportText(kScene).text, Catch::Contains("// lattice 'hair' (test.toml:35:1) as its exact object"));
}

TEST_CASE("exporter: what POV-Ray cannot express is refused, naming the file and line") {
  std::string negativeK = kScene;
  negativeK.replace(negativeK.find("K = 0.5"), 7, "K = -0.5");
  try {
    exportText(negativeK);
    FAIL("K < 0 was exported");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    CHECK_THAT(e.what(), Catch::Contains("test.toml") && Catch::Contains("K = -0.5"));
  }
  SceneDesc scene;
  scene.root.children.push_back(NodeDesc::makeLeaf(std::make_shared<Secret>(), "test.toml:7:1"));
  try {
    povText(scene);
    FAIL("an opaque leaf was exported");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    CHECK_THAT(e.what(), Catch::Contains("test.toml:7:1") && Catch::Contains("a secret leaf"));
  }
}

TEST_CASE("exporter: `lattice export pov` writes the file and names a bad scene's file and line") {
  const lattice::testing::TempDir dir("export-pov");
  const auto scene = dir / "scene.toml";
  const auto pov = dir / "scene.pov";
  writeFileAtomically(scene, std::span(reinterpret_cast<const std::uint8_t*>(kScene), std::strlen(kScene)));
  auto run = lattice::testing::runLattice(fmt::format("export pov '{}' -o '{}' -q", scene, pov));
  CHECK(run.exitCode == 0);
  const auto written = readWholeFile(pov);
  CHECK_THAT(std::string(written.begin(), written.end()), Catch::Contains("#version 3.7;"));
  // Nothing is left beside the output (written atomically).
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
  CHECK(files == 2);

  const std::string broken = "[options]\nwidth = 5\n\n[[objects]]\ntype = \"sphere\"\nradius = -1\n";
  writeFileAtomically(scene, std::span(reinterpret_cast<const std::uint8_t*>(broken.data()), broken.size()));
  run = lattice::testing::runLattice(fmt::format("export pov '{}' -o '{}' -q", scene, pov));
  CHECK(run.exitCode != 0);
  CHECK_THAT(run.stderrText, Catch::Contains("scene.toml:") && Catch::Contains("radius"));

  run = lattice::testing::runLattice("export pov --help >/dev/null");
  CHECK(run.exitCode == 0);
}
