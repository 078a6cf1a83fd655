// The form list (lht/table/table_forms.hpp): every form of LhtTable is
// reached through it - its name, its code in files, building by
// rasterizing, writing and reading a .lht file, and the look-up - so a new
// form joins all of them by being listed.
#include <catch2/catch.hpp>

#include <cstring>

#include "foundation/error.hpp"
#include "lht/file/lht_file.hpp"
#include "lht/leaf/table_lookup.hpp"
#include "lht/raster/lattice_object.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

// Every form the list can build by rasterizing, from the same hits.
std::vector<LhtFile> everyRasterizedForm(const LatticeBox& box, const RasterResult& raster) {
  std::vector<LhtFile> files;
  for (std::size_t code = 0; code < kLhtFormCount; ++code) {
    withForm(
        static_cast<LhtForm>(code),
        [&](auto i) {
          using Form = FormAt<decltype(i)::value>;
          if constexpr (RasterizedForm<Form>) {
            LhtFile lht;
            lht.box = box;
            lht.pairs = raster.stats.pairs;
            lht.hits = raster.stats.hits;
            lht.objectHash = 7;
            lht.table.emplace<decltype(i)::value>(Form::fromHits(raster.hits, box.cells(), LhtPrecision::Thesis));
            files.push_back(std::move(lht));
          }
        },
        [] { FAIL("a code below kLhtFormCount has no form"); });
  }
  return files;
}

}  // namespace

TEST_CASE("table forms: every name and code of the list goes both ways") {
  REQUIRE(kLhtFormCount == 3);
  for (std::size_t code = 0; code < kLhtFormCount; ++code) {
    const auto form = static_cast<LhtForm>(code);
    CHECK(lhtFormFromName(lhtFormName(form)) == form);
    CHECK(lhtFormChoices().find(std::string(lhtFormName(form))) != std::string::npos);
  }
  CHECK(lhtFormName(LhtForm::Compressed) == "compressed");
  // Files hold the forms that say so, and only those.
  CHECK(lhtFormFromCode(0) == LhtForm::Hashed);
  CHECK(lhtFormFromCode(1) == LhtForm::Compressed);
  CHECK_FALSE(lhtFormFromCode(2).has_value());  // on-demand: built while rendering
  CHECK_FALSE(lhtFormFromCode(3).has_value());
  CHECK(lhtFiledFormCodes() == "0 hashed, 1 compressed");
  CHECK(lhtFiledFormNames() == "hashed or compressed");
  CHECK_FALSE(lhtFormFromName("chained").has_value());
}

TEST_CASE("table forms: every rasterized form survives its .lht file and answers every pair as the others do") {
  const LatticeObject sphere = sphereObject(1.0);
  const LatticeBox box(sphere.bounds, 0.25, 1.0);
  RasterOptions options;
  options.progress = false;
  const RasterResult raster = rasterize(box, *sphere.primitive, options);
  REQUIRE(raster.hits.size() > 100);
  const std::vector<LhtFile> files = everyRasterizedForm(box, raster);
  REQUIRE(files.size() == 2);  // hashed and compressed; on-demand is never rasterized
  const BoundaryIndex index(box.cells());
  const std::size_t payload = payloadBytes(LhtPrecision::Thesis);
  for (const LhtFile& built : files) {
    INFO("form " << lhtFormName(built.form()));
    CHECK(built.entryCount() == raster.hits.size());
    const LhtFile read = parseLht(serializeLht(built), "forms.lht", 7, LhtPrecision::Thesis, built.form());
    CHECK(read.form() == built.form());
    CHECK(read.entryCount() == built.entryCount());
    CHECK(serializeLht(read) == serializeLht(built));
    // The look-up through the list gives the first form's answers, pair by pair.
    const LhtLookup reference(files.front()), lookup(read);
    std::uint64_t hits = 0, mismatches = 0;
    for (std::uint32_t i = 0; i < index.count(); ++i)
      for (std::uint32_t o = 0; o < index.count(); ++o) {
        const std::uint8_t* x = reference.payload(index.pointAt(i), index.pointAt(o));
        const std::uint8_t* y = lookup.payload(index.pointAt(i), index.pointAt(o));
        if (bool(x) != bool(y) || (x && std::memcmp(x, y, payload) != 0)) ++mismatches;
        if (y) ++hits;
      }
    CHECK(mismatches == 0);
    CHECK(hits == raster.hits.size());
  }
}

TEST_CASE("table forms: a form files do not hold is refused by name when written") {
  LhtFile lht;
  lht.table.emplace<static_cast<std::size_t>(LhtForm::OnDemand)>(nullptr);
  try {
    (void)serializeLht(lht);
    FAIL("an on-demand table was written");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("an on-demand table is built while rendering") != std::string::npos);
    CHECK(std::string(e.what()).find("hashed or compressed") != std::string::npos);
  }
}
