#pragma once
// "Did you mean": the known name nearest to a mistyped one.
//
// Method and tunables: the optimal-string-alignment distance (Levenshtein
// plus the swap of two neighbours, Damerau 1964), so `rendr`, `--widht` and
// `--colours` each cost one or two edits. A name is suggested when it is at
// most max(1, |typed| / 3) edits away (a third of the letters: close enough
// to be a typo, far enough that unrelated short names are not offered), or
// when the typed word is a prefix of exactly one name (`--thre`). Ties go to
// the first name in the list, so callers list names in their help order.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lattice::app {

std::size_t editDistance(std::string_view a, std::string_view b);
std::optional<std::string> nearestName(std::string_view typed, const std::vector<std::string>& names);

}  // namespace lattice::app
