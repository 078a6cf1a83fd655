// The wire budget (app/wire_budget.hpp), `lattice render --wire-bytes`,
// and the points of `lattice emulate --at` (app/stream_points.hpp).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "app/stream_points.hpp"
#include "app/wire_budget.hpp"
#include "devices/device_table.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/error.hpp"
#include "io/png.hpp"
#include "tests/support/example_scene.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

using namespace lattice;

namespace {

RgbImage truecolour(const char* scene, int width, int height) {
  Renderer<double> renderer = testing::makeTestRenderer(testing::loadExampleScene(scene), width, height);
  return renderImage(renderer);
}

std::uint64_t encodedBytes(const devices::Device& device, const IndexedImage& picture) {
  CountingSink counter;
  auto driver = device.makeDriver(counter);
  app::sendPicture(picture, driver->sink());
  return counter.bytesWritten();
}

}  // namespace

TEST_CASE("wire budget: the chosen picture's real stream fits, and a looser budget is no less accurate") {
  const RgbImage reference = truecolour("torus-floor.toml", 96, 72);
  for (const char* device : {"tek4125", "tek4027"}) {
    INFO(device);
    const devices::Device d = devices::makeDevice(device, {});
    double lastPsnr = 0;
    std::uint64_t lastBytes = 0;
    for (std::uint64_t limit : {std::uint64_t(2500), std::uint64_t(5000), std::uint64_t(20000)}) {
      app::WireBudget budget;
      budget.bytes = limit;
      const app::WireSearch s = app::searchWireBudget(reference, d, budget, {}, false);
      INFO(limit << " bytes: " << app::describeWireChoice(s));
      if (!s.choice.fits) {
        CHECK(lastBytes == 0);  // only the tightest may fail, and then no looser one has come yet
        continue;
      }
      CHECK(s.choice.bytes <= limit);
      CHECK(encodedBytes(d, s.picture) == s.choice.bytes);  // the figure is the real encoder's
      CHECK(s.choice.psnr >= lastPsnr);
      CHECK(s.choice.ssim > 0.0);
      CHECK(std::abs(s.choice.seconds - double(s.choice.bytes) * 10.0 / s.baud) < 1e-9);
      lastPsnr = s.choice.psnr;
      lastBytes = s.choice.bytes;
    }
    CHECK(lastBytes > 0);
  }
}

// The coarse-to-fine search ranks settings on a quarter of the rows and
// searches only the best few whole: it may pick another setting than
// searching every one, but must come close, with fewer whole encodings.
TEST_CASE("wire budget: the coarse-to-fine search comes within a quarter dB of searching every setting") {
  const RgbImage reference = truecolour("torus-floor.toml", 96, 72);
  const devices::Device d = devices::makeDevice("tek4125", {});
  for (std::uint64_t limit : {std::uint64_t(3000), std::uint64_t(6000)}) {
    app::WireBudget budget;
    budget.bytes = limit;
    const app::WireSearch fast = app::searchWireBudget(reference, d, budget, {}, false);
    budget.exhaustive = true;
    const app::WireSearch every = app::searchWireBudget(reference, d, budget, {}, false);
    INFO(limit << " bytes: coarse to fine " << app::describeWireChoice(fast) << "; every setting "
                << app::describeWireChoice(every));
    REQUIRE(every.choice.fits);
    REQUIRE(fast.choice.fits);
    CHECK(fast.choice.bytes <= limit);
    CHECK(encodedBytes(d, fast.picture) == fast.choice.bytes);
    CHECK(fast.choice.psnr >= every.choice.psnr - 0.25);
    CHECK(fast.encodings < every.encodings / 2);
    CHECK(every.proxyEncodings == 0);
  }
}

TEST_CASE("wire budget: a device's wire settings are added unless the user gave the key") {
  const devices::Device strict = devices::makeDevice("tek4125", {});
  CHECK(app::wireSettingsToAdd(strict, {}) == std::vector<std::string>{"xy-short=on"});
  CHECK(app::wireSettingsToAdd(strict, {"xy-short=off"}).empty());
  CHECK(app::wireSettingsToAdd(strict, {"planes=4"}) == std::vector<std::string>{"xy-short=on"});
  CHECK(app::wireSettingsToAdd(devices::makeDevice("tek4125", {"profile=compact"}), {}) ==
        std::vector<std::string>{"ru-bits=fit"});
}

