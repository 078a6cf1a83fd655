#pragma once
// The canonical text of a TOML value: what a lattice's cache key (the object
// hash in its .lht file) is computed from, so the key rests on the values a
// scene gives, not on how a formatter prints them (docs/lattices.md).
//
// Method: a walk of toml++'s node tree, each value tagged with its type.
//   table    {k1=v1;k2=v2;}   keys sorted by their UTF-8 bytes
//   array    [v1,v2,]
//   string   s<bytes>:<text>  (length-prefixed: no escaping to get wrong)
//   key      <bytes>:<text>
//   integer  i<decimal>
//   float    f<16 hex digits>  the IEEE-754 binary64 bit pattern, exact
//   boolean  b0 | b1
//   dates    D<y>-<m>-<d>, T<h>:<m>:<s>.<ns>, DT<date><time>[Z<offset minutes>]
// Equal values give equal text; 1 and 1.0 differ (their types do).
#include <string>

#include <toml++/toml.h>

namespace lattice::lht {

std::string canonicalToml(const toml::node& node);
// A double in the same form: f<16 hex digits of its bits>.
std::string canonicalDouble(double value);

}  // namespace lattice::lht
