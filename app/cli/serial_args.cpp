#include "app/cli/serial_args.hpp"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app/cli/setting_flags.hpp"
#include "io/serial_settings.hpp"

namespace lattice::app {

void addSerialOptions(CLI::App* cmd, io::SerialOptions& options, bool portRequired, const std::string& baudDefault) {
  constexpr const char* kGroup = "Serial line";
  auto* port = cmd->add_option("--port", options.port,
                               "Serial port: a device such as /dev/ttyUSB0, or `auto` for the only USB-serial "
                               "adapter (`lattice ports` lists them)")
                   ->group(kGroup);
  if (portRequired) port->required();
  const std::vector<std::string_view> keys = settableKeys(io::serialSettings());
  addSettingFlagsInto(cmd, io::serialSettings(), options, keys, kGroup);
  if (!baudDefault.empty()) cmd->get_option("--baud")->default_str(baudDefault);
}

}  // namespace lattice::app
