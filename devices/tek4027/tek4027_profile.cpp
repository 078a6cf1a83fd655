#include "devices/tek4027/tek4027_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <iterator>

#include "foundation/error.hpp"
#include "foundation/key_value.hpp"
#include "foundation/name_table.hpp"

namespace lattice::tek4027 {

namespace {

using P = Tek4027Profile;

constexpr std::string_view kPresetNames[] = {"strict", "compact"};

// The presets: the only place that says which forms a profile permits.
// Strict: every form has at least one independent source (docs/tek-sources.md).
// Compact: the forms the project used before the audit, shorter, unsourced.
Tek4027Profile strictPreset() { return Tek4027Profile{}; }

Tek4027Profile compactPreset() {
  Tek4027Profile p;
  p.name = kPresetNames[1];
  p.height = 480;
  p.workspaceLines = 34;
  p.graphicsLastRow = 34;
  p.colourForm = Tek4027ColourForm::Map;
  p.relativeVectors = true;
  p.pacing = Tek4027Pacing::None;
  return p;
}

constexpr Tek4027Profile (*kPresets[])() = {strictPreset, compactPreset};  // kPresetNames' order
static_assert(std::size(kPresets) == std::size(kPresetNames));

// A preset's settings, keeping the transport ones: the forms follow the preset.
void applyPreset(P& p, double index) {
  P preset = kPresets[static_cast<std::size_t>(index)]();
  preset.line = p.line;
  preset.terminalCharsPerSecond = p.terminalCharsPerSecond;
  p = preset;
}

double presetIndex(const P& p) {
  const auto* at = std::find(std::begin(kPresetNames), std::end(kPresetNames), p.name);
  return static_cast<double>(at - std::begin(kPresetNames));
}

std::string colourFormText(const P& p) {
  return p.colourForm == Tek4027ColourForm::Mix ? "mix (RGB percent)" : "map (HLS)";
}

constexpr std::string_view kPacingNames[] = {"none", "report", "auto"};  // Tek4027Pacing's order
constexpr std::string_view kParity[] = {"none", "even", "odd"};  // even and odd: only the bit time matters
constexpr std::string_view kSeparatorNames[] = {"space", "comma"};
constexpr char kSeparators[] = {' ', ','};
constexpr std::string_view kTerminatorNames[] = {"cr", "semicolon"};
constexpr char kTerminators[] = {'\r', ';'};
constexpr std::string_view kRveFirstNames[] = {"move", "draw"};
constexpr bool kRveFirstMoves[] = {true, false};

// Every key of the profile, in describe()'s order (docs/cli.md shows this
// table); the reported rows follow from the preset.
constexpr Setting<P> kSettings[] = {
    {"profile", SettingKind::Choice, {}, &choicesIn<kPresetNames>,
     "the preset: strict uses only forms an independent source shows; compact the older, shorter, unsourced ones. "
     "The other keys refine it, whatever their order",
     presetIndex, applyPreset, nullptr, true},
    reported<P>("colour-form", colourFormText),
    reported<P>("relative-vectors", [](const P& p) { return std::string(p.relativeVectors ? "yes" : "no"); }),
    choice<kPacingNames, &P::pacing>(
        "pacing",
        "report requests (!REP 00) after each record so a sender waits for the terminal; auto: once the stream is "
        "longer than one record"),
    whole<&P::recordBytes>("record-bytes", {64, 65536},
        "bytes of a record before its report request, for a terminal with a larger buffer than UGS assumed"),
    reported<P>("workspace-lines", [](const P& p) { return fmt::format("{}", p.workspaceLines); }),
    reported<P>("graphics-rows",
                [](const P& p) { return fmt::format("{}..{}", p.graphicsFirstRow, p.graphicsLastRow); }),
    whole<&P::width>("width", {1, 4096}, "graphics area pixels across, if your terminal's differs"),
    whole<&P::height>("height", {1, 4096}, "graphics area pixels down, if your terminal's differs"),
    whole<&P::line, &LineFormat::baud>("baud", {1}, "the line's rate: the reported transmit time follows it"),
    whole<&P::line, &LineFormat::dataBits>("data-bits", {7, 8}, "bits a character on the line, for the transmit time"),
    choice<kParity, &P::line, &LineFormat::parity>("parity", "the line's parity, for the transmit time"),
    whole<&P::line, &LineFormat::stopBits>("stop-bits", {1, 2},
                                           "stop bits a character on the line, for the transmit time"),
    number<&P::terminalCharsPerSecond>("chars-per-second", {0.001},
                                       "how fast the terminal draws, for the drawing time reported"),
    whole<&P::commandChar>("command-char", {1, 126},
        "the ASCII code that introduces commands, for a terminal set with !COM (punctuation or a control character)"),
    choiceAs<kSeparatorNames, kSeparators, &P::separator>("separator",
        "what goes between arguments; both are legal, the same length"),
    choiceAs<kTerminatorNames, kTerminators, &P::terminator>("terminator", "what ends the last command of a stream"),
    whole<&P::backgroundPot>("background-pot", {0, 7}, "the pot !ERA G clears to, if your terminal's is not C0"),
    whole<&P::maxPointsPerCommand>("max-points", {2, 1024},
                                   "points in one polyline command, for a terminal with a shorter command buffer"),
    choiceAs<kRveFirstNames, kRveFirstMoves, &P::rveFirstMoves>(
        "rve-first",
        "the emulator's reading of !RVE's first pair: a move, or a drawn step (streams from before that reading need "
        "draw)"),
};

constexpr SettingsSchema<P> kSchema{"tek4027 profile", kSettings, strictPreset, [](const P& p) { p.validate(); }};

void require(bool ok, const std::string& what) {
  if (!ok) throw Error(ErrorKind::Usage, fmt::format("{}: {}", kSchema.context, what));
}

}  // namespace

const SettingsSchema<Tek4027Profile>& tek4027Settings() { return kSchema; }

void Tek4027Profile::validate() const {
  checkSettings(kSchema, *this);  // each field in its row's range or among its names
  const auto c = static_cast<unsigned char>(commandChar);
  // The introducer must not be something that can appear inside a command.
  // Letters, digits, signs, separators, terminators and flow control are taken.
  require(c > 0 && c < 127 && !std::isalnum(c) && c != ' ' && c != ',' && c != ';' && c != '\r' &&
              c != '\n' && c != '\t' && c != '-' && c != '+' && c != 0x11 && c != 0x13,
          fmt::format("command character code {} cannot introduce commands; use a punctuation or "
                      "control character such as '!' (33) or US (31)",
                      int(c)));
  require(colors >= 2 && colors <= 8, fmt::format("colour count {} is outside 2..8 paint pots", colors));
  require(backgroundPot < colors, fmt::format("background pot C{} is not one of C0..C{}", backgroundPot, colors - 1));
  require(workspaceLines >= 1 && graphicsFirstRow >= 1 && graphicsFirstRow <= graphicsLastRow &&
              graphicsLastRow <= workspaceLines,
          "graphics rows must lie within the workspace (1 <= first <= last <= workspace lines)");
}

std::vector<std::string> tek4027PresetNames() { return {std::begin(kPresetNames), std::end(kPresetNames)}; }

Tek4027Profile tek4027Preset(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kPresetNames); ++i)
    if (kPresetNames[i] == name) {
      Tek4027Profile p;
      applyPreset(p, static_cast<double>(i));
      return p;
    }
  throw Error(ErrorKind::Usage,
              fmt::format("{}: no preset is called '{}'; use {}", kSchema.context, name, choicesOf(kPresetNames)));
}

void applyOverride(Tek4027Profile& profile, std::string_view keyValue) { applySetting(kSchema, profile, keyValue); }

void applyOverrides(Tek4027Profile& profile, const std::vector<std::string>& keyValues) {
  applySettings(kSchema, profile, keyValues);
}

std::string describe(const Tek4027Profile& profile) { return describeSettings(kSchema, profile); }

}  // namespace lattice::tek4027
