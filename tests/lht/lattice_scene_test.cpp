// Lattices in scene files: the [[lattices]] section, the lattice /
// lattice_scatter / polyline node types, the cache file, and the image a
// lattice renders compared with the full ray trace of its object.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "io/image_metrics.hpp"
#include "loader/canonical_toml.hpp"
#include "lht/raster/lattice_object.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "loader/table_build.hpp"
#include "render/renderer.hpp"
#include "loader/scene_loader.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/hair_scene.hpp"
#include "tests/support/temp_dir.hpp"
#include "foundation/system/atomic_file.hpp"
#include "lht/file/lht_file.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::io;
using namespace lattice::lht;

namespace {

// Table settings that force the entry form (and, with quiet, show no progress).
TableSettings tablesIn(std::optional<LhtPrecision> form, bool quiet = false) {
  TableSettings settings;
  settings.precision = form;
  settings.progress = !quiet;
  return settings;
}

// A small fuzzy sphere (thesis sec. 3.4) with a floor, two lights.
std::string fuzzyScene(int hairs, const std::string& extraLatticeKeys = "") {
  testing::HairScene scene;
  scene.size = 72;
  scene.hairs = hairs;
  if (!extraLatticeKeys.empty()) scene.latticeKeys = extraLatticeKeys + "\n";
  scene.fur = true;
  scene.fillLight = true;
  scene.floor = true;
  return scene.toml();
}

RgbImage render(const SceneDesc& scene, bool full, bool latticeShadows = true) {
  RenderSettings settings;
  settings.threads = 2;
  settings.build.fullRayTrace = full;
  settings.build.latticeShadows = latticeShadows;
  Renderer<double> renderer(scene, settings);
  return renderImage(renderer);
}

std::string loadError(const std::string& text) {
  try {
    parseSceneWithLattices(text, "bad.toml").scene;
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    return e.what();
  }
  FAIL("the scene was accepted");
  return {};
}

}  // namespace

TEST_CASE("lattice scene: a lattice renders close to the full ray trace of its object") {
  const SceneDesc scene = parseSceneWithLattices(fuzzyScene(300), "fuzzy.toml").scene;
  const RgbImage lattice = render(scene, false);
  const RgbImage full = render(scene, true);
  const testing::ImageDifference diff = testing::compareImages(lattice, full);
  INFO("differing pixels " << diff.differingPixels << ", max delta " << diff.maxChannelDelta << ", MSE "
                           << diff.meanSquaredError);
  // Hairs here are about one pixel thick, so nearly every hair pixel is a
  // silhouette pixel, and rounding a ray to the lattice moves silhouettes by
  // up to half a cell: pixel by pixel the images differ a lot (measured:
  // ~23% of pixels, MSE ~650). What must agree is the texture at the scale of
  // a few pixels, which is what a lattice promises (thesis sec. 2.1): mean
  // brightness over 8 x 8 blocks.
  CHECK(diff.differingPixels > 0);  // the two paths really are different code
  CHECK(diff.differingPixels < 72 * 72 * 35 / 100);
  double worstBlock = 0.0, sumBlock = 0.0;
  int blocks = 0;
  for (int by = 0; by < 72; by += 8)
    for (int bx = 0; bx < 72; bx += 8) {
      double a = 0.0, b = 0.0;
      for (int y = by; y < by + 8; ++y)
        for (int x = bx; x < bx + 8; ++x)
          for (int c = 0; c < 3; ++c) {
            const std::size_t i = (static_cast<std::size_t>(y) * 72 + static_cast<std::size_t>(x)) * 3 + c;
            a += lattice.rgb[i];
            b += full.rgb[i];
          }
      const double delta = std::abs(a - b) / (8 * 8 * 3);
      worstBlock = std::max(worstBlock, delta);
      sumBlock += delta;
      ++blocks;
    }
  INFO("8x8 block mean |difference|: worst " << worstBlock << ", average " << sumBlock / blocks);
  CHECK(worstBlock < 20.0);   // measured 11.8 of 255
  CHECK(sumBlock / blocks < 4.0);  // measured 2.05
}

