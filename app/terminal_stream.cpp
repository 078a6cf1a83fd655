#include "app/terminal_stream.hpp"

#include <unistd.h>

#include "devices/device_table.hpp"

namespace lattice::app {

void streamToTerminalByDefault(RenderJob& job) {
  if (job.output.device.empty() || !job.output.stream.empty() || !job.output.picture.empty() || job.output.port) return;
  if (!devices::makeDevice(job.output.device, job.output.settings).showsOnTerminal || ::isatty(STDOUT_FILENO) != 1) return;
  job.output.stream.assign(1, '-');  // (not = "-": GCC 12 -Wrestrict false positive at -O3)
  job.quiet = true;
  job.pipeline.progress = false;
}

}  // namespace lattice::app
