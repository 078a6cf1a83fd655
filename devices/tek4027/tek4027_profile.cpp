#include "devices/tek4027/tek4027_profile.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>

#include "foundation/error.hpp"
#include "foundation/key_value.hpp"
#include "foundation/name_table.hpp"

namespace lattice::tek4027 {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw Error(ErrorKind::Usage, fmt::format("tek4027 profile: {}", what));
}

}  // namespace

void Tek4027Profile::validate() const {
  const auto c = static_cast<unsigned char>(commandChar);
  // The introducer must not be something that can appear inside a command.
  // Letters, digits, signs, separators, terminators and flow control are taken.
  require(c > 0 && c < 127 && !std::isalnum(c) && c != ' ' && c != ',' && c != ';' && c != '\r' &&
              c != '\n' && c != '\t' && c != '-' && c != '+' && c != 0x11 && c != 0x13,
          fmt::format("command character code {} cannot introduce commands; use a punctuation or "
                      "control character such as '!' (33) or US (31)",
                      int(c)));
  require(separator == ' ' || separator == ',', "separator must be a space or a comma");
  require(terminator == '\r' || terminator == ';', "terminator must be CR or ';'");
  require(width >= 1 && width <= 4096 && height >= 1 && height <= 4096,
          fmt::format("resolution {}x{} is outside 1..4096 in each direction", width, height));
  require(colors >= 2 && colors <= 8, fmt::format("colour count {} is outside 2..8 paint pots", colors));
  require(backgroundPot >= 0 && backgroundPot < colors,
          fmt::format("background pot C{} is not one of C0..C{}", backgroundPot, colors - 1));
  require(line.baud > 0, "baud must be positive");
  require(terminalCharsPerSecond > 0, "terminal characters per second must be positive");
  require(maxPointsPerCommand >= 2 && maxPointsPerCommand <= 1024,
          fmt::format("points per command {} is outside 2..1024", maxPointsPerCommand));
  require(recordBytes >= 64 && recordBytes <= 65536,
          fmt::format("record bytes {} is outside 64..65536", recordBytes));
  require(workspaceLines >= 1 && graphicsFirstRow >= 1 && graphicsFirstRow <= graphicsLastRow &&
              graphicsLastRow <= workspaceLines,
          "graphics rows must lie within the workspace (1 <= first <= last <= workspace lines)");
}

namespace {
constexpr std::string_view kContext = "tek4027 profile";
constexpr std::string_view kKeys =
    "profile, width, height, baud, data-bits, parity, stop-bits, chars-per-second, command-char, separator, "
    "terminator, background-pot, max-points, pacing, record-bytes, rve-first";

// The presets: the only place that says which forms a profile permits.
// Strict: every form has at least one independent source (docs/tek-sources.md).
// Compact: the forms the project used before the audit, shorter, unsourced.
Tek4027Profile strictPreset() { return Tek4027Profile{}; }

Tek4027Profile compactPreset() {
  Tek4027Profile p;
  p.name = "compact";
  p.height = 480;
  p.workspaceLines = 34;
  p.graphicsLastRow = 34;
  p.colourForm = Tek4027ColourForm::Map;
  p.relativeVectors = true;
  p.pacing = Tek4027Pacing::None;
  return p;
}

constexpr std::array<EnumName<Tek4027Pacing>, 3> kPacingNames = {{
    {Tek4027Pacing::None, "none"},
    {Tek4027Pacing::Report, "report"},
    {Tek4027Pacing::Auto, "auto"},
}};

std::string_view pacingName(Tek4027Pacing pacing) { return nameOfValue(kPacingNames, pacing, "?"); }
}  // namespace

std::vector<std::string> tek4027PresetNames() { return {"strict", "compact"}; }

Tek4027Profile tek4027Preset(std::string_view name) {
  if (name == "strict") return strictPreset();
  if (name == "compact") return compactPreset();
  throw Error(ErrorKind::Usage, fmt::format("{}: profile={} must be strict or compact", kContext, name));
}