// A lattice ball seen along the lattice's z axis by a (nearly) parallel
// bundle of rays, one through each grid column: every ray enters and leaves
// the lattice box at grid points, so rounding to the grid moves nothing and
// the lattice's only error is its entries' quantization - which the entry
// precision decides. (In ordinary scenes rounding rays to the grid dominates
// instead; docs/lattices.md, "Entry precision".) The box is 2.5 units, 15
// cells of 1/6; the thesis camera's 16 pixel centres span exactly 2.5.
const char* kGridAlignedBall = R"(
[options]
width = 16
height = 16
ambient = 0.1
K = 0
[camera]
type = "thesis"
distance = 10000.0
width = 2.5
height = 2.5
[materials.shiny]
diffuse = [0.8, 0.5, 0.3]
specular = 0.6
shininess = 40
[[lights]]
position = [-3.0, 4.0, -6.0]
intensity = 60.0
[[lattices]]
name = "ball"
spacing = 0.5
oversample = 3
shadows = false   # shadow rays are not grid-aligned; a convex ball casts none on itself anyway
object = { type = "sphere", radius = 1.0 }
[[objects]]
type = "lattice"
lattice = "ball"
material = "shiny"
)";

TEST_CASE("lattice scene: the wide entry renders closer to the full ray trace than the thesis's") {
  const RgbImage full = render(parseSceneWithLattices(kGridAlignedBall, "ball.toml").scene, true);
  std::map<LhtPrecision, ImageMetrics> error;
  for (const LhtPrecisionInfo& form : kLhtPrecisions) {
    const SceneWithLattices loaded =
        parseSceneWithLattices(kGridAlignedBall, "ball.toml", tablesIn(form.precision));
    error[form.precision] = compareRgb(render(loaded.scene, false), full);
  }
  const ImageMetrics& thesis = error[LhtPrecision::Thesis];
  const ImageMetrics& wide = error[LhtPrecision::Wide];
  const ImageMetrics& compact = error[LhtPrecision::Compact];
  INFO("PSNR / max error against the full ray trace: thesis " << thesis.psnr << " dB / " << thesis.maxChannelError
                                                              << ", wide " << wide.psnr << " / " << wide.maxChannelError
                                                              << ", compact " << compact.psnr << " / "
                                                              << compact.maxChannelError);
  // Measured: thesis 54.2 dB / 5, wide 70.0 dB / 1, compact 50.3 dB / 11.
  CHECK(thesis.maxChannelError <= 8);  // the geometry agrees: only shading is off
  CHECK(wide.psnr >= thesis.psnr + 10.0);
  CHECK(wide.maxChannelError <= 2);
  CHECK(wide.maxChannelError <= thesis.maxChannelError);
  CHECK(wide.differingPixels < thesis.differingPixels);
  // The compact entry's octahedral normal is coarser than the thesis's 3 bytes.
  CHECK(compact.psnr <= thesis.psnr);
  CHECK(compact.psnr >= thesis.psnr - 8.0);
}

TEST_CASE("lattice scene: lattice-lattice shadows can be switched off (plate 3 vs plate 4)") {
  const SceneDesc scene = parseSceneWithLattices(fuzzyScene(300), "fuzzy.toml").scene;
  const RgbImage withShadows = render(scene, false, true);
  const RgbImage without = render(scene, false, false);
  const auto diff = testing::compareImages(withShadows, without);
  CHECK(diff.differingPixels > 20);  // hair shadows on the sphere and floor disappear
  // Without shadows nothing gets darker.
  long brighter = 0, darker = 0;
  for (std::size_t i = 0; i < without.rgb.size(); ++i) {
    if (without.rgb[i] > withShadows.rgb[i]) ++brighter;
    if (without.rgb[i] < withShadows.rgb[i]) ++darker;
  }
  CHECK(brighter > 20 * darker);
  // The per-lattice switch does the same.
  const SceneDesc off = parseSceneWithLattices(fuzzyScene(300, "shadows = false"), "fuzzy.toml").scene;
  CHECK(testing::compareImages(render(off, false), without).differingPixels == 0);
}

