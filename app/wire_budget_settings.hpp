#pragma once
// A wire budget's settings, each declared once: the budget (seconds at the
// line's rate, or bytes), the size search's quality floor and whether a
// picture may shrink when nothing fits. `lattice render`'s flags, their
// help and docs/cli.md's table are read from this table; a budget given
// twice (seconds and bytes) is refused here. The budget's baud is the serial
// line's (io/serial_settings.hpp), not a row of its own.
#include "app/wire_budget.hpp"
#include "foundation/settings_schema.hpp"

namespace lattice::app {

const SettingsSchema<WireBudget>& wireBudgetSettings();

}  // namespace lattice::app
