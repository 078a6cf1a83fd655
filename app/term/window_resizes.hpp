#pragma once
// SIGWINCH while the sixel display is up: the user's terminal window
// changed size, so the picture is fitted again and drawn whole. The handler
// only records the signal (a lock-free atomic store, all a handler may
// safely do); the session's poll() returns EINTR and the loop takes it.
// The action there was comes back when this is destroyed. One at a time.
#include <signal.h>

namespace lattice::app {

class WindowResizes {
 public:
  WindowResizes();
  ~WindowResizes();
  WindowResizes(const WindowResizes&) = delete;
  WindowResizes& operator=(const WindowResizes&) = delete;
  // Whether the window changed size since the last call.
  bool take();

 private:
  struct sigaction previous_ {};
};

}  // namespace lattice::app
