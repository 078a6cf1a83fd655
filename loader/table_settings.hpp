#pragma once
// The lattice tables' settings a user gives for one run, each declared once:
// the entry precision, the table form and the leaves' look-up of every
// lattice (each left unset, "scene", means each lattice's own, as its
// [[lattices]] entry says), and the on-demand form's memory bound. The
// flags of `lattice render`, their help and docs/cli.md's table are read
// from this table (app/cli/setting_flags.hpp,
// tests/devices/shared/settings_doc_test.cpp). The run's other table
// settings (threads, a memory budget's hooks, the look-up counter) are the
// job's, not the user's, and have no row.
#include "foundation/settings_schema.hpp"
#include "loader/lattice_definition.hpp"

namespace lattice::lht {

const SettingsSchema<TableSettings>& tableSettings();

}  // namespace lattice::lht
