#pragma once
// The 4027 emulator: a byte-at-a-time parser of the terminal's command
// language feeding a framebuffer of paint-pot numbers (0..7), with the pots'
// colours (HLS -> RGB) as the colour map. Chunking never matters: all state
// lives in the object between feed() calls.
//
// Language as implemented (docs/tek4027.md has the full account):
//   <cmdchar> NAME [args] <end>   NAME = letters, case-insensitive, first 3 significant
//   args separated by spaces, commas (runs collapse) or LF;
//   <end> = CR, ';' or the next command character.
// Bytes outside commands are alphanumeric text for the terminal's workspace:
// whitespace is ignored, other text is counted once per run as malformed
// (this emulator only shows graphics), once per word.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "devices/stream_decoder.hpp"
#include "devices/tek4027/tek4027_hls.hpp"
#include "devices/tek4027/tek4027_profile.hpp"

namespace lattice::tek4027 {

class Tek4027Decoder final : public StreamDecoder {
 public:
  // Limits that keep hostile input bounded (memory and time per byte).
  static constexpr std::size_t kMaxNameLength = 16;
  static constexpr std::size_t kMaxTokenLength = 24;
  static constexpr std::size_t kMaxArguments = 4096;
  static constexpr std::size_t kMaxUnknownNames = 64;
  // Numbers beyond this magnitude are malformed; the beam is clamped to
  // +-kMaxCoordinate so relative vectors cannot overflow.
  static constexpr long kMaxNumber = 32767;
  static constexpr long kMaxCoordinate = 65535;

  explicit Tek4027Decoder(Tek4027Profile profile = {});

  void feed(std::span<const std::uint8_t> bytes) override;
  void finish() override;
  const IndexedImage& image() const override { return image_; }
  const DecodeReport& report() const override { return report_; }

  // State a test may inspect.
  char commandChar() const { return commandChar_; }
  int currentPot() const { return pot_; }
  long beamX() const { return beamX_; }
  long beamY() const { return beamY_; }
  const std::array<Hls, 8>& potHls() const { return hls_; }
  int lineStyle() const { return lineStyle_; }

 private:
  enum class State { Text, Name, Args };

  void consume(std::uint8_t byte);
  void startCommand();
  void endToken();
  void endCommand();
  bool execute();  // false: malformed (nothing changed)

  bool vectors(bool relative);
  bool color();
  bool mapPots(bool rgb);
  bool erase();
  bool setCommandChar();
  bool checkOnly(std::size_t minArgs, std::size_t maxArgs, bool letterFlags);

  bool number(std::size_t index, long& out) const;
  bool potNumber(std::size_t index, int& out) const;
  void setPot(int pot, Hls hls);
  void setPotRgb(int pot, Rgb8 rgb);
  void plot(long x, long y);
  void line(long x0, long y0, long x1, long y1);

  Tek4027Profile profile_;
  IndexedImage image_;
  DecodeReport report_;

  char commandChar_;
  State state_ = State::Text;
  bool inStrayText_ = false;
  std::string name_;
  bool nameOverflow_ = false;
  std::string token_;
  bool tokenOverflow_ = false;
  std::vector<std::string> args_;
  bool argsOverflow_ = false;

  std::array<Hls, 8> hls_{};
  int pot_ = 1;
  long beamX_ = 0, beamY_ = 0;
  int lineStyle_ = 1;
};

}  // namespace lattice::tek4027
