#pragma once
// Which command forms a 4125 stream may use: the one place that decides it.
// A named form set ("strict", "compact") is plain data; the driver asks it
// and never tests a profile's name. docs/tek-sources.md gives, for every
// form, the independent programs that send it and so the confidence.
//
//   strict   only forms at least one independent driver sends, and nothing
//            that depends on an unsettled reading: surfaces defined (RD,
//            as many planes as RU then writes bits a pixel),
//            the background set (TB) and painted, a pixel viewport that
//            covers the whole screen (so RH and RR coordinates mean the
//            same under either reading of RR), full five-byte xy, one
//            colour map entry per TG, DEL sent as ESC ? after KI1 (as
//            RAL-CGM does), run-length writes (RL) of at most 12 bytes of
//            run codes each, as the RAL GKS 4200 driver sends them.
//            RP only at 4 bits a pixel; a picture of more than 16 colours
//            goes as RL at 8 bits, as the GKS driver's 8-plane workstations.
//   compact  the forms the driver sent before `strict` (viewport around the
//            picture, short xy forms, one TG for the whole palette, raw DEL,
//            background left to the ESC FF clear, RP at 8 bits) plus RL
//            without the GKS driver's limits, and RP and RL following each
//            other without a new RH: the cost of strictness, measured.
#include <string>
#include <string_view>
#include <vector>

namespace lattice::tek4125 {

struct Tek4125Forms {
  std::string name;
  bool defineSurfaces = false;      // ESC RD 1 <bits>: surface 1 with as many planes as RU writes bits
  bool explicitBackground = false;  // TB with colour 0, then one RR over the picture in index 0
  bool screenViewport = false;      // RS covers the screen, not just the picture
  bool fullXy = false;              // every xy in five bytes (no registers relied on)
  bool escapeDel = false;           // KI1 first, then each DEL in a parameter goes as ESC ?
  int colourEntriesPerTg = 0;       // colour map entries per TG command; 0 = all in one
  bool runLength = false;           // RL run-length writes may be used
  int runCodeBytesPerRl = 0;        // most run-code bytes in one RL; 0 = no limit
  int maxRunCode = 65535;           // largest RL run code (length * 2^bits + index)
  bool beamContinues = false;       // an RP or RL may follow the other kind without a new RH
  bool rasterOnlyAtFourBits = false;  // RP only at 4 bits a pixel (the one depth a source packs)
  // With fullXy: an xy of RR or RH after another RR or RH xy leaves out Hi-Y
  // and Hi-X when unchanged, always sending Extra, Lo-Y and Lo-X (OpenVnmrJ's
  // tek_coord0, the terminal keeping its registers across pixel commands).
  // Off in every named set; the profile's xy-short=on turns it on.
  bool shortHighXy = false;
  // RU may write as few bits a pixel as the palette needs (5 to 7 for 17 to
  // 128 colours) when the profile asks (ru-bits=fit): no source writes a
  // depth other than 4 or its planes, so compact only.
  bool fittedDepth = false;
};

// The named form sets, strict first (the default).
const std::vector<Tek4125Forms>& tek4125FormSets();
// Throws lattice::Error(Usage) naming the known sets.
const Tek4125Forms& tek4125Forms(std::string_view name);
// "strict, compact", for help texts and errors.
std::string tek4125FormSetNames();

}  // namespace lattice::tek4125
