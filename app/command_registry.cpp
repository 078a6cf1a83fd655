#include "app/command_registry.hpp"

namespace lattice::app {

std::vector<CommandAdder>& commandAdders() {
  // A function-local static: safe to use from other files' static initializers.
  static std::vector<CommandAdder> adders;
  return adders;
}

}  // namespace lattice::app
