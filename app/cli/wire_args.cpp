#include "app/cli/wire_args.hpp"

#include <CLI/CLI.hpp>

#include "app/wire_budget_settings.hpp"
#include "foundation/error.hpp"

namespace lattice::app {

void addWireOptions(CLI::App* cmd, WireArgs& args) {
  const SettingsSchema<WireBudget>& schema = wireBudgetSettings();
  addSettingFlags(cmd, schema, schema.initial(), args.given, settableKeys(schema), "Wire budget");
}

void applyWireArgs(const WireArgs& args, const CLI::App& cmd, int baud, RenderJob& job) {
  WireBudget budget = wireBudgetSettings().initial();
  applySettingFlags(wireBudgetSettings(), budget, args.given);
  const bool given = budget.seconds || budget.bytes;
  if (budget.shrink && !given)
    throw Error(ErrorKind::Usage, "--wire-shrink applies to a wire budget: add --wire-seconds S or --wire-bytes N");
  const bool quality = args.given.contains("wire-quality");
  if (quality && !given)
    throw Error(ErrorKind::Usage, "--wire-quality is the floor of a wire budget's size search: add --wire-seconds S "
                                  "or --wire-bytes N");
  if (quality && (cmd.count("--width") > 0 || cmd.count("--height") > 0))
    throw Error(ErrorKind::Usage, "--wire-quality chooses the picture's size, and --width/--height fix it: drop one "
                                  "or the other");
  if (!given) return;
  if (cmd.count("--baud") > 0) budget.baud = baud;
  job.wire = budget;
}

}  // namespace lattice::app
