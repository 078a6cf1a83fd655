#include "app/terminal_stream.hpp"

#include <unistd.h>

#include "devices/device_table.hpp"

namespace lattice::app {

void streamToTerminalByDefault(RenderJob& job) {
  if (job.device.empty() || !job.stream.empty() || !job.picture.empty() || job.port) return;
  if (!devices::makeDevice(job.device, job.settings).showsOnTerminal || ::isatty(STDOUT_FILENO) != 1) return;
  job.stream.assign(1, '-');  // (not = "-": GCC 12 -Wrestrict false positive at -O3)
  job.quiet = true;
  job.pipeline.progress = false;
}

}  // namespace lattice::app
