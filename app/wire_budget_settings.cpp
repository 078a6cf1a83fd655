#include "app/wire_budget_settings.hpp"

#include "foundation/error.hpp"

namespace lattice::app {

namespace {

using W = WireBudget;

constexpr std::string_view kNoBudget = "none";

// Each help line says why a user would set it.
constexpr lattice::Setting<W> kWireRows[] = {
    orUnset(number<&W::seconds>("wire-seconds", {0.001, 1e9},
                                "send the most accurate picture whose stream takes at most S seconds at --baud "
                                "(default: the profile's rate): palette size, dithering and run merging are searched "
                                "with the real encoder; exits 8 with the smallest stream if nothing fits"),
            kNoBudget),
    orUnset(bytes<&W::bytes>("wire-bytes", "as --wire-seconds, a budget of N bytes (57600, 56K)"), kNoBudget),
    number<&W::quality>("wire-quality", {1.0, 99.0},
                        "with a budget and no --width/--height: the largest picture (up to the device's drawable "
                        "area, at the scene's aspect) whose stream fits with at least this PSNR in dB against the "
                        "truecolour render at that size"),
    onOff<&W::shrink>("wire-shrink", "with a budget: when nothing fits, send a smaller picture (each side x0.8 until "
                                     "it fits) rather than none"),
};

void refuseTwoBudgets(const W& w) {
  if (w.seconds && w.bytes)
    throw Error(ErrorKind::Usage, "--wire-seconds and --wire-bytes are two budgets for one stream; give one (at 8N1 "
                                  "a second is baud / 10 bytes: 60 s at 9600 baud is --wire-bytes 57600)");
}

constexpr SettingsSchema<W> kWireSchema{"wire budget", kWireRows, [] { return W{}; }, refuseTwoBudgets};

}  // namespace

const SettingsSchema<WireBudget>& wireBudgetSettings() { return kWireSchema; }

}  // namespace lattice::app
