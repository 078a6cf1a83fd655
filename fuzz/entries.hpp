#pragma once
// The fuzzing entry points: one function per surface that reads outside
// bytes. The libFuzzer harnesses (fuzz/*_fuzzer.cpp) and the ordinary test
// suite's replay of fuzz/regressions/ (tests/fuzz/) call the same functions,
// so an input that once failed is checked by every build, g++ included.
//
// Contract: bytes in; lattice::Error is the expected answer to bad input and
// is swallowed; anything else (another exception, a crash, a sanitizer
// report) escapes and is a finding.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace lattice::fuzz {

using Entry = void (*)(std::span<const std::uint8_t> bytes);

void sceneLoader(std::span<const std::uint8_t> bytes);  // TOML text -> SceneDesc, lattice types included
void lhtReader(std::span<const std::uint8_t> bytes);    // .lht bytes -> LhtFile, as read and checksum-fixed
void tek4125Decoder(std::span<const std::uint8_t> bytes);  // Tek 4100 command stream -> screen
void tek4027Decoder(std::span<const std::uint8_t> bytes);  // Tek 4027 command stream -> screen
void tek4014Decoder(std::span<const std::uint8_t> bytes);  // Tek 4010/4014 graphics stream -> screen
void pngReader(std::span<const std::uint8_t> bytes);       // PNG file -> RgbImage
void sixelDecoder(std::span<const std::uint8_t> bytes);    // DEC sixel stream -> screen
void commandLine(std::span<const std::uint8_t> bytes);     // argv from the command table -> `lattice`, in-process

struct Target {
  std::string_view name;  // the harness is fuzz_<name>; regressions live in fuzz/regressions/<name>/
  Entry entry;
};
const std::vector<Target>& targets();

}  // namespace lattice::fuzz