void applyOverride(Tek4027Profile& profile, std::string_view keyValue) {
  Tek4027Profile p = profile;  // a rejected override leaves the profile as it was
  const KeyValue kv = splitKeyValue(kContext, keyValue, kKeys);
  const std::string_view key = kv.key, value = kv.value;
  if (key == "profile") {
    Tek4027Profile preset = tek4027Preset(value);
    // Transport settings stay as the caller set them; the forms follow the preset.
    preset.line = p.line;
    preset.terminalCharsPerSecond = p.terminalCharsPerSecond;
    p = preset;
  } else if (key == "width") p.width = parseIntSetting(kContext, kv);
  else if (key == "height") p.height = parseIntSetting(kContext, kv);
  else if (key == "baud") p.line.baud = parseIntSetting(kContext, kv);
  else if (key == "data-bits") p.line.dataBits = parseIntSetting(kContext, kv);
  else if (key == "stop-bits") p.line.stopBits = parseIntSetting(kContext, kv);
  else if (key == "chars-per-second") p.terminalCharsPerSecond = parseNumberSetting(kContext, kv);
  else if (key == "command-char") p.commandChar = static_cast<char>(parseIntSetting(kContext, kv));
  else if (key == "background-pot") p.backgroundPot = parseIntSetting(kContext, kv);
  else if (key == "max-points") p.maxPointsPerCommand = parseIntSetting(kContext, kv);
  else if (key == "record-bytes") p.recordBytes = parseIntSetting(kContext, kv);
  else if (key == "rve-first") {
    if (value == "move") p.rveFirstMoves = true;
    else if (value == "draw") p.rveFirstMoves = false;
    else throw Error(ErrorKind::Usage, fmt::format("{}: rve-first={} must be move or draw", kContext, value));
  } else if (key == "pacing") {
    const auto pacing = valueNamed(kPacingNames, value);
    if (!pacing)
      throw Error(ErrorKind::Usage,
                  fmt::format("{}: pacing={} must be {}", kContext, value, choicesOf(kPacingNames)));
    p.pacing = *pacing;
  }
  else if (key == "parity") {
    if (value == "none") p.line.parity = false;
    else if (value == "even" || value == "odd") p.line.parity = true;  // only its bit time matters here
    else throw Error(ErrorKind::Usage, fmt::format("{}: parity={} must be none, even or odd", kContext, value));
  } else if (key == "separator") {
    if (value == "space") p.separator = ' ';
    else if (value == "comma") p.separator = ',';
    else throw Error(ErrorKind::Usage, fmt::format("{}: separator={} must be space or comma", kContext, value));
  } else if (key == "terminator") {
    if (value == "cr") p.terminator = '\r';
    else if (value == "semicolon") p.terminator = ';';
    else throw Error(ErrorKind::Usage, fmt::format("{}: terminator={} must be cr or semicolon", kContext, value));
  } else {
    unknownSetting(kContext, kv, kKeys);
  }
  if (p.line.dataBits != 7 && p.line.dataBits != 8)
    throw Error(ErrorKind::Usage, fmt::format("{}: data-bits={} must be 7 or 8", kContext, p.line.dataBits));
  if (p.line.stopBits != 1 && p.line.stopBits != 2)
    throw Error(ErrorKind::Usage, fmt::format("{}: stop-bits={} must be 1 or 2", kContext, p.line.stopBits));
  p.validate();
  profile = p;
}

void applyOverrides(Tek4027Profile& profile, const std::vector<std::string>& keyValues) {
  // The preset first, wherever it was typed: the other keys refine it.
  for (const auto& kv : keyValues)
    if (kv.rfind("profile=", 0) == 0) applyOverride(profile, kv);
  for (const auto& kv : keyValues)
    if (kv.rfind("profile=", 0) != 0) applyOverride(profile, kv);
}

std::string describe(const Tek4027Profile& p) {
  return fmt::format(
      "profile={}\ncolour-form={}\nrelative-vectors={}\npacing={}\nrecord-bytes={}\nworkspace-lines={}\n"
      "graphics-rows={}..{}\n",
      p.name, p.colourForm == Tek4027ColourForm::Mix ? "mix (RGB percent)" : "map (HLS)",
      p.relativeVectors ? "yes" : "no", pacingName(p.pacing), p.recordBytes, p.workspaceLines, p.graphicsFirstRow,
      p.graphicsLastRow) + fmt::format(
      "width={}\nheight={}\nbaud={}\ndata-bits={}\nparity={}\nstop-bits={}\nchars-per-second={}\n"
      "command-char={}\nseparator={}\nterminator={}\nbackground-pot={}\nmax-points={}\nrve-first={}\n",
      p.width, p.height, p.line.baud, p.line.dataBits, p.line.parity ? "even" : "none", p.line.stopBits,
      p.terminalCharsPerSecond, static_cast<int>(p.commandChar), p.separator == ' ' ? "space" : "comma",
      p.terminator == ';' ? "semicolon" : "cr", p.backgroundPot, p.maxPointsPerCommand,
      p.rveFirstMoves ? "move" : "draw");
}

}  // namespace lattice::tek4027
