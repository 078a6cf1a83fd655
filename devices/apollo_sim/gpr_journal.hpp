#pragma once
// The GPR journal: the Apollo driver's calls as a byte stream, so the
// simulated Apollo goes through a transport and an emulator exactly as the
// Tek terminals do (a file with --stream, the emulator's picture with -o).
//
// Format (ours; Apollo had no such wire form), integers little-endian:
//   "GPR" 0x01                         header, once
//   'A'                                gpr_$acquire_display
//   'R'                                gpr_$release_display
//   'M' start:u16 n:u16 n x (r g b)    gpr_$set_color_map
//   'W' x:u16 y:u16 w:u16 h:u16 w*h x index:u8   gpr_$write_pixels
//   'K' index:u8                       gpr_$clear
// A pixel value is a byte: the simulator's displays have at most 8 planes.
// The decoder replays each whole record on a GprDisplay of the device's
// profile; a record the display would refuse (outside the screen or the
// colour map, drawing before acquire) is counted as malformed and skipped.
#include <cstdint>
#include <memory>
#include <vector>

#include "devices/apollo_sim/apollo_profile.hpp"
#include "devices/apollo_sim/gpr_calls.hpp"
#include "devices/apollo_sim/gpr_display.hpp"
#include "devices/stream_decoder.hpp"
#include "foundation/byte_sink.hpp"

namespace lattice::apollo {

inline constexpr std::uint8_t kGprJournalHeader[4] = {'G', 'P', 'R', 1};

class GprJournalWriter final : public GprCalls {
 public:
  // Writes the header at once. The profile answers inqDispCharacteristics.
  GprJournalWriter(ByteSink& out, const ApolloProfile& profile);
  GprDisplayCharacteristics inqDispCharacteristics() const override;
  void acquireDisplay() override;
  void releaseDisplay() override;
  void setColorMap(int start, std::span<const std::uint32_t> values) override;
  void writePixels(std::span<const std::uint32_t> values, const GprWindow& window) override;
  void clear(std::uint32_t index) override;

 private:
  ByteSink& out_;
  ApolloProfile profile_;
  std::vector<std::uint8_t> record_;
};

class GprJournalDecoder final : public StreamDecoder {
 public:
  explicit GprJournalDecoder(const ApolloProfile& profile);
  void feed(std::span<const std::uint8_t> bytes) override;
  void finish() override;
  const IndexedImage& image() const override;
  const DecodeReport& report() const override { return report_; }

 private:
  // The length of the record at the front of pending_, 0 if more bytes are
  // needed to tell, or -1 if its opcode is unknown.
  long recordLength() const;
  static std::size_t headLength(std::uint8_t op);
  // Whether the record whose head is pending_ lies inside the screen and the
  // colour map.
  bool fits() const;
  void replay(std::span<const std::uint8_t> record);

  ApolloProfile profile_;
  GprDisplay display_;
  std::vector<std::uint8_t> pending_;
  std::size_t headerSeen_ = 0;
  std::size_t skip_ = 0;
  DecodeReport report_;
  mutable IndexedImage snapshot_;
  mutable bool snapshotStale_ = true;
};

}  // namespace lattice::apollo