TEST_CASE("wire budget on sixel: a byte count below the lossless stream is met, measured by the real encoder") {
  const RgbImage reference = truecolour("fuzzy-sphere-1000.toml", 128, 128);
  const devices::Device d = devices::makeDevice("sixel", {"registers=256"});
  REQUIRE(d.runCost);
  app::WireBudget lossless;
  lossless.bytes = UINT64_MAX;
  const app::WireSearch all = app::searchWireBudget(reference, d, lossless, {}, false);
  REQUIRE(all.choice.fits);
  double lastPsnr = 1e9;
  for (double share : {0.8, 0.5}) {
    app::WireBudget budget;
    budget.bytes = static_cast<std::uint64_t>(double(all.choice.bytes) * share);
    const app::WireSearch s = app::searchWireBudget(reference, d, budget, {}, false);
    INFO(*budget.bytes << " bytes: " << app::describeWireChoice(s));
    REQUIRE(s.choice.fits);
    CHECK(s.choice.bytes <= *budget.bytes);
    CHECK(encodedBytes(d, s.picture) == s.choice.bytes);  // the figure is the real encoder's
    CHECK(s.choice.psnr <= lastPsnr);                     // a tighter budget is no more accurate
    lastPsnr = s.choice.psnr;
    // The terminal shows the picture chosen: our emulator decodes the stream to it.
    MemorySink out;
    auto driver = d.makeDriver(out);
    app::sendPicture(s.picture, driver->sink());
    auto decoder = d.makeEmulator();
    decoder->feed(out.data());
    decoder->finish();
    CHECK(decoder->image().pixels == s.picture.pixels);
  }
  CHECK(lastPsnr < all.choice.psnr);
}

TEST_CASE("wire budget: nothing fits, the smallest stream is reported, and --wire-shrink makes it fit") {
  const RgbImage reference = truecolour("sphere-hole.toml", 64, 64);
  const devices::Device d = devices::makeDevice("tek4125", {});
  app::WireBudget budget;
  budget.seconds = 0.01;  // 38 bytes at 38400 baud: less than the set-up alone (a 2-colour strict stream is 86)
  const app::WireSearch none = app::searchWireBudget(reference, d, budget, {}, false);
  CHECK_FALSE(none.choice.fits);
  CHECK(none.limit == 38);
  CHECK(none.choice.bytes > 38);
  CHECK(encodedBytes(d, none.picture) == none.choice.bytes);
  budget.shrink = true;  // smaller pictures cannot shrink the set-up: still nothing, and no larger a stream
  const app::WireSearch shrunk = app::searchWireBudget(reference, d, budget, {}, false);
  INFO(app::describeWireChoice(shrunk));
  CHECK_FALSE(shrunk.choice.fits);
  CHECK(shrunk.choice.bytes <= none.choice.bytes);
  CHECK(shrunk.picture.width == shrunk.choice.width);
}

TEST_CASE("emulate --at: percentages and byte offsets, in stream order, bad items refused") {
  const auto points = app::parseStreamPoints("50%,100,10%", 1000);
  REQUIRE(points.size() == 3);
  CHECK(points[0].offset == 100);
  CHECK(points[1].offset == 100);
  CHECK(points[2].offset == 500);
  CHECK(points[2].tag == "50pct");
  CHECK(app::parseStreamPoints("5000", 1000)[0].offset == 1000);  // past the end: the whole stream
  for (const char* bad : {"", "x", "110%", "-5", "1.5", "10%,,20%"})
    CHECK_THROWS_AS(app::parseStreamPoints(bad, 1000), Error);
  CHECK(app::pointPngPath("dir/screen.png", "25pct") == "dir/screen-at25pct.png");
}

