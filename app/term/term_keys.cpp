#include "app/term/term_keys.hpp"

namespace lattice::app {

KeyActions readKeys(std::span<const std::uint8_t> keys) {
  KeyActions actions;
  for (std::uint8_t key : keys) {
    if (key == kQuitKey) {
      actions.quit = true;
      break;
    }
    if (key == kPngKey)
      ++actions.pngs;
    else
      actions.forward.push_back(key);
  }
  return actions;
}

}  // namespace lattice::app
