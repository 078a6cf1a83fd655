// docs/scene-format.md's table of object types is the loader's own:
// regenerated here from the node table (loader/node_types.cpp and the
// lattice module's types) and compared with the doc, so a type or key added
// in code and not in the doc fails this test. LATTICE_REGENERATE_GOLDENS=1
// rewrites the doc's table instead (scripts/regenerate-goldens.sh).
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "app/cli/scene_types_doc.hpp"
#include "foundation/system/atomic_file.hpp"
#include "tests/support/golden.hpp"

namespace {

constexpr const char* kBegin =
    "<!-- object types: generated from the scene loader by tests/app/scene_types_doc_test.cpp -->\n";
constexpr const char* kEnd = "<!-- end of the generated object types -->\n";

}  // namespace

TEST_CASE("the object types the loader knows, with their keys") {
  const lattice::app::NodeTypeTable table = lattice::app::nodeTypeTable();
  std::vector<std::string> names;
  for (const auto& entry : table.types) names.push_back(entry.type);
  for (const char* type : {"sphere", "torus", "quartic", "union", "difference", "polyline", "lattice", "lattice_scatter"})
    CHECK(std::find(names.begin(), names.end(), type) != names.end());
  const auto keysOf = [&](const std::string& type) {
    for (const auto& entry : table.types)
      if (entry.type == type) return entry.keys;
    return std::vector<std::string>{};
  };
  CHECK(keysOf("torus") == std::vector<std::string>{"major", "minor"});
  CHECK(keysOf("lattice_scatter") == std::vector<std::string>{"lattice", "count", "radius", "seed"});
  CHECK(std::find(table.common.begin(), table.common.end(), "material") != table.common.end());
  CHECK(std::find(table.common.begin(), table.common.end(), "radius") == table.common.end());
}

TEST_CASE("docs/scene-format.md lists every object type with its keys, as the loader reads them") {
  const std::filesystem::path doc = lattice::testing::sourcePath("docs/scene-format.md");
  std::ifstream in(doc);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::size_t begin = text.find(kBegin);
  const std::size_t end = text.find(kEnd);
  REQUIRE(begin != std::string::npos);
  REQUIRE(end != std::string::npos);
  const std::size_t from = begin + std::string(kBegin).size();
  const std::string generated = lattice::app::nodeTypeMarkdown(lattice::app::nodeTypeTable());
  if (lattice::testing::regeneratingGoldens()) {
    const std::string rewritten = text.substr(0, from) + generated + text.substr(end);
    lattice::writeFileAtomically(doc, std::span(reinterpret_cast<const std::uint8_t*>(rewritten.data()), rewritten.size()));
    WARN("rewrote the object-type table of " << doc.string());
    return;
  }
  INFO("regenerate with LATTICE_REGENERATE_GOLDENS=1 (scripts/regenerate-goldens.sh app) and review the diff");
  CHECK(text.substr(from, end - from) == generated);
}
