#pragma once
// What the user's terminal can show: whether it draws sixels, how many
// colour registers a picture may use, and its size in text cells and pixels.
//
// Method: the terminal is asked (the answers come back on its input, which
// is in raw mode by then) and its window size read:
//  * DA1, CSI c: a VT340 or xterm -ti vt340 lists attribute 4 ("sixel
//    graphics") in its answer CSI ? 63;1;2;4;6;9;15;22 c (xterm's
//    ctlseqs, "Send Device Attributes"). Every VT100-class terminal answers
//    DA1, so it is asked last and its answer ends the wait.
//  * XTSMGRAPHICS, CSI ? 1;1;0 S: the number of colour registers, answered
//    CSI ? 1;0;N S (xterm's ctlseqs). A terminal that does not know it says
//    nothing, and the profile's 16 (a VT340's) stands.
//  * TIOCGWINSZ for rows, columns and the pixel size; where the pixel size
//    is 0 (some terminals leave it), XTWINOPS CSI 14 t, answered
//    CSI 4;height;width t.
// A terminal that answers nothing within kAskSeconds shows no sixels.
#include <string>

namespace lattice::app {

struct HostGraphics {
  bool sixel = false;
  int registers = 16;
  int columns = 80, rows = 24;
  int pixelWidth = 0, pixelHeight = 0;  // the text area; 0: unknown
  std::string why;                      // when !sixel: what the terminal said (or did not)
  int cellWidth() const { return columns > 0 && pixelWidth > 0 ? pixelWidth / columns : 10; }
  int cellHeight() const { return rows > 0 && pixelHeight > 0 ? pixelHeight / rows : 20; }
};

inline constexpr double kAskSeconds = 1.0;

// Reads the answers in `text` (what the terminal sent back) into `host`;
// true once the DA1 answer has been seen. A pure function: the tests give it
// real terminals' answers.
bool readHostAnswers(const std::string& text, HostGraphics& host);

// Asks the terminal on `in` / `out` (raw mode) and reads its window size.
HostGraphics askHost(int in, int out);

// Reads the window's size again (after SIGWINCH) into `host`; where the
// terminal gives no pixel size, the text cells keep the size they had.
// False when the size cannot be read.
bool readWindowSize(int fd, HostGraphics& host);

}  // namespace lattice::app