TEST_CASE("lattice scene: scatter places N instances on the sphere") {
  const SceneDesc scene = parseSceneWithLattices(fuzzyScene(50), "fuzzy.toml").scene;
  // root = union of the top-level objects; the scatter is the second one.
  REQUIRE(scene.root.children.size() == 3);
  const NodeDesc& scatter = scene.root.children[1];
  REQUIRE(scatter.children.size() == 50);
  for (const NodeDesc& hair : scatter.children) {
    const Vec3d root = transformPoint(scatter.transform * hair.transform, Vec3d(0.0));
    CHECK(glm::length(root) == Approx(0.9));
    const Vec3d up = glm::normalize(transformDirection(hair.transform, Vec3d(0, 0, 1)));
    CHECK(glm::dot(up, glm::normalize(root)) == Approx(1.0));
  }
  const auto points = fibonacciSphere(1000);
  double closest = 10.0;
  for (std::size_t i = 1; i < points.size(); ++i) closest = std::min(closest, glm::length(points[i] - points[0]));
  CHECK(closest > 0.05);  // almost uniform: no two points bunch up (mean spacing ~0.11)
}

TEST_CASE("lattice scene: a scatter's placements are the same matrices at every thread count") {
  // 700 instances: above the count placed on threads (loader/lattice_scene_loader.cpp).
  TableSettings one;
  one.threads = 1;
  const SceneDesc serial = parseSceneWithLattices(fuzzyScene(700), "fuzzy.toml", one).scene;
  const std::vector<NodeDesc>& expected = serial.root.children[1].children;
  REQUIRE(expected.size() == 700);
  for (unsigned threads : {2u, 3u}) {
    TableSettings tables;
    tables.threads = threads;
    const SceneDesc scene = parseSceneWithLattices(fuzzyScene(700), "fuzzy.toml", tables).scene;
    const std::vector<NodeDesc>& placed = scene.root.children[1].children;
    REQUIRE(placed.size() == expected.size());
    int differ = 0, unplaced = 0;
    for (std::size_t i = 0; i < placed.size(); ++i) {
      differ += std::memcmp(&placed[i].transform, &expected[i].transform, sizeof(Mat4d)) != 0;
      unplaced += placed[i].transform == Mat4d(1.0);
    }
    CHECK(differ == 0);
    CHECK(unplaced == 0);
  }
}

namespace {

// The scene with every lattice instance written out as its exact object,
// placed where the instance is: what the full ray trace built before
// instancing (one world-space copy per hair).
NodeDesc expandLattices(const NodeDesc& node) {
  if (node.kind == NodeDesc::Kind::Leaf) {
    const std::optional<LeafShape> shape = node.leaf->shape();
    const LatticeShape* lattice = shape ? std::get_if<LatticeShape>(&*shape) : nullptr;
    if (!lattice) return node;
    NodeDesc copy = *lattice->object;
    copy.transform = node.transform * copy.transform;
    if (!copy.material) copy.material = node.material;
    return copy;
  }
  NodeDesc copy = node;
  for (NodeDesc& child : copy.children) child = expandLattices(child);
  return copy;
}

template <typename T>
RgbImage renderFull(const SceneDesc& scene) {
  RenderSettings settings;
  settings.threads = 2;
  settings.build.fullRayTrace = true;
  Renderer<T> renderer(scene, settings);
  return renderImage(renderer);
}

}  // namespace

TEST_CASE("lattice scene: the full trace of a scatter shares one object and draws what world copies draw") {
  const SceneDesc scene = parseSceneWithLattices(fuzzyScene(300), "fuzzy.toml").scene;
  SceneDesc copies = scene;
  copies.root = expandLattices(scene.root);
  REQUIRE(copies.root.children[1].children.size() == 300);
  const std::optional<LeafShape> hair = copies.root.children[1].children[0].leaf->shape();
  REQUIRE((hair && std::holds_alternative<PolylineShape>(*hair)));
  // Double: the same picture to the last bit at this size (measured identical
  // at 512x512 on the fuzzy spheres and the thistle too: bench/results/2026-11-22-renderer-and-peers.md).
  CHECK(renderFull<double>(scene).rgb == renderFull<double>(copies).rgb);
  // Float: the ray is carried into object space in float, one rounding more.
  const RgbImage a = renderFull<float>(scene), b = renderFull<float>(copies);
  const testing::ImageDifference diff = testing::compareImages(a, b);
  const double psnr = diff.meanSquaredError > 0 ? 10 * std::log10(255.0 * 255.0 / diff.meanSquaredError) : 999.0;
  INFO("float, instances vs copies: " << psnr << " dB, " << diff.differingPixels << " pixels differ");
  CHECK(psnr > 45.0);
  CHECK(diff.differingPixels <= 20);
}

