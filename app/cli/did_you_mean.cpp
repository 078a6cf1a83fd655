#include "app/cli/did_you_mean.hpp"

#include <algorithm>

namespace lattice::app {

std::size_t editDistance(std::string_view a, std::string_view b) {
  // Three rows of the dynamic-programming table: the swap looks two back.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitute});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    before.swap(previous);
    previous.swap(current);
  }
  return previous[b.size()];
}

std::optional<std::string> nearestName(std::string_view typed, const std::vector<std::string>& names) {
  const std::size_t allowed = std::max<std::size_t>(1, typed.size() / 3);
  std::optional<std::string> best;
  std::size_t bestDistance = allowed + 1;
  for (const std::string& name : names) {
    const std::size_t d = editDistance(typed, name);
    if (d < bestDistance) {
      bestDistance = d;
      best = name;
    }
  }
  if (best) return best;
  std::vector<std::string> extending;
  for (const std::string& name : names)
    if (typed.size() >= 3 && name.size() > typed.size() && name.compare(0, typed.size(), typed) == 0)
      extending.push_back(name);
  if (extending.size() == 1) return extending.front();
  return std::nullopt;
}

}  // namespace lattice::app
