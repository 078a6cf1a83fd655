#pragma once
// A real xterm as a test peer: starts a private X server (Xvfb), runs
// `xterm ARGS` on it, has xterm's shell write a stream file to the terminal
// with the text cursor hidden, then captures the xterm window with `xwd` and
// returns its pixels. What xterm drew can then be compared with one of our
// emulators' pictures (tests/devices/sixel/xterm_test.cpp uses it for
// `xterm -ti vt340`; `xterm -t` shows a Tek 4014 window the same way).
//
// Method and tunables:
//  * The X server is `Xvfb :N -screen 0 WxHx24 -nolisten tcp`, N the first
//    display number from 90 whose lock file (/tmp/.X<N>-lock) is absent and
//    that Xvfb accepts, so parallel tests do not collide. 24-bit TrueColor:
//    every colour xterm allocates is exact.
//  * xterm runs with `-geometry +0+0 -b 0 -bw 0` before the caller's
//    arguments (internal border and window border 0: the window's pixel
//    (0,0) is the terminal's), and `-e sh -c ...`: the shell hides the cursor
//    (CSI ? 25 l), copies the stream to the terminal (or runs the given
//    command there, which draws for itself), then writes xterm's
//    $WINDOWID to a marker file and sleeps until it is killed.
//  * Once the marker exists the window is captured with `xwd -id WINDOWID`
//    every 250 ms until two captures in a row are identical (xterm draws
//    asynchronously), or the time-out passes (then the last one is used).
//  * The xwd file is decoded here: its header is 25 big-endian 32-bit fields
//    (X11/XWDFile.h), then the window name, the colour map (12 bytes an
//    entry), then ZPixmap rows of bytes_per_line; 24/32 bits a pixel,
//    channels found by the header's masks, byte order by its byte_order.
//  * Everything started is killed (SIGTERM, then SIGKILL) and the scratch
//    directory removed when the capture returns, whatever happened.
#include <string>
#include <vector>

#include "foundation/rgb_image.hpp"

namespace lattice::testing {

struct XtermCaptureOptions {
  std::vector<std::string> xtermArguments;  // e.g. {"-ti", "vt340", "-xrm", "XTerm*numColorRegisters: 256"}
  std::string streamFile;                   // copied to the terminal as it is
  // Non-empty: run this program in the terminal instead (argv, no shell),
  // e.g. `lattice term --stream FILE`; the capture starts once it has exited.
  std::vector<std::string> command;
  // Empty: capture xterm's VT window ($WINDOWID). Otherwise the top-level
  // window of this name (xwd -name): "tektronix(Tek)" is `xterm -t`'s Tek 4014
  // window, a window of its own beside the (unmapped) VT one. Either way the
  // window's border is left out (xwd -nobdrs).
  std::string windowName;
  int screenWidth = 1280;                   // the Xvfb screen
  int screenHeight = 1024;
  double timeoutSeconds = 30;  // for the X server, xterm and the drawing to settle
};

struct XtermCapture {
  RgbImage window;         // the xterm window's pixels, top row first (empty when skipped)
  std::string skipReason;  // non-empty: no capture, and why (a peer missing, or it failed)
  bool captured() const { return skipReason.empty(); }
};

// Whether Xvfb, xterm and xwd are on PATH; the missing ones named, or "".
std::string missingXtermPeers();

XtermCapture captureXterm(const XtermCaptureOptions& options);

// Decodes the bytes of an xwd file (24 or 32 bits a pixel, TrueColor).
// Throws lattice::Error(Input) on anything else.
RgbImage decodeXwd(const std::vector<std::uint8_t>& bytes);

}  // namespace lattice::testing
