#include "devices/tek4027/tek4027_decoder.hpp"

#include "devices/canvas.hpp"
#include "devices/work_budget.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iterator>
#include <string_view>

namespace lattice::tek4027 {

namespace {

// Power-up pots (assumed; the manual's table was not available): black
// background, white, then the six primaries and secondaries. Tek HLS.
constexpr std::array<Hls, 8> kPowerUpPots{{
    {0, 0, 0},       // C0 black
    {0, 100, 0},     // C1 white
    {120, 50, 100},  // C2 red
    {240, 50, 100},  // C3 green
    {0, 50, 100},    // C4 blue
    {300, 50, 100},  // C5 cyan
    {60, 50, 100},   // C6 magenta
    {180, 50, 100},  // C7 yellow
}};

bool isSeparator(std::uint8_t b) { return b == ' ' || b == ',' || b == '\t' || b == '\n'; }
bool isTerminator(std::uint8_t b) { return b == '\r' || b == ';'; }
// Bytes that may sit between commands without being text: whitespace,
// terminators, NUL/DEL padding and XON/XOFF flow control.
bool isFiller(std::uint8_t b) {
  return isSeparator(b) || isTerminator(b) || b == 0 || b == 0x7F || b == 0x11 || b == 0x13;
}

// Commands for the text workspace, the keyboard and the line that the
// ncurses terminfo entries (tek4024/4025/4027, tek4025a, tek4025-cr) and a
// real program (a TIG font tool) send: known, any arguments, nothing drawn.
bool isTextCommand(const std::string& key) {
  static constexpr std::string_view kText[] = {"ATT", "BAC", "BUF", "DCH", "DEL", "DIS", "DLI", "DOW", "DUP",
                                               "ECH", "ENA", "EOL", "FOR", "ICH", "ILI", "INK", "JUM", "LEA",
                                               "LEF", "PAD", "RIG", "RSS", "RUP", "SNO", "STO", "UP"};
  return std::find(std::begin(kText), std::end(kText), key) != std::end(kText);
}

}  // namespace

Tek4027Decoder::Tek4027Decoder(Tek4027Profile profile)
    : profile_(profile), image_(profile.width, profile.height, 8), commandChar_(profile.commandChar) {
  profile_.validate();
  hls_ = kPowerUpPots;
  for (int p = 0; p < 8; ++p) image_.colormap[static_cast<std::size_t>(p)] = tekHlsToRgb(hls_[static_cast<std::size_t>(p)]);
  std::fill(image_.pixels.begin(), image_.pixels.end(), static_cast<PaletteIndex>(profile_.backgroundPot));
}

void Tek4027Decoder::feed(std::span<const std::uint8_t> bytes) {
  report_.bytes += bytes.size();
  for (std::uint8_t b : bytes) consume(b);
}

void Tek4027Decoder::finish() {
  if (state_ != State::Text) {
    // Cut off by the end of the stream: the terminal would still be waiting.
    ++report_.malformed;
    state_ = State::Text;
  }
  inStrayText_ = false;
}

void Tek4027Decoder::startCommand() {
  state_ = State::Name;
  inStrayText_ = false;
  name_.clear();
  nameOverflow_ = false;
  token_.clear();
  tokenOverflow_ = false;
  args_.clear();
  argsOverflow_ = false;
}

void Tek4027Decoder::consume(std::uint8_t b) {
  // The command character is recognised wherever it appears: it ends the
  // command in progress (if any) and starts the next one.
  if (b == static_cast<std::uint8_t>(commandChar_)) {
    if (state_ != State::Text) endCommand();
    startCommand();
    return;
  }
  switch (state_) {
    case State::Text:
      if (isFiller(b)) {
        inStrayText_ = false;
      } else if (!inStrayText_) {
        ++report_.malformed;  // text for the alpha workspace, not shown here
        inStrayText_ = true;
      }
      return;
    case State::Name:
      if (std::isalpha(b)) {
        if (name_.size() < kMaxNameLength)
          name_.push_back(static_cast<char>(std::toupper(b)));
        else
          nameOverflow_ = true;
        return;
      }
      state_ = State::Args;
      [[fallthrough]];
    case State::Args:
      if (isTerminator(b)) {
        endCommand();
        state_ = State::Text;
      } else if (b == 0 || b == 0x7F || b == 0x11 || b == 0x13) {
        // Padding and flow control are not part of the command.
      } else if (b < 0x20 && !isSeparator(b)) {
        // No argument holds a control character: it ends the command, and
        // after `!COM n` it may be the new command character (terminfo's
        // tek4025a reset string sends `!com 29` then GS at once).
        endCommand();
        if (b == static_cast<std::uint8_t>(commandChar_)) startCommand();
      } else if (isSeparator(b)) {
        endToken();
      } else if (token_.size() < kMaxTokenLength) {
        token_.push_back(static_cast<char>(b));
      } else {
        tokenOverflow_ = true;
      }
      return;
  }
}

void Tek4027Decoder::endToken() {
  if (token_.empty()) return;
  if (args_.size() < kMaxArguments)
    args_.push_back(token_);
  else
    argsOverflow_ = true;
  token_.clear();
}

void Tek4027Decoder::endCommand() {
  endToken();
  state_ = State::Text;
  if (name_.empty() || nameOverflow_ || tokenOverflow_ || argsOverflow_) {
    ++report_.malformed;
    return;
  }
  if (execute()) ++report_.commands;  // failures are counted inside execute()
}

bool Tek4027Decoder::execute() {
  const std::string key = name_.substr(0, 3);
  bool ok;
  if (key == "VEC")
    ok = vectors(false);
  else if (key == "RVE")
    ok = vectors(true);
  else if (key == "COL")
    ok = color();
  else if (key == "MAP")
    ok = mapPots(false);
  else if (key == "MIX")
    ok = mapPots(true);
  else if (key == "ERA")
    ok = erase();
  else if (key == "COM")
    ok = setCommandChar();
  else if (key == "GRA")
    ok = checkOnly(2, 4, false);  // graphics region in text rows: the framebuffer is fixed
  else if (key == "WOR")
    ok = checkOnly(1, 2, true);  // workspace size [H]: text layout only
  else if (key == "MON")
    ok = checkOnly(1, 3, true);  // monitor size [H] [K] (`!MON 12 H K` in a real program): text layout only
  else if (key == "REP")
    ok = checkOnly(0, 1, false);  // report request (UGS paces with `!REP 00`): the emulator has no one to answer
  else if (key == "CLE")
    ok = args_.empty();  // clears tab stops: nothing graphic
  else if (key == "LIN") {
    long style = 0;
    ok = args_.size() == 1 && number(0, style) && style >= 0 && style <= 255;
    if (ok) lineStyle_ = static_cast<int>(style);  // recorded; vectors are drawn solid
  } else if (isTextCommand(key)) {
    ok = true;
  } else {
    ++report_.unknownCommands;
    if (report_.unknownByName.size() < kMaxUnknownNames || report_.unknownByName.count(name_) != 0)
      ++report_.unknownByName[name_];
    else
      ++report_.unknownByName["(other)"];
    return false;
  }
  if (!ok) ++report_.malformed;
  return ok;
}

bool Tek4027Decoder::number(std::size_t index, long& out) const {
  if (index >= args_.size()) return false;
  const std::string& t = args_[index];
  std::size_t i = 0;
  bool negative = false;
  if (t[0] == '-' || t[0] == '+') {
    negative = t[0] == '-';
    i = 1;
  }
  if (i == t.size()) return false;
  long value = 0;
  for (; i < t.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(t[i]))) return false;
    value = value * 10 + (t[i] - '0');
    if (value > kMaxNumber) return false;  // also stops overflow: at most 24 digits read
  }
  out = negative ? -value : value;
  return true;
}