TEST_CASE("lattice scene: the cache file is written, reused, and refused when the object changes") {
  const auto dir = std::filesystem::temp_directory_path() / ("lattice-lht-scene-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto write = [&](const std::string& text) {
    std::ofstream(dir / "s.toml") << text;
  };
  write(fuzzyScene(5, "cache = \"hair.lht\""));
  {
    const SceneDesc scene = loadSceneWithLattices(dir / "s.toml").scene;
    render(scene, false);  // builds the lattice: rasterizes and writes the cache
  }
  REQUIRE(std::filesystem::exists(dir / "hair.lht"));
  const auto firstWrite = std::filesystem::last_write_time(dir / "hair.lht");
  {
    const SceneDesc scene = loadSceneWithLattices(dir / "s.toml").scene;
    render(scene, false);  // reads the cache
  }
  CHECK(std::filesystem::last_write_time(dir / "hair.lht") == firstWrite);
  // Same cache name, thicker hair: the old table must not be used.
  std::string changed = fuzzyScene(5, "cache = \"hair.lht\"");
  changed.replace(changed.find("radius = 0.015"), 14, "radius = 0.014");
  write(changed);
  const SceneDesc scene = loadSceneWithLattices(dir / "s.toml").scene;
  try {
    render(scene, false);
    FAIL("a stale cache was used");
  } catch (const Error& e) {
    const std::string message = e.what();
    CHECK(message.find("hair.lht") != std::string::npos);
    CHECK(message.find("different object") != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("lattice scene: a cache an older Lattice wrote is rebuilt, not refused") {
  const lattice::testing::TempDir dir("lht-old-cache");
  std::ofstream(dir / "s.toml") << fuzzyScene(5, "cache = \"hair.lht\"");
  const std::filesystem::path cache = dir / "hair.lht";
  render(loadSceneWithLattices(dir / "s.toml").scene, false);  // writes a version-4 cache
  std::vector<std::uint8_t> bytes = readWholeFile(cache);
  REQUIRE(bytes.size() > 12);
  REQUIRE(bytes[8] == lht::kLhtVersion);
  bytes[8] = 2;  // as version 2 of the format, the thesis's chained table, headed it
  writeFileAtomically(cache, bytes);
  REQUIRE(lht::retiredLhtVersion(cache) == 2u);
  const RgbImage picture = render(loadSceneWithLattices(dir / "s.toml").scene, false);
  CHECK(picture.width > 0);
  CHECK_FALSE(lht::retiredLhtVersion(cache));  // rewritten in today's layout
  CHECK(lht::readLhtFile(cache).version == lht::kLhtVersion);
}

TEST_CASE("lattice scene: the precision key picks the entry form and the thesis's keeps the old object hash") {
  const auto definition = [](const std::string& keys) {
    const auto defs = parseSceneWithLattices(fuzzyScene(5, keys), "p.toml").lattices;
    REQUIRE(defs.size() == 1);
    return defs[0];
  };
  const LatticeDefinitionPtr plain = definition("");
  CHECK(plain->precision == LhtPrecision::Thesis);
  CHECK(definition("precision = \"thesis\"")->hash() == plain->hash());
  // The key of a thesis-precision lattice names no precision.
  CHECK(plain->hash() == fnv1a64(fmt::format("lattice2 spacing={} oversample={} object={}",
                                             canonicalDouble(plain->lambda), canonicalDouble(plain->oversample),
                                             plain->objectText)));
  for (const char* name : {"wide", "compact"}) {
    const LatticeDefinitionPtr d = definition(fmt::format("precision = \"{}\"", name));
    CHECK(lhtPrecisionName(d->precision) == name);
    CHECK(d->hash() != plain->hash());
    CHECK(buildLatticeTable(*d, tablesIn(std::nullopt, true)).lht.precision() == d->precision);
  }
}

TEST_CASE("lattice scene: a cache of another precision is refused and not silently used") {
  const auto dir = std::filesystem::temp_directory_path() / ("lattice-lht-precision-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "s.toml") << fuzzyScene(5, "cache = \"hair.lht\"");
  render(loadSceneWithLattices(dir / "s.toml").scene, false);  // writes a thesis cache
  REQUIRE(readLhtFile(dir / "hair.lht").precision() == LhtPrecision::Thesis);
  const auto expectRefusal = [&](const SceneDesc& scene, const std::string& asked) {
    try {
      render(scene, false);
      FAIL("a cache of another precision was used");
    } catch (const Error& e) {
      const std::string message = e.what();
      CHECK(message.find("hair.lht") != std::string::npos);
      CHECK(message.find("'thesis' entries") != std::string::npos);
      CHECK(message.find("'" + asked + "'") != std::string::npos);
    }
  };
  // In the scene file...
  std::ofstream(dir / "s.toml") << fuzzyScene(5, "cache = \"hair.lht\"\nprecision = \"wide\"");
  expectRefusal(loadSceneWithLattices(dir / "s.toml").scene, "wide");
  // ... or in the settings the scene is loaded with, as --lht-precision does...
  std::ofstream(dir / "s.toml") << fuzzyScene(5, "cache = \"hair.lht\"");
  const SceneWithLattices loaded = loadSceneWithLattices(dir / "s.toml", tablesIn(LhtPrecision::Compact));
  REQUIRE(loaded.lattices.size() == 1);
  expectRefusal(loaded.scene, "compact");
  // ... or rebound with later, leaving the loaded scene as it was.
  const SceneWithLattices plain = loadSceneWithLattices(dir / "s.toml");
  expectRefusal(withTableSettings(plain, tablesIn(LhtPrecision::Wide)).scene, "wide");
  render(plain.scene, false);  // the thesis cache still serves the scene as loaded
  std::filesystem::remove_all(dir);
}

TEST_CASE("lattice scene: the loader knows lattices only through the format it is handed") {
  // The built-in format has no lattices, whatever was loaded before.
  const SceneWithLattices first = parseSceneWithLattices(fuzzyScene(5), "a.toml");
  REQUIRE_THROWS_WITH(parseScene(fuzzyScene(5), "b.toml"), Catch::Contains("unknown section 'lattices'"));
  // Each load returns its own definitions, in file order.
  const SceneWithLattices second = parseSceneWithLattices(fuzzyScene(5), "c.toml");
  REQUIRE(first.lattices.size() == 1);
  REQUIRE(second.lattices.size() == 1);
  CHECK(first.lattices[0]->name == "hair");
  CHECK(first.lattices[0] != second.lattices[0]);
  CHECK(first.lattices[0]->hash() == second.lattices[0]->hash());
}

TEST_CASE("lattice scene: the packing hook of the table settings picks the form, and such a table is not cached") {
  const auto dir = std::filesystem::temp_directory_path() / ("lattice-lht-packing-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "s.toml") << fuzzyScene(5, "cache = \"hair.lht\"");
  int calls = 0;
  std::uint64_t entriesSeen = 0;
  TableSettings settings;
  settings.progress = false;
  settings.packing = [&](const LatticeDefinition& lattice, LhtPrecision requested, std::uint64_t entries,
                         std::uint64_t hitListBytes) {
    ++calls;
    CHECK(lattice.name == "hair");
    CHECK(requested == LhtPrecision::Thesis);
    CHECK(hitListBytes >= entries);
    entriesSeen = entries;
    return LhtPrecision::Compact;
  };
  const SceneWithLattices loaded = loadSceneWithLattices(dir / "s.toml");
  const BuiltTable built = buildLatticeTable(*loaded.lattices.at(0), settings);
  CHECK(calls == 1);
  CHECK(built.lht.precision() == LhtPrecision::Compact);
  CHECK(built.lht.hashed().entryCount() == entriesSeen);
  CHECK(built.lht.objectHash == loaded.lattices[0]->hashFor(LhtPrecision::Compact));
  render(withTableSettings(loaded, settings).scene, false);  // five instances, one table
  CHECK(calls == 2);
  CHECK_FALSE(std::filesystem::exists(dir / "hair.lht"));  // packed otherwise than asked: not cached
  render(loaded.scene, false);  // the scene as loaded packs as asked, and caches
  CHECK(calls == 2);
  CHECK(readLhtFile(dir / "hair.lht").precision() == LhtPrecision::Thesis);
  std::filesystem::remove_all(dir);
}

TEST_CASE("lattice scene: one call builds a table for a shape or a scene's entry") {
  TableRequest sphere;
  sphere.shape = "sphere";
  sphere.radius = 2.0;
  sphere.settings.progress = false;
  const BuiltTable fromShape = buildLatticeTable(sphere);
  CHECK(fromShape.lht.objectHash == sphereObject(2.0).hash());
  CHECK(fromShape.lht.box.cells() == LatticeBox(sphereObject(2.0).bounds, 1.0, 1.0).cells());
  CHECK(fromShape.lht.hits == fromShape.stats.hits);
  CHECK(fromShape.lht.hashed().entryCount() > 0);
  TableRequest wrong = sphere;
  wrong.shape = "cube";
  REQUIRE_THROWS_WITH(buildLatticeTable(wrong), Catch::Contains("unknown --shape 'cube'"));
  TableRequest neither;
  REQUIRE_THROWS_WITH(buildLatticeTable(neither), Catch::Contains("--scene FILE --name NAME or --shape"));

  const auto dir = std::filesystem::temp_directory_path() / ("lattice-lht-request-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "s.toml") << fuzzyScene(5);
  TableRequest entry;
  entry.scene = dir / "s.toml";
  entry.name = "hair";
  entry.oversample = 1.0;  // the file says 2
  entry.settings = tablesIn(LhtPrecision::Wide, true);
  const BuiltTable fromScene = buildLatticeTable(entry);
  LatticeDefinition expected = *loadSceneWithLattices(entry.scene).lattices.at(0);
  expected.oversample = 1.0;
  CHECK(fromScene.lht.objectHash == expected.hashFor(LhtPrecision::Wide));
  CHECK(fromScene.lht.precision() == LhtPrecision::Wide);
  entry.name = "fur";
  REQUIRE_THROWS_WITH(buildLatticeTable(entry), Catch::Contains("no [[lattices]] entry named 'fur' (defined: hair)"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("lattice scene: mistakes are located errors") {
  CHECK(loadError("[[objects]]\ntype = \"lattice\"\nlattice = \"nope\"\n").find("no lattice named 'nope'") !=
        std::string::npos);
  CHECK(loadError("[[lattices]]\nname = \"a\"\nspacing = 1\n").find("object") != std::string::npos);
  CHECK(loadError("[[lattices]]\nname = \"a\"\nspacing = -1\nobject = { type = \"sphere\", radius = 1 }\n")
            .find("bad.toml:") != std::string::npos);
  CHECK(loadError("[[lattices]]\nname = \"a\"\nspacing = 1\noversample = 0.5\nobject = { type = \"sphere\", radius = 1 }\n")
            .find("oversample") != std::string::npos);
  CHECK(loadError("[[objects]]\ntype = \"polyline\"\nradius = 1\npoints = [[0, 0, 0]]\n").find("two points") !=
        std::string::npos);
  const std::string twice =
      "[[lattices]]\nname = \"a\"\nspacing = 1\nobject = { type = \"sphere\", radius = 1 }\n"
      "[[lattices]]\nname = \"a\"\nspacing = 1\nobject = { type = \"sphere\", radius = 1 }\n";
  CHECK(loadError(twice).find("defined twice") != std::string::npos);
  const std::string badPrecision = loadError(
      "[[lattices]]\nname = \"a\"\nspacing = 1\nprecision = \"huge\"\nobject = { type = \"sphere\", radius = 1 }\n");
  CHECK(badPrecision.find("bad.toml:4:") != std::string::npos);
  CHECK(badPrecision.find("'huge'") != std::string::npos);
  CHECK(badPrecision.find("thesis (14 B/entry), wide (16 B/entry), compact (13 B/entry)") != std::string::npos);
  const std::string notAString = loadError(
      "[[lattices]]\nname = \"a\"\nspacing = 1\nprecision = 16\nobject = { type = \"sphere\", radius = 1 }\n");
  CHECK(notAString.find("bad.toml:4:") != std::string::npos);
  CHECK(notAString.find("precision") != std::string::npos);
}

TEST_CASE("lattice scene: lattice_scatter's count is capped at kMaxScatterCount with a located error") {
  std::string over = fuzzyScene(static_cast<int>(kMaxScatterCount) + 1);
  const std::string message = loadError(over);
  CHECK_THAT(message, Catch::Contains("bad.toml:") && Catch::Contains("between 1 and 100000") &&
                          Catch::Contains("docs/limits.md"));
  // The limit itself loads (placing is linear; nothing is rendered here).
  const SceneDesc scene = parseSceneWithLattices(fuzzyScene(static_cast<int>(kMaxScatterCount)), "limit.toml").scene;
  CHECK(scene.root.children.size() == 3);
}
