#include "io/serial_options.hpp"

#include <fmt/format.h>

#include "io/port_discovery.hpp"
#include "io/serial_port.hpp"
#include "io/serial_settings.hpp"
#include "io/serial_sink.hpp"
#include "foundation/error.hpp"

namespace lattice::io {

void SerialOptions::validate() const {
  if (port.empty()) throw Error(ErrorKind::Usage, "--port: empty; give a device such as /dev/ttyUSB0, or auto");
  checkSettings(serialSettings(), *this);  // the ranges and names, as the flags declare them
}

std::string_view toString(Parity parity) { return nameOfValue(kParityNames, parity, "none"); }

std::string_view toString(FlowControl flow) { return nameOfValue(kFlowControlNames, flow, "none"); }

std::string serialFlags(const SerialOptions& options) {
  // From the line's settings table: the rate always (its default is the
  // command's, not the line's), every other setting where it is not the default.
  const SettingsSchema<SerialOptions>& schema = serialSettings();
  const SerialOptions initial = schema.initial();
  std::string flags = fmt::format("--port {}", options.port);
  for (const Setting<SerialOptions>& row : schema.rows) {
    const std::string value = settingText(row, options);
    if (row.key != "baud" && value == settingText(row, initial)) continue;
    flags += row.kind == SettingKind::Switch ? fmt::format(" --{}", row.key) : fmt::format(" --{} {}", row.key, value);
  }
  return flags;
}

std::unique_ptr<SerialSink> openSerialSink(const SerialOptions& options, const std::filesystem::path& sysfsRoot,
                                           const std::filesystem::path& devRoot) {
  options.validate();
  SerialOptions resolved = options;
  if (resolved.port == "auto") resolved.port = chooseAutoPort(listSerialPorts(sysfsRoot, devRoot));
  return std::make_unique<SerialSink>(SerialPort(resolved.port), resolved);
}

}  // namespace lattice::io
