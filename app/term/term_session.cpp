#include "app/term/term_session.hpp"

#include <fmt/format.h>
#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/term/dialog_lines.hpp"
#include "app/term/host_graphics.hpp"
#include "app/term/host_terminal.hpp"
#include "app/term/term_keys.hpp"
#include "app/term/term_screen.hpp"
#include "app/term/term_source.hpp"
#include "app/term/term_write.hpp"
#include "app/term/window_resizes.hpp"
#include "devices/device_table.hpp"
#include "foundation/system/atomic_file.hpp"
#include "io/png.hpp"
#include "io/stream_sender.hpp"

namespace lattice::app {
namespace {

using Clock = std::chrono::steady_clock;

void writeText(int fd, const std::string& text) {
  writeToPeer(fd, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

// The first PREFIX-N.png that does not exist yet.
std::string nextPngPath(const std::string& prefix) {
  for (int n = 1;; ++n) {
    std::string path = fmt::format("{}-{}.png", prefix, n);
    if (!std::filesystem::exists(path)) return path;
  }
}

ViewGeometry geometryOf(const HostGraphics& host) {
  return {host.columns, host.rows, host.cellWidth(), host.cellHeight(), host.registers};
}

// The display in the user's terminal, when it shows sixels.
class Display {
 public:
  Display(const HostGraphics& host, const devices::Device& device)
      : host_(host),
        view_(geometryOf(host), device.width, device.height),
        title_(device.title) {
    writeText(1, "\x1b[?25l\x1b[2J");  // hide the text cursor, clear
  }
  ~Display() {
    // The status line cleared and the cursor back on there, below the
    // picture: what is said next (and the shell's prompt) goes on that line
    // and scrolls the picture up only then.
    writeText(1, fmt::format("\x1b[{};1H\x1b[2K\x1b[?25h", host_.rows));
  }
  void draw(const TermScreen& screen) {
    writeText(1, view_.update(screen.image()));
    // The dialog area's last lines, on the rows between the picture and the status line.
    const std::vector<std::string> lines =
        lastDialogLines(screen.dialogText(), kTextRowsBelow - 1, static_cast<std::size_t>(host_.columns));
    if (lines != dialog_ && host_.rows > kTextRowsBelow) {  // a window of a few rows has no room for them
      for (int i = 0; i < kTextRowsBelow - 1; ++i)
        writeText(1, fmt::format("\x1b[{};1H\x1b[2K{}", host_.rows - (kTextRowsBelow - 1) + i,
                                 static_cast<std::size_t>(i) < lines.size() ? lines[static_cast<std::size_t>(i)] : ""));
      dialog_ = lines;
    }
    writeText(1, fmt::format("\x1b[{};1H\x1b[2K{} | {} bytes | Ctrl-] quits, Ctrl-\\ writes a PNG", host_.rows,
                             title_, screen.bytes()));
  }
  // The window changed size: the picture is fitted again and drawn whole at the next draw.
  void resize() {
    if (!readWindowSize(1, host_)) return;
    view_ = SixelView(geometryOf(host_), view_.screenWidth(), view_.screenHeight());
    dialog_.clear();
    writeText(1, "\x1b[2J");
  }
  const SixelView& view() const { return view_; }
  SixelView& view() { return view_; }

 private:
  HostGraphics host_;
  SixelView view_;
  std::vector<std::string> dialog_;  // the dialog lines shown
  std::string title_;
};

}  // namespace

TermResult runTerm(const TermOptions& options, const TermSay& say) {
  const devices::Device device = devices::makeDevice(options.device, options.settings);
  std::optional<AtomicFile> record;
  if (!options.record.empty()) record.emplace(options.record);
  TermScreen screen(device, record ? &*record : nullptr);
  // Opened first: a program that cannot run, a port that cannot be opened or
  // a stream that cannot be read is an error before the host terminal is touched.
  std::unique_ptr<TermSource> source = openTermSource(options, device.line ? device.line->baud : 0);
  TermResult result;

  io::SendSignals signals;  // SIGINT, SIGTERM, SIGHUP end the session in order
  HostTerminal host(0);
  std::optional<Display> display;
  std::optional<WindowResizes> resizes;
  if (options.display == TermOptions::Display::Auto) {
    if (!host.isTerminal() || !::isatty(1)) {
      say("no display: standard input and output are not both a terminal (--snapshot keeps the screen)");
    } else {
      const HostGraphics graphics = askHost(0, 1);
      if (graphics.sixel) {
        display.emplace(graphics, device);
        resizes.emplace();
      } else
        say(fmt::format("no display: {}; xterm -ti vt340, mlterm, foot or WezTerm show sixels "
                        "(--snapshot keeps the screen)", graphics.why));
    }
  }

  const auto interval = std::chrono::duration<double>(1.0 / options.refreshPerSecond);
  Clock::time_point lastRefresh = Clock::now() - std::chrono::hours(1);
  bool dirty = false;
  bool budgetSaid = false;
  auto refresh = [&](AtomicFile::Landing landing) {
    if (display) display->draw(screen);
    if (!options.snapshot.empty()) io::writePng(options.snapshot, screen.image(), 0, landing);
    ++result.refreshes;
    lastRefresh = Clock::now();
    dirty = false;
    if (screen.report().overBudget && !budgetSaid) {
      say("the stream asks for more drawing than the emulator's budget (docs/limits.md): nothing more is drawn");
      budgetSaid = true;
    }
  };

  bool keysOpen = true;
  bool quit = false;
  std::vector<std::uint8_t> incoming;
  for (;;) {
    int timeout = source->timeoutMs();
    if (dirty) {
      const auto due = lastRefresh + std::chrono::duration_cast<Clock::duration>(interval) - Clock::now();
      const int dueMs = std::max(0, static_cast<int>(std::chrono::ceil<std::chrono::milliseconds>(due).count()));
      timeout = timeout < 0 ? dueMs : std::min(timeout, dueMs);
    }
    pollfd fds[2];
    nfds_t count = 0;
    if (source->fd() >= 0) fds[count++] = pollfd{source->fd(), POLLIN, 0};
    const nfds_t keysAt = count;
    if (keysOpen) fds[count++] = pollfd{0, POLLIN, 0};
    ::poll(fds, count, timeout);
    if (signals.caught() != 0) {
      result.endReason = fmt::format("stopped by {}", io::signalName(signals.caught()));
      source->stop();
      break;
    }
    if (resizes && resizes->take()) {
      display->resize();
      dirty = true;  // redrawn whole even if no byte comes
    }
    if (keysOpen && (fds[keysAt].revents & (POLLIN | POLLHUP | POLLERR))) {
      std::uint8_t keys[4096];
      const ssize_t n = ::read(0, keys, sizeof keys);
      if (n <= 0) {
        keysOpen = false;  // the keyboard is gone (a file or pipe at its end): the source goes on
      } else {
        const KeyActions actions = readKeys(std::span(keys, static_cast<std::size_t>(n)));
        source->write(actions.forward);
        for (int i = 0; i < actions.pngs; ++i) {
          const std::string path = nextPngPath(options.pngPrefix);
          io::writePng(path, screen.image(), 0, AtomicFile::Landing::Now);
          result.pngs.push_back(path);
        }
        quit = actions.quit;
      }
    }
    if (quit) {
      result.endReason = "the quit key";
      source->stop();
      break;
    }
    incoming.clear();
    const bool more = source->read(incoming);
    if (!incoming.empty()) {
      const std::vector<std::uint8_t> answers = screen.receive(incoming);
      if (!answers.empty()) source->write(answers);
      dirty = true;
    }
    if (!more) {
      result.endReason = source->endReason();
      break;
    }
    if (dirty && Clock::now() - lastRefresh >= interval) refresh(AtomicFile::Landing::Now);
  }
  screen.finish();
  refresh(AtomicFile::Landing::Now);
  if (display) {
    result.displayed = true;
    result.view = display->view().stats();
    result.fullFrameBytes = display->view().fullFrame(screen.image()).size();
  }
  display.reset();
  if (record) record->close();
  result.bytes = screen.bytes();
  result.answers = screen.answers();
  result.unknownCommands = screen.report().unknownCommands;
  result.malformed = screen.report().malformed;
  return result;
}

}  // namespace lattice::app
