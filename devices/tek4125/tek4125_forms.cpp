#include "devices/tek4125/tek4125_forms.hpp"

#include "devices/tek4125/named_table.hpp"

namespace lattice::tek4125 {

const std::vector<Tek4125Forms>& tek4125FormSets() {
  static const std::vector<Tek4125Forms> sets = {
      // Fields: name, defineSurfaces, explicitBackground, screenViewport,
      // fullXy, escapeDel, colourEntriesPerTg, runLength, runCodeBytesPerRl,
      // maxRunCode, beamContinues, rasterOnlyAtFourBits, shortHighXy,
      // fittedDepth. RL's 12-byte cap and
      // its codes below 32768 are the RAL GKS driver's (GK4TRO); RP at 4 bits
      // is zebra's dev_4107.c, the only packing a source shows.
      {"strict", true, true, true, true, true, 1, true, 12, 32767, false, true, false, false},
      {"compact", false, false, false, false, false, 0, true, 0, 65535, true, false, false, true},
  };
  return sets;
}

std::string tek4125FormSetNames() { return namesOf(tek4125FormSets()); }

const Tek4125Forms& tek4125Forms(std::string_view name) { return findNamed(tek4125FormSets(), name, "form set"); }

}  // namespace lattice::tek4125
