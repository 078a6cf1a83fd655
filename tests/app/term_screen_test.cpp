// lattice term's screen is incremental: the bytes arrive in whatever pieces
// the line gives, and after every piece the screen must be what `lattice
// emulate --at` (app/stream_points.hpp) draws for the bytes so far, and at
// the end what `lattice emulate` draws for the recording. Checked with
// random splits of real streams of all three terminals: the project's
// goldens and gnuplot's (when it is installed).
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "app/stream_points.hpp"
#include "app/term/term_screen.hpp"
#include "devices/device_table.hpp"
#include "foundation/system/atomic_file.hpp"
#include "io/png.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

struct Stream {
  const char* device;
  const char* path;  // under tests/golden
};

// Splits `bytes` at `cuts` sorted random offsets.
std::vector<std::size_t> randomCuts(std::size_t size, std::size_t count, std::mt19937& random) {
  std::uniform_int_distribution<std::size_t> at(1, size - 1);
  std::vector<std::size_t> cuts;
  for (std::size_t i = 0; i < count; ++i) cuts.push_back(at(random));
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

}  // namespace

TEST_CASE("term: after every piece the screen is emulate --at of the bytes so far", "[term]") {
  const lattice::testing::TempDir scratch("term-screen");
  std::mt19937 random(20261204);
  for (const Stream s : {Stream{"tek4125", "tek4125/scenes/torus-floor_80x60_8planes.tek"},
                         Stream{"tek4125", "tek4125/scenes/hook_64x64_8planes_compact.tek"},
                         Stream{"tek4027", "tek4027/scenes/hook_64x64.tek"},
                         Stream{"tek4014", "tek4014/rings-96x64.tek"}}) {
    const std::string file = fmt::format("{}/{}", LATTICE_GOLDEN_DIR, s.path);
    const std::vector<std::uint8_t> bytes = lattice::readWholeFile(file);
    REQUIRE(bytes.size() > 64);
    const lattice::devices::Device device = lattice::devices::makeDevice(s.device);
    for (int trial = 0; trial < 2; ++trial) {
      const std::vector<std::size_t> cuts = randomCuts(bytes.size(), 12, random);
      // The term's screen, piece by piece, its screen kept after each piece.
      lattice::MemorySink record;
      lattice::app::TermScreen screen(device, &record);
      std::vector<std::vector<std::uint8_t>> seen;
      std::size_t from = 0;
      std::string points;
      for (const std::size_t cut : cuts) {
        screen.receive(std::span(bytes).subspan(from, cut - from));
        seen.push_back(screen.image().toRgb());
        from = cut;
        points += fmt::format("{}{}", points.empty() ? "" : ",", cut);
      }
      screen.receive(std::span(bytes).subspan(from));
      screen.finish();
      CHECK(record.data() == bytes);
      // emulate --at's own code on the same file, at the same offsets.
      const std::unique_ptr<lattice::StreamDecoder> decoder = device.makeEmulator();
      std::FILE* in = std::fopen(file.c_str(), "rb");
      REQUIRE(in != nullptr);
      const std::string out = scratch / "at.png";
      const std::vector<std::string> written = lattice::app::decodeWithSnapshots(*decoder, in, file, points, out);
      std::fclose(in);
      REQUIRE(written.size() == cuts.size());
      for (std::size_t i = 0; i < cuts.size(); ++i) {
        INFO(s.path << " trial " << trial << " at byte " << cuts[i]);
        const lattice::RgbImage at = lattice::io::readPng(written[i]);
        CHECK(at.rgb == seen[i]);
      }
      INFO(s.path << " trial " << trial << " at the end");
      CHECK(decoder->image().toRgb() == screen.image().toRgb());
    }
  }
}

TEST_CASE("term: the 4027's report requests are answered, one CR each", "[term]") {
  // The strict 4027 stream paces itself with `!REP 00` after each record.
  const std::string file = fmt::format("{}/tek4027/scenes/torus-floor_80x60.tek", LATTICE_GOLDEN_DIR);
  const std::vector<std::uint8_t> bytes = lattice::readWholeFile(file);
  const lattice::devices::Device device = lattice::devices::makeDevice("tek4027");
  REQUIRE(device.replies);
  const std::size_t requests = device.replies->points(bytes).size();
  REQUIRE(requests > 1);
  lattice::app::TermScreen screen(device, nullptr);
  std::string answers;
  // One byte at a time: a request cut anywhere is still found once.
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const std::vector<std::uint8_t> got = screen.receive(std::span(bytes).subspan(i, 1));
    answers.append(got.begin(), got.end());
  }
  CHECK(answers == std::string(requests, '\r'));
  CHECK(screen.answers() == requests);
}

TEST_CASE("term: GIN requests are answered with a key, the cursor's address and CR", "[term]") {
  auto bytesOf = [](const std::string& text) {
    return std::vector<std::uint8_t>(text.begin(), text.end());
  };
  // The 4010's ESC SUB: key, Hi-X, Lo-X, Hi-Y, Lo-Y (x = 512, y = 390), as RAL GKS's GK0TCS reads it.
  lattice::app::TermScreen tek4014(lattice::devices::makeDevice("tek4014"), nullptr);
  CHECK(tek4014.receive(bytesOf("\x1b\x1a")) == bytesOf(" 0 ,&\r"));
  // The 4100's ENABLE-GIN, ESC I E 0 1, cut in two: key, Hi-Y, Extra, Lo-Y, Hi-X, Lo-X
  // (x = 2048, y = 1536), as GK1TCS reads it from a 4107.
  lattice::app::TermScreen tek4125(lattice::devices::makeDevice("tek4125"), nullptr);
  CHECK(tek4125.receive(bytesOf("\x1bIE0")).empty());
  const std::vector<std::uint8_t> report = tek4125.receive(bytesOf("1"));
  REQUIRE(report.size() == 7);
  auto five = [&](std::size_t i) { return report[i] - 32; };
  CHECK(five(4) * 128 + five(5) * 4 + (five(2) & 3) == 2048);
  CHECK(five(1) * 128 + five(3) * 4 + ((five(2) >> 2) & 3) == 1536);
  CHECK(report.back() == '\r');
  // The 4027 has neither.
  lattice::app::TermScreen tek4027(lattice::devices::makeDevice("tek4027"), nullptr);
  CHECK(tek4027.receive(bytesOf("\x1b\x1a\x1bIE01")).empty());
}
