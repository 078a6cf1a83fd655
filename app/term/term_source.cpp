#include "app/term/term_source.hpp"

#include "app/term/port_source.hpp"
#include "app/term/program_source.hpp"
#include "app/term/stream_source.hpp"
#include "foundation/line_timing.hpp"

namespace lattice::app {

std::unique_ptr<TermSource> openTermSource(const TermOptions& options, int profileBaud) {
  switch (options.source) {
    case TermSourceKind::Program:
      return std::make_unique<ProgramSource>(options.program, termNameFor(options.device));
    case TermSourceKind::Port:
      return std::make_unique<PortSource>(options.line);
    case TermSourceKind::Stream: {
      if (options.unpaced) return std::make_unique<StreamSource>(options.stream, 0.0);
      io::SerialOptions line = options.line;
      if (!options.baudGiven && profileBaud > 0) line.baud = profileBaud;
      return std::make_unique<StreamSource>(options.stream, 1.0 / transmitSeconds(1, line.lineFormat()));
    }
  }
  return nullptr;
}

}  // namespace lattice::app