bool Tek4027Decoder::potNumber(std::size_t index, int& out) const {
  if (index >= args_.size()) return false;
  const std::string& t = args_[index];
  if (t.size() != 2 || (t[0] != 'C' && t[0] != 'c') || !std::isdigit(static_cast<unsigned char>(t[1])))
    return false;
  out = t[1] - '0';
  return out < profile_.colors;
}

bool Tek4027Decoder::checkOnly(std::size_t minArgs, std::size_t maxArgs, bool letterFlags) {
  if (args_.size() < minArgs || args_.size() > maxArgs) return false;
  long v = 0;
  for (std::size_t i = 0; i < args_.size(); ++i) {
    const std::string& t = args_[i];
    // Workspace and monitor take single-letter flags, alone or after the
    // count: terminfo's `mon h`, `wor 33h`, a real program's `!MON 12 H K`.
    if (letterFlags && std::isalpha(static_cast<unsigned char>(t.back()))) {
      if (t.size() == 1) continue;
      const std::string count = t.substr(0, t.size() - 1);
      if (count.find_first_not_of("0123456789") == std::string::npos) continue;
      return false;
    }
    if (!number(i, v) || v < 0) return false;
  }
  return true;
}

bool Tek4027Decoder::vectors(bool relative) {
  if (args_.empty() || args_.size() % 2 != 0) return false;
  std::vector<long> values(args_.size());
  for (std::size_t i = 0; i < args_.size(); ++i)
    if (!number(i, values[i])) return false;
  long x = beamX_, y = beamY_;
  std::size_t first = 0;
  if (!relative) {
    // A lone point lights its pixel: a zero-length vector.
    x = values[0];
    y = values[1];
    if (values.size() == 2) plot(x, y);
    first = 2;
  } else if (profile_.rveFirstMoves) {  // the first pair moves the beam (profile rve-first)
    x = std::clamp(x + values[0], -kMaxCoordinate, kMaxCoordinate);
    y = std::clamp(y + values[1], -kMaxCoordinate, kMaxCoordinate);
    first = 2;
  }
  for (std::size_t i = first; i < values.size(); i += 2) {
    long nx = relative ? x + values[i] : values[i];
    long ny = relative ? y + values[i + 1] : values[i + 1];
    nx = std::clamp(nx, -kMaxCoordinate, kMaxCoordinate);
    ny = std::clamp(ny, -kMaxCoordinate, kMaxCoordinate);
    line(x, y, nx, ny);
    x = nx;
    y = ny;
  }
  beamX_ = x;
  beamY_ = y;
  return true;
}

