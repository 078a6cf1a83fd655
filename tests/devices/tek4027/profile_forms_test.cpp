// Which command forms each profile lets the driver send. Strict (the
// default) may only use forms an independent source shows
// (docs/tek-sources.md, "Tek 4027"); compact keeps the older, unsourced ones.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/tek4027/tek4027_driver.hpp"
#include "foundation/byte_sink.hpp"
#include "tests/devices/tek4027/drive_frame.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::tek4027;
using namespace lattice::tek4027::test;

namespace {

std::string drive(const IndexedImage& img, const Tek4027Profile& profile) { return test::driveFrame(img, profile); }

// The three-letter keys of every command in a stream.
std::set<std::string> commandNames(const std::string& text) {
  std::set<std::string> names;
  for (std::size_t at = text.find('!'); at != std::string::npos; at = text.find('!', at + 1))
    names.insert(text.substr(at + 1, 3));
  return names;
}

}  // namespace

TEST_CASE("the strict profile sends only sourced forms") {
  const Tek4027Profile strict;
  CHECK(strict.name == "strict");
  CHECK(strict.workspaceLines <= 33);  // UGS allows at most 33 graphics lines
  CHECK(strict.width == 640);
  CHECK(strict.height == 350);  // UGS: 640x350 at its default 26 lines
  const std::string text = drive(testing::ringsImage(200, 150), strict);
  const std::set<std::string> sourced = {"WOR", "GRA", "MIX", "ERA", "COL", "VEC", "RVE", "REP"};
  for (const std::string& name : commandNames(text)) {
    INFO(name);
    CHECK(sourced.count(name) == 1);
  }
  CHECK(text.rfind("!WOR 26!GRA 1 26!MIX C", 0) == 0);
  CHECK(text.find("!MAP") == std::string::npos);
  CHECK(text.find("!REP 00\r") != std::string::npos);  // long enough to be paced
}

TEST_CASE("the compact profile keeps the older forms") {
  const Tek4027Profile compact = tek4027Preset("compact");
  CHECK(compact.height == 480);
  const std::string text = drive(testing::ringsImage(200, 150), compact);
  CHECK(text.rfind("!WOR 34!GRA 1 34!MAP C", 0) == 0);
  CHECK(text.find("!MIX") == std::string::npos);
  CHECK(text.find("!REP") == std::string::npos);
}

TEST_CASE("!MIX sends whole percent per gun, and the emulator shows them exactly") {
  IndexedImage img(4, 1, 2);
  img.colormap = {{0, 0, 0}, {255, 128, 1}};
  img.at(2, 0) = 1;
  const std::string text = drive(img, Tek4027Profile{});
  CHECK(text.find("!MIX C1 100 50 0") != std::string::npos);
  Tek4027Decoder d;
  d.feed(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  d.finish();
  CHECK(d.report().malformed == 0);
  CHECK(d.image().colormap[1] == Rgb8{255, levelFromPercent(50), 0});
  CHECK(levelFromPercent(50) == 128);
  for (int level = 0; level < 256; ++level)  // the percent round trip moves a gun by at most 1.3 levels
    CHECK(std::abs(levelFromPercent(percentFromLevel(static_cast<std::uint8_t>(level))) - level) <= 2);
}

TEST_CASE("profile= picks a preset wherever it is typed, other keys refine it") {
  Tek4027Profile p;
  applyOverrides(p, {"height=300", "profile=compact"});
  CHECK(p.name == "compact");
  CHECK(p.colourForm == Tek4027ColourForm::Map);
  CHECK(p.height == 300);
  applyOverrides(p, {"profile=strict", "pacing=none"});
  CHECK(p.name == "strict");
  CHECK(p.colourForm == Tek4027ColourForm::Mix);
  CHECK(p.pacing == Tek4027Pacing::None);
  CHECK_THROWS_AS(applyOverride(p, "profile=loose"), lattice::Error);
  CHECK_THROWS_AS(applyOverride(p, "pacing=sometimes"), lattice::Error);
  CHECK_THROWS_AS(applyOverride(p, "record-bytes=10"), lattice::Error);
  CHECK(p.name == "strict");  // a refused override changes nothing
  CHECK(describe(p).find("profile=strict\n") == 0);
}
