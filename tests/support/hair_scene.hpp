#pragma once
// The lattice suites' test scene as TOML: a sphere wearing a scatter of short
// polyline hairs (thesis sec. 3.4, Plate 6 in miniature), seen from the
// front and above, lit from the upper right. What a suite varies is a field;
// the rest stays the same in every suite, so their pictures are comparable.
#include <string>

namespace lattice::testing {

struct HairScene {
  int size = 56;            // width and height in pixels
  int hairs = 200;          // the scatter's count
  int seed = 7;             // the scatter's seed
  std::string latticeKeys;  // extra keys of the [[lattices]] entry, one per line ("cache = ...\n")
  bool fur = false;         // ambient 0.2, K 0, and a "fur" material on the hairs
  bool fillLight = false;   // a second, dimmer light from the left
  bool floor = false;       // a floor (half-space) at y = -1.3

  std::string toml() const {
    std::string t = "[options]\nwidth = " + std::to_string(size) + "\nheight = " + std::to_string(size) + "\n";
    if (fur) t += "ambient = 0.2\nK = 0\n";
    t += R"([camera]
type = "look_at"
eye = [0.0, 1.0, -3.6]
target = [0.0, 0.0, 0.0]
fov = 40
)";
    if (fur) t += "[materials.fur]\ndiffuse = [0.9, 0.6, 0.3]\nspecular = 0.4\nshininess = 30\n";
    t += "[[lights]]\nposition = [4.0, 6.0, -5.0]\nintensity = 9.0\n";
    if (fillLight) t += "[[lights]]\nposition = [-6.0, 3.0, -2.0]\nintensity = 3.0\n";
    t += "[[lattices]]\nname = \"hair\"\nspacing = 0.03\noversample = 2\n" + latticeKeys;
    t += R"(object = { type = "polyline", radius = 0.015, points = [[0, 0, 0], [0.02, 0, 0.15], [0.08, 0.01, 0.3]] }
[[objects]]
type = "sphere"
radius = 0.9
[[objects]]
type = "lattice_scatter"
lattice = "hair"
)";
    t += "count = " + std::to_string(hairs) + "\nradius = 0.9\nseed = " + std::to_string(seed) + "\n";
    if (fur) t += "material = \"fur\"\n";
    if (floor) t += "[[objects]]\ntype = \"half_space\"\nnormal = [0.0, 1.0, 0.0]\noffset = -1.3\n";
    return t;
  }
};

}  // namespace lattice::testing