bool Tek4027Decoder::color() {
  int pot = 0;
  if (args_.size() != 1 || !potNumber(0, pot)) return false;
  pot_ = pot;
  return true;
}

bool Tek4027Decoder::mapPots(bool rgb) {
  // One or more groups "Cn a b c"; validated as a whole before any pot changes.
  if (args_.empty() || args_.size() % 4 != 0) return false;
  struct Change {
    int pot;
    long a, b, c;
  };
  std::vector<Change> changes;
  for (std::size_t i = 0; i < args_.size(); i += 4) {
    Change ch{};
    if (!potNumber(i, ch.pot) || !number(i + 1, ch.a) || !number(i + 2, ch.b) || !number(i + 3, ch.c))
      return false;
    if (rgb && (ch.a < 0 || ch.a > 100)) return false;
    if (ch.b < 0 || ch.b > 100 || ch.c < 0 || ch.c > 100) return false;
    changes.push_back(ch);
  }
  for (const Change& ch : changes) {
    if (rgb) {
      auto percent = [](long v) { return static_cast<std::uint8_t>((v * 255 + 50) / 100); };
      setPotRgb(ch.pot, {percent(ch.a), percent(ch.b), percent(ch.c)});
    } else {
      long hue = ch.a % 360;
      if (hue < 0) hue += 360;
      setPot(ch.pot, {static_cast<int>(hue), static_cast<int>(ch.b), static_cast<int>(ch.c)});
    }
  }
  return true;
}

void Tek4027Decoder::setPot(int pot, Hls hls) {
  hls_[static_cast<std::size_t>(pot)] = hls;
  image_.colormap[static_cast<std::size_t>(pot)] = tekHlsToRgb(hls);
}

void Tek4027Decoder::setPotRgb(int pot, Rgb8 rgb) {
  hls_[static_cast<std::size_t>(pot)] = rgbToTekHls(rgb);
  image_.colormap[static_cast<std::size_t>(pot)] = rgb;  // !MIX is exact: no HLS rounding
}

bool Tek4027Decoder::erase() {
  if (args_.size() > 1) return false;
  if (args_.empty()) return true;  // the workspace text: nothing graphic
  const std::string& what = args_[0];
  if (what == "G" || what == "g") {
    if (chargePixelWork(report_, image_.pixels.size()))
      std::fill(image_.pixels.begin(), image_.pixels.end(), static_cast<PaletteIndex>(profile_.backgroundPot));
    return true;
  }
  return what == "W" || what == "w" || what == "M" || what == "m";
}

bool Tek4027Decoder::setCommandChar() {
  long code = 0;
  if (args_.size() != 1 || !number(0, code)) return false;
  if (code <= 0 || code >= 127) return false;
  Tek4027Profile candidate = profile_;
  candidate.commandChar = static_cast<char>(code);
  try {
    candidate.validate();
  } catch (const std::exception&) {
    return false;  // a character that could not introduce commands unambiguously
  }
  commandChar_ = candidate.commandChar;
  return true;
}

void Tek4027Decoder::plot(long x, long y) {
  // Terminal y grows upwards from the bottom row.
  const long row = static_cast<long>(profile_.height) - 1 - y;
  if (x < 0 || x >= profile_.width || row < 0 || row >= profile_.height) return;
  image_.at(static_cast<int>(x), static_cast<int>(row)) = static_cast<PaletteIndex>(pot_);
}

void Tek4027Decoder::line(long x0, long y0, long x1, long y1) {
  if (!chargePixelWork(report_, devices::lineWork(image_, x0, y0, x1, y1))) return;
  devices::drawLine(image_, x0, y0, x1, y1, static_cast<PaletteIndex>(pot_));
}

}  // namespace lattice::tek4027
