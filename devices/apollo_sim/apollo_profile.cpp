#include "devices/apollo_sim/apollo_profile.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"

namespace lattice::apollo {

ApolloProfile dn660Profile(int planes) {
  if (planes != 4 && planes != 8)
    throw Error(ErrorKind::Usage, fmt::format("a DN660 has 4 or 8 bit planes, not {}: use dn660-4 or dn660", planes));
  ApolloProfile p;
  p.name = planes == 8 ? "dn660" : "dn660-4";
  p.model = fmt::format("Apollo DN660, 1024x1024, {} planes", planes);
  p.width = 1024;
  p.height = 1024;
  p.planes = planes;
  return p;
}

ApolloProfile dn580Profile() {
  ApolloProfile p;
  p.name = "dn580";
  p.model = "Apollo DN580, 1280x1024, 8 planes";
  p.width = 1280;
  p.height = 1024;
  p.planes = 8;
  return p;
}

std::vector<std::string> apolloProfileNames() { return {"dn660", "dn660-8", "dn660-4", "dn580"}; }

ApolloProfile apolloProfileByName(std::string_view name) {
  if (name == "dn660" || name == "dn660-8") return dn660Profile(8);
  if (name == "dn660-4") return dn660Profile(4);
  if (name == "dn580") return dn580Profile();
  throw Error(ErrorKind::Usage,
              fmt::format("unknown Apollo model '{}': use one of {}", name, fmt::join(apolloProfileNames(), ", ")));
}

}  // namespace lattice::apollo