TEST_CASE("lattice render --wire-bytes and lattice emulate --at, end to end") {
  testing::TempDir dir("wire");
  const std::string scene = testing::sourcePath("scenes/sphere-hole.toml").string();
  const auto stream = dir.path() / "s.tek", picture = dir.path() / "s.png";
  const testing::CommandRun fit = testing::runLattice(
      fmt::format("render {} --device tek4125 --width 64 --height 64 --wire-bytes 4000 --quiet --stream {} -o {}",
                  scene, stream.string(), picture.string()));
  INFO(fit.stderrText);
  CHECK(fit.exitCode == 0);
  CHECK(std::filesystem::file_size(stream) <= 4000);
  CHECK(fit.stderrText.find("wire budget:") != std::string::npos);

  // Exit 8 with the smallest stream: the one failure whose output still lands.
  std::filesystem::remove(stream);
  const testing::CommandRun tight = testing::runLattice(
      fmt::format("render {} --device tek4125 --width 64 --height 64 --wire-bytes 40 --quiet --stream {}", scene,
                  stream.string()));
  INFO(tight.stderrText);
  CHECK(tight.exitCode == 8);
  CHECK(tight.stderrText.find("no setting fits 40 bytes") != std::string::npos);
  CHECK(std::filesystem::file_size(stream) > 40);  // the smallest stream, written

  const auto screen = dir.path() / "e.png";
  const testing::CommandRun at = testing::runLattice(fmt::format(
      "emulate --device tek4125 {} -o {} --at 25%,50%,0", stream.string(), screen.string()));
  INFO(at.stderrText);
  CHECK(at.exitCode == 0);
  for (const char* tag : {"25pct", "50pct", "0B"})
    CHECK(std::filesystem::exists(dir.path() / fmt::format("e-at{}.png", tag)));
  // At byte 0 nothing is drawn yet; the whole stream's screen is e.png.
  const RgbImage empty = io::readPng(dir.path() / "e-at0B.png");
  const RgbImage whole = io::readPng(screen);
  CHECK(empty.rgb != whole.rgb);
}

TEST_CASE("one baud: --baud feeds the budget and the timing line, and two budgets are refused", "[wire]") {
  const testing::TempDir dir("one-baud");
  const std::string scene = fmt::format("{}/scenes/torus-floor.toml", LATTICE_SOURCE_DIR);
  const auto stream = dir.path() / "b.tek";
  const testing::CommandRun run = testing::runLattice(fmt::format(
      "render {} --device tek4125 --width 48 --height 48 --wire-seconds 5 --baud 9600 --quiet --stream {}", scene,
      stream.string()));
  INFO(run.stderrText);
  CHECK(run.exitCode == 0);
  CHECK_THAT(run.stderrText, Catch::Contains("at 9600 baud") && !Catch::Contains("38400"));

  const testing::CommandRun both = testing::runLattice(
      fmt::format("render {} --device tek4125 --wire-seconds 60 --wire-bytes 1000 --stream {}", scene, stream.string()));
  CHECK(both.exitCode == 2);
  CHECK_THAT(both.stderrText, Catch::Contains("two budgets for one stream; give one"));

  const testing::CommandRun clash = testing::runLattice(fmt::format(
      "render {} --device tek4125 --wire-seconds 5 --baud 9600 --set baud=19200 --stream {}", scene, stream.string()));
  CHECK(clash.exitCode == 2);
  CHECK_THAT(clash.stderrText, Catch::Contains("name two line rates"));

  const testing::CommandRun shrunk = testing::runLattice(fmt::format(
      "render {} --device tek4125 --width 64 --height 64 --wire-bytes 40 --wire-shrink --quiet --stream {}", scene,
      stream.string()));
  CHECK(shrunk.exitCode == 8);
  CHECK_THAT(shrunk.stderrText, Catch::Contains("already made the picture as small") && !Catch::Contains("add --wire-shrink"));

  // --wire-quality is the size search's floor: refused where there is no size to search.
  const testing::CommandRun fixed = testing::runLattice(fmt::format(
      "render {} --device tek4125 --width 48 --height 48 --wire-seconds 5 --wire-quality 35 --stream {}", scene,
      stream.string()));
  CHECK(fixed.exitCode == 2);
  CHECK_THAT(fixed.stderrText, Catch::Contains("--wire-quality chooses the picture's size, and --width/--height fix it"));
  const testing::CommandRun alone = testing::runLattice(
      fmt::format("render {} --device tek4125 --wire-quality 35 --stream {}", scene, stream.string()));
  CHECK(alone.exitCode == 2);
  CHECK_THAT(alone.stderrText, Catch::Contains("--wire-quality is the floor of a wire budget's size search"));
}
