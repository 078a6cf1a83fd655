// docs/cli.md's table of each device's --set keys is the device's settings
// table (foundation/settings_schema.hpp), and its tables of the quantizer's,
// the lattice tables', the wire budget's and the serial line's flags are
// their schemas' (quantize/pipeline_settings.hpp, loader/table_settings.hpp,
// app/wire_budget_settings.hpp, io/serial_settings.hpp), regenerated here and
// compared with the doc's text between each table's markers, so a key
// added, renamed or re-ranged in code and not in the doc fails this test. On
// a difference it prints the block to paste; LATTICE_REGENERATE_GOLDENS=1
// rewrites the doc instead (scripts/regenerate-goldens.sh app).
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "app/wire_budget_settings.hpp"
#include "devices/device_table.hpp"
#include "foundation/system/atomic_file.hpp"
#include "io/serial_settings.hpp"
#include "loader/table_settings.hpp"
#include "quantize/pipeline_settings.hpp"
#include "tests/support/golden.hpp"

namespace {

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace

TEST_CASE("docs/cli.md lists each device's --set keys and each stage's flags as their schemas declare them") {
  const std::filesystem::path doc = lattice::testing::sourcePath("docs/cli.md");
  std::string text = readText(doc);
  REQUIRE_FALSE(text.empty());
  bool rewritten = false;
  std::vector<std::pair<std::string, std::vector<lattice::SettingInfo>>> tables;
  for (const lattice::devices::DeviceEntry& entry : lattice::devices::deviceTable())
    tables.emplace_back(entry.name, entry.settings());
  tables.emplace_back("quantizer", lattice::settingInfos(lattice::quantize::pipelineSettings()));
  tables.emplace_back("lattice-tables", lattice::settingInfos(lattice::lht::tableSettings()));
  tables.emplace_back("wire", lattice::settingInfos(lattice::app::wireBudgetSettings()));
  tables.emplace_back("serial", lattice::settingInfos(lattice::io::serialSettings()));
  for (const auto& [name, infos] : tables) {
    const std::string begin = fmt::format("<!-- settings:{} begin -->\n", name);
    const std::string end = fmt::format("<!-- settings:{} end -->\n", name);
    const std::string generated = lattice::settingsMarkdown(infos);
    const std::size_t from = text.find(begin);
    const std::size_t to = text.find(end);
    INFO(name << ": " << begin << "..." << end);
    REQUIRE(from != std::string::npos);
    REQUIRE(to != std::string::npos);
    REQUIRE(from < to);
    const std::size_t inside = from + begin.size();
    if (lattice::testing::regeneratingGoldens()) {
      text = text.substr(0, inside) + generated + text.substr(to);
      rewritten = true;
      continue;
    }
    const bool same = text.substr(inside, to - inside) == generated;
    // Unwrapped, to paste: Catch's own report folds long lines.
    if (!same) std::cout << "docs/cli.md needs, for " << name << ":\n" << begin << generated << end;
    CHECK(same);
  }
  if (rewritten) {
    lattice::writeFileAtomically(doc, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
    WARN("rewrote the settings tables of " << doc.string());
  }
}
