#pragma once
// Inputs the harnesses pass over because they reach a defect already filed
// (issue 15, part A), so a known slow or huge case does not end every run
// as a timeout. Only the libFuzzer harnesses consult this: the regression
// replay (tests/fuzz/) runs every input it has. Each rule names its defect;
// delete the rule when the defect is fixed.
#include <cstdint>
#include <span>
#include <string_view>

namespace lattice::fuzz {

bool heldBack(std::string_view target, std::span<const std::uint8_t> bytes);

}  // namespace lattice::fuzz
