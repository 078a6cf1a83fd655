#pragma once
// What the simulator assumes about an Apollo colour display. Sizes are those
// of Apollo's GPR documentation (Domain Graphics Primitive Resource): the
// DN6xx colour node is 1024x1024 with 4 or 8 bit planes, the DN580 1280x1024
// with 8. The colour map has 2^planes entries, each given to GPR packed as
// 0xRRGGBB; the per-gun table width that gpr_$inq_disp_characteristics
// reports is ASSUMED to be 8 bits (the packing allows no more), so a colour
// map entry shows exactly the Rgb8 it was given.
#include <string>
#include <string_view>
#include <vector>

#include "foundation/settings_schema.hpp"

namespace lattice::apollo {

struct ApolloProfile {
  std::string name;     // "dn660", "dn660-4", "dn580"
  std::string model;    // human-readable, for reports
  int width = 1024;     // visible pixels
  int height = 1024;
  int planes = 8;       // bits per pixel: 2^planes colour map entries
  int gunBits = 8;      // bits per primary in the colour map (assumed, see above)
  int colorMapEntries() const { return 1 << planes; }
};

// DN660 with 4 or 8 planes; lattice::Error(Usage) for anything else.
ApolloProfile dn660Profile(int planes = 8);
ApolloProfile dn580Profile();
// By name ("dn660", "dn660-4", "dn660-8", "dn580"); Error(Usage) listing the names.
ApolloProfile apolloProfileByName(std::string_view name);
std::vector<std::string> apolloProfileNames();

// The profile's one setting, `profile` (the model), and what follows from it
// (apollo_profile.cpp): --set, describe() and docs/cli.md's table read it.
// The profile before any --set is the DN660 with 8 planes.
const SettingsSchema<ApolloProfile>& apolloSettings();
// Throws lattice::Error(Usage) naming the key and the models, or listing the keys.
void applyOverrides(ApolloProfile& profile, const std::vector<std::string>& keyValues);
std::string describe(const ApolloProfile& profile);

}  // namespace lattice::apollo
