#include "devices/tek4125/tek4125_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>

#include "foundation/error.hpp"
#include "foundation/name_table.hpp"

namespace lattice::tek4125 {

namespace {

using P = Tek4125Profile;

// The names of a table of named entries (form sets, strategies), kept for
// the program's life as the tables are.
template <class Table>
std::vector<std::string_view> namesIn(const Table& table) {
  std::vector<std::string_view> names;
  for (const auto& entry : table) names.push_back(entryName(entry));
  return names;
}

SettingChoices formSetNames() {
  static const std::vector<std::string_view> names = namesIn(tek4125FormSets());
  return names;
}

SettingChoices strategyNames() {
  static const std::vector<std::string_view> names = namesIn(tek4125Strategies());
  return names;
}

double indexIn(SettingChoices names, std::string_view name) {
  return static_cast<double>(std::find(names.begin(), names.end(), name) - names.begin());
}

constexpr std::string_view kParity[] = {"none", "even", "odd"};  // even and odd: only the bit time matters
constexpr std::string_view kRuBits[] = {"planes", "fit"};

// Rows that the constraints over several keys name.
constexpr auto kPlanes = whole<&P::planes>("planes", {4, 8}, "bit planes, 4 or 8: 4 for a 16-colour unit");
constexpr auto kReserved = whole<&P::reserved>("reserved", {0, 254},
                                                "colour map entries the picture leaves alone, e.g. for dialog-area text");

// Every key of the profile, in describe()'s order (docs/cli.md shows this table).
constexpr Setting<P> kSettings[] = {
    {"profile", SettingKind::Choice, {}, formSetNames,
     "the form set: strict sends only forms an independent program sends; compact is smaller and relies on our "
     "readings",
     [](const P& p) { return indexIn(formSetNames(), p.forms); },
     [](P& p, double i) { p.forms = formSetNames()[static_cast<std::size_t>(i)]; }},
    whole<&P::width>("width", {1, 4096},
                     "visible pixels across, if your terminal's differ from the sibling 4115B's we assume"),
    whole<&P::height>("height", {1, 4096},
                      "visible pixels down, if your terminal's differ from the sibling 4115B's we assume"),
    kPlanes,
    whole<&P::paletteBits>("palette-bits", {3, 24},
        "colour map precision in bits, for a terminal with coarser guns (recorded; the map is sent in percent)"),
    kReserved,
    whole<&P::baud>("baud", {50, 1000000},
                    "the host port's rate: the reported transmit time and --baud's default follow it"),
    whole<&P::dataBits>("data-bits", {7, 8}, "bits a character on the line, for the transmit time"),
    choice<kParity, &P::parity>("parity", "the line's parity, for the transmit time"),
    whole<&P::stopBits>("stop-bits", {1, 2}, "stop bits a character on the line, for the transmit time"),
    onOff<&P::xonXoff>("xon-xoff", "whether the terminal flags DC1/DC3 on the line (recorded; the stream is the same)"),
    {"strategy", SettingKind::Choice, {}, strategyNames,
     "how the driver spends bytes within the form set; shortest tries each way and keeps the smallest stream",
     [](const P& p) { return indexIn(strategyNames(), p.strategy); },
     [](P& p, double i) { p.strategy = strategyNames()[static_cast<std::size_t>(i)]; }},
    onOff<&P::progressive>("progressive",
                           "a blocky picture first, then draft rows, then exact ones: the picture early on a slow line"),
    onOff<&P::xyShort>("xy-short",
        "strict: RR and RH xys leave out an unchanged Hi-Y and Hi-X (one source); fewer bytes, on under a wire budget"),
    choice<kRuBits, &P::ruBitsFit>("ru-bits",
        "compact: RU writes as few bits a pixel as the palette needs (no source); fewer bytes, on under a wire budget"),
};

constexpr SettingsSchema<P> kSchema{"tek4125 profile", kSettings, [] { return P{}; },
                                    [](const P& p) { p.validate(); }};

[[noreturn]] void refuse(const std::string& what) {
  throw Error(ErrorKind::Usage, fmt::format("{}: {}", kSchema.context, what));
}

}  // namespace

const SettingsSchema<Tek4125Profile>& tek4125Settings() { return kSchema; }

void Tek4125Profile::validate() const {
  checkSettings(kSchema, *this);  // each field in its row's range or among its names
  if (planes != 4 && planes != 8) refuse(fmt::format("{0}={1} is not supported; use {0}=4 or {0}=8", kPlanes.key, planes));
  // Two entries at least are left for the picture.
  if (reserved > colorMapSize() - 2)
    refuse(fmt::format("{}={} is out of range; use a value in 0..{} with {}={}", kReserved.key, reserved,
                       colorMapSize() - 2, kPlanes.key, planes));
}

int Tek4125Profile::pixelBitsFor(int colours) const {
  const int needed = colours + reserved;
  if (needed <= 16) return 4;
  if (ruBitsFit && formSet().fittedDepth) return std::min(planes, int(std::bit_width(unsigned(needed - 1))));
  return planes;
}

void applyOverride(Tek4125Profile& profile, std::string_view keyValue) { applySetting(kSchema, profile, keyValue); }

void applyOverrides(Tek4125Profile& profile, const std::vector<std::string>& keyValues) {
  applySettings(kSchema, profile, keyValues);
}

std::string describe(const Tek4125Profile& profile) { return describeSettings(kSchema, profile); }

}  // namespace lattice::tek4125
