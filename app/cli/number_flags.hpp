#pragma once
// Numeric flags are read by the one number parser (foundation/number_text.hpp):
// `numberIn(range)` is the check a numeric flag declares its range with, and
// guardNumbers() gives every numeric option of the command tree that declared
// none the range of its C++ type, so NaN, infinities and overflow are refused
// before CLI11 converts the text (CLI11's own Range lets NaN through: every
// comparison with NaN is false). Errors read
// "lattice: error: render: --width: 'nan' is not a finite number; give a whole number from 1 to 16384".
#include <string>
#include <vector>

#include "app/cli/cli_forward.hpp"
#include "foundation/number_text.hpp"

namespace CLI {
class Validator;
}  // namespace CLI

namespace lattice::app {

// A CLI11 check that refuses what parseNumberText refuses.
CLI::Validator numberIn(NumberRange range);
// The same, taking `word` too (a setting's unset word: "none").
CLI::Validator numberIn(NumberRange range, const std::string& word);

// Every numeric option below `root` without a numberIn check gets one for its type.
void guardNumbers(CLI::App& root);

// "render --threads"-style names of the numeric options below `root` that
// declare no range of their own (tests keep this list empty).
std::vector<std::string> numericOptionsWithoutRange(CLI::App& root);

}  // namespace lattice::app
