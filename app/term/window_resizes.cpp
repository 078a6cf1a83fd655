#include "app/term/window_resizes.hpp"

#include <atomic>

namespace lattice::app {
namespace {

std::atomic<bool> gResized{false};
static_assert(std::atomic<bool>::is_always_lock_free);

void recordResize(int) { gResized = true; }

}  // namespace

WindowResizes::WindowResizes() {
  gResized = false;
  struct sigaction action {};
  action.sa_handler = recordResize;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGWINCH, &action, &previous_);
}

WindowResizes::~WindowResizes() { ::sigaction(SIGWINCH, &previous_, nullptr); }

bool WindowResizes::take() { return gResized.exchange(false); }

}  // namespace lattice::app
