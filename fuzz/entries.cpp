// The fuzzing entry points (entries.hpp).
//
// Method and tunables:
// * Each entry calls the library function a user's file reaches (not the CLI,
//   whose process start would cost more than the parse) and catches only
//   lattice::Error.
// * Decoders are fed in chunks whose size follows from the input's length
//   (1..8 bytes), so chunk boundaries fall everywhere across a run without
//   spending input bytes on them; a seed is still a valid stream. The next
//   two bits of the length choose the Tek 4125 emulator's unsettled readings
//   (RR from the viewport, RH from the screen: tek4125_profile.hpp); for the
//   sixel emulator the next bit chooses 16 or 256 registers.
// * The .lht entry parses the bytes as they are and again with the trailing
//   FNV-1a checksum recomputed, so mutations also reach the checks behind it
//   (a random flip almost never survives a 64-bit checksum). A table that
//   parses is walked (probeStats, hashed form) and probed through LhtLookup,
//   the leaves' look-up, in either form (version 3 is the compressed one).
// * The fixed .lht bytes also go through readLhtFile, the streamed reader the
//   CLI uses, by way of a scratch file in $TMPDIR named by the process id
//   (one per fuzzing worker). PNG bytes go to readPngBytes, the decoder
//   readPng uses, in memory.
#include "fuzz/entries.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "devices/sixel/sixel_decoder.hpp"
#include "devices/tek4014/tek4014_decoder.hpp"
#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/tek4125/tek4125_decoder.hpp"
#include "io/png.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "lht/file/lht_file.hpp"
#include "lht/leaf/table_lookup.hpp"
#include "foundation/error.hpp"

namespace lattice::fuzz {
namespace {

void decode(StreamDecoder& decoder, std::span<const std::uint8_t> bytes) {
  const std::size_t chunk = 1 + bytes.size() % 8;
  for (std::size_t at = 0; at < bytes.size(); at += chunk)
    decoder.feed(bytes.subspan(at, std::min(chunk, bytes.size() - at)));
  decoder.finish();
}

void probeLht(const lht::LhtFile& file) {
  if (file.form() == lht::LhtForm::Hashed) (void)file.hashed().probeStats();
  const lht::LhtLookup lookup(file);
  const auto& cells = file.box.cells();
  for (int i = 0; i < 64; ++i) {
    const auto coord = [&](int axis, int salt) {
      return static_cast<std::uint8_t>((i * 37 + salt) % (cells[static_cast<std::size_t>(axis)] + 1));
    };
    const lht::LatticePoint in{coord(0, 0), coord(1, 5), coord(2, 11)};
    const lht::LatticePoint out{coord(0, 3), coord(1, 7), coord(2, 13)};
    (void)lookup.find(in, out);
  }
}

// Removed when the process ends normally (libFuzzer's runs end with exit()).
struct ScratchFile {
  std::filesystem::path path;
  ~ScratchFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
};

// Each parse of one input: a located Error is the expected answer.
template <class Read>
void readAndProbe(Read read) {
  try {
    probeLht(read());
  } catch (const Error&) {
  }
}

}  // namespace

void sceneLoader(std::span<const std::uint8_t> bytes) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  try {
    (void)lht::parseSceneWithLattices(text, "fuzz.toml");
  } catch (const Error&) {
  }
}

void lhtReader(std::span<const std::uint8_t> bytes) {
  readAndProbe([&] { return lht::parseLht(bytes, "fuzz.lht"); });
  if (bytes.size() < lht::kLhtHeaderBytes + 8) return;
  std::vector<std::uint8_t> fixed(bytes.begin(), bytes.end());
  const std::size_t end = fixed.size() - 8;
  std::uint64_t sum = fnv1a64(std::span<const std::uint8_t>(fixed).first(end));
  for (std::size_t i = 0; i < 8; ++i, sum >>= 8) fixed[end + i] = static_cast<std::uint8_t>(sum);
  readAndProbe([&] { return lht::parseLht(fixed, "fuzz.lht"); });
  static const ScratchFile scratch{std::filesystem::temp_directory_path() /
                                   ("lattice-fuzz-" + std::to_string(::getpid()) + ".lht")};
  {
    std::ofstream out(scratch.path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(fixed.data()), static_cast<std::streamsize>(fixed.size()));
  }
  readAndProbe([&] { return lht::readLhtFile(scratch.path); });
}

void tek4125Decoder(std::span<const std::uint8_t> bytes) {
  tek4125::Tek4125Readings readings;  // the origin readings vary with the input's length
  readings.rrFromViewport = (bytes.size() / 8) % 2 == 1;
  readings.rhFromScreen = (bytes.size() / 16) % 2 == 1;
  tek4125::Tek4125Decoder decoder(tek4125::Tek4125Profile{}, readings);
  decode(decoder, bytes);
}

void tek4027Decoder(std::span<const std::uint8_t> bytes) {
  tek4027::Tek4027Decoder decoder{tek4027::Tek4027Profile{}};
  decode(decoder, bytes);
}

void tek4014Decoder(std::span<const std::uint8_t> bytes) {
  tek4014::Tek4014Profile profile;
  // Now and then the 12-bit screen (16 times the pixels, so not always).
  if (bytes.size() % 16 == 15) profile.addressBits = 12;
  tek4014::Tek4014Decoder decoder{profile};
  decode(decoder, bytes);
}

void pngReader(std::span<const std::uint8_t> bytes) {
  try {
    (void)io::readPngBytes(bytes, "fuzz.png");
  } catch (const Error&) {
  }
}

void sixelDecoder(std::span<const std::uint8_t> bytes) {
  // The next bit of the length picks 16 or 256 registers, so register wrap-around is reached both ways.
  sixel::SixelProfile profile;
  profile.registers = (bytes.size() / 8) % 2 == 1 ? 256 : 16;
  sixel::SixelDecoder decoder{profile};
  decode(decoder, bytes);
}

const std::vector<Target>& targets() {
  static const std::vector<Target> list{{"scene", sceneLoader},
                                        {"lht", lhtReader},
                                        {"tek4125", tek4125Decoder},
                                        {"tek4027", tek4027Decoder},
                                        {"tek4014", tek4014Decoder},
                                        {"png", pngReader},
                                        {"sixel", sixelDecoder},
                                        {"cli", commandLine}};
  return list;
}

}  // namespace lattice::fuzz
