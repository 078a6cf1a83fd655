// The table forms in scenes (lht/table/lht_form.hpp): `form = "compressed"` and
// `"on-demand"` (or TableSettings::form, `--lht-form`) render the pictures the
// hashed table renders, byte for byte, in every arithmetic and precision; the
// compressed form's cache is .lht version 3; the on-demand table stores what
// it traces within its bound and refuses beyond it without changing a pixel.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <filesystem>

#include "foundation/error.hpp"
#include "foundation/fixed.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "lht/file/lht_file.hpp"
#include "lht/leaf/lookup_stats.hpp"
#include "loader/table_build.hpp"
#include "render/renderer.hpp"
#include "tests/lht/scene_render_support.hpp"
#include "tests/support/hair_scene.hpp"
#include "tests/support/temp_dir.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

std::string hairScene(const std::string& latticeKeys) {
  testing::HairScene scene;
  scene.latticeKeys = latticeKeys;
  return scene.toml();
}

template <typename T>
RgbImage renderScene(const std::string& text, const std::filesystem::path& file, TableSettings tables = {}) {
  return testing::renderLatticeScene<T>(text, file, tables);
}

}  // namespace

TEST_CASE("compressed LHT: a scene renders byte-identical pictures in both forms, every precision and arithmetic") {
  for (const LhtPrecisionInfo& p : kLhtPrecisions) {
    INFO(p.name);
    const std::string keys = fmt::format("precision = \"{}\"\n", p.name);
    const std::string hashed = hairScene(keys + "form = \"hashed\"\n");
    const std::string compressed = hairScene(keys + "form = \"compressed\"\n");
    CHECK(renderScene<double>(hashed, "h.toml").rgb == renderScene<double>(compressed, "c.toml").rgb);
    CHECK(renderScene<float>(hashed, "h.toml").rgb == renderScene<float>(compressed, "c.toml").rgb);
    CHECK(renderScene<Fixed32>(hashed, "h.toml").rgb == renderScene<Fixed32>(compressed, "c.toml").rgb);
  }
  // The settings' form (`--lht-form`) overrides the scene's key.
  TableSettings forced;
  forced.form = LhtForm::Compressed;
  CHECK(renderScene<double>(hairScene(""), "s.toml", forced).rgb == renderScene<double>(hairScene(""), "s.toml").rgb);
}

TEST_CASE("compressed LHT: a scene's cache is written as version 3, reused, and refused for the other form") {
  const lattice::testing::TempDir dir("lht-form-cache");
  const std::string text = hairScene("form = \"compressed\"\ncache = \"hair.lht\"\n");
  const RgbImage first = renderScene<double>(text, dir / "s.toml");
  const LhtFile cached = readLhtFile(dir / "hair.lht");
  CHECK(cached.version == kLhtCompressedVersion);
  CHECK(cached.form() == LhtForm::Compressed);
  CHECK(renderScene<double>(text, dir / "s.toml").rgb == first.rgb);  // read from the cache
  TableSettings hashed;
  hashed.form = LhtForm::Hashed;
  try {
    renderScene<double>(text, dir / "s.toml", hashed);
    FAIL("a compressed cache served a hashed table");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("holds a compressed table but a hashed one was asked for") != std::string::npos);
  }
  try {
    parseSceneWithLattices(hairScene("form = \"zipped\"\n"), "bad.toml");
    FAIL("an unknown form was accepted");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("unknown LHT `form` 'zipped'; use one of hashed, compressed") != std::string::npos);
  }
}

TEST_CASE("on-demand LHT: byte-identical pictures in every arithmetic, with room and with a full cache") {
  const std::string text = hairScene("");
  TableSettings onDemand;
  onDemand.form = LhtForm::OnDemand;
  TableSettings tiny = onDemand;
  tiny.onDemandCacheBytes = 100 * OnDemandTable::kStoredBytes;  // 100 answers: most stores refused
  for (const LhtPrecisionInfo& p : kLhtPrecisions) {
    INFO(p.name);
    TableSettings hashed;
    hashed.precision = p.precision;
    onDemand.precision = tiny.precision = p.precision;
    const RgbImage reference = renderScene<double>(text, "s.toml", hashed);
    CHECK(renderScene<double>(text, "s.toml", onDemand).rgb == reference.rgb);
    CHECK(renderScene<double>(text, "s.toml", tiny).rgb == reference.rgb);
    CHECK(renderScene<float>(text, "s.toml", onDemand).rgb == renderScene<float>(text, "s.toml", hashed).rgb);
    CHECK(renderScene<Fixed32>(text, "s.toml", onDemand).rgb == renderScene<Fixed32>(text, "s.toml", hashed).rgb);
  }
  CHECK(renderScene<double>(hairScene("form = \"on-demand\"\n"), "s.toml").rgb ==
        renderScene<double>(text, "s.toml").rgb);
}

TEST_CASE("on-demand LHT: it stores each pair asked once, exactly the precomputed table's entries referenced") {
  const std::string text = hairScene("");
  TableSettings hashed, onDemand;
  hashed.stats = std::make_shared<LookupStatsBook>();
  onDemand.stats = std::make_shared<LookupStatsBook>();
  onDemand.form = LhtForm::OnDemand;
  renderScene<double>(text, "s.toml", hashed);
  renderScene<double>(text, "s.toml", onDemand);
  const LookupSummary h = hashed.stats->summaries().at(0), d = onDemand.stats->summaries().at(0);
  REQUIRE(d.onDemand);
  CHECK(d.lookups == h.lookups);
  CHECK(d.hits == h.hits);
  CHECK(d.onDemand->hitsStored == h.entriesReferenced);  // the entries the render needed, no more
  CHECK(d.onDemand->hitsStored + d.onDemand->missesStored == h.distinctPairs);
  CHECK(d.onDemand->traced >= h.distinctPairs);  // two threads may both trace a new pair
  CHECK(d.onDemand->traced <= h.distinctPairs + 64);
  CHECK(d.onDemand->refused == 0);
  CHECK(describeLookups(d).find("built on demand: ") != std::string::npos);
  // A bound of 100 answers: no more are stored, the rest are traced each time.
  TableSettings tiny = onDemand;
  tiny.stats = std::make_shared<LookupStatsBook>();
  tiny.onDemandCacheBytes = 100 * OnDemandTable::kStoredBytes;
  renderScene<double>(text, "s.toml", tiny);
  const OnDemandCounts t = *tiny.stats->summaries().at(0).onDemand;
  CHECK(t.mapAnswers <= 100 + 2);  // two threads may each pass the check once
  CHECK(t.mapAnswers == t.hitsStored);  // the misses are in the bitmap, outside the bound
  CHECK(t.missBitmapBytes > 0);
  CHECK(t.refused > 0);
  CHECK(t.traced >= t.hitsStored + t.missesStored + t.refused);  // plus pairs two threads traced at once
  CHECK(t.traced <= t.hitsStored + t.missesStored + t.refused + 64);
}

TEST_CASE("on-demand LHT: it is never rasterized or written to a file") {
  TableRequest request;
  request.shape = "sphere";
  request.settings.form = LhtForm::OnDemand;
  CHECK_THROWS_WITH(buildLatticeTable(request), Catch::Contains("built while rendering, not rasterized"));
  LhtFile file;
  file.table = std::shared_ptr<const OnDemandTable>();  // the form alone is refused, before the table is read
  CHECK_THROWS_WITH(serializeLht(file), Catch::Contains("never written to a .lht file"));
}
