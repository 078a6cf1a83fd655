#include "render/scene/scene_baker.hpp"

namespace lattice {

std::string SceneBaker::mat4(const Mat4d& m) const {
  // glm is column-major: the constructor takes the columns in order.
  std::string out = "lattice::Mat4d(";
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out += (c || r ? ", " : "") + number(m[c][r]);
  return out + ")";
}

}  // namespace lattice
