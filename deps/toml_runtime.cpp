// The compiled half of toml++, built once for every target of ours.
//
// Method: toml++ documents two forms, header-only (TOML_HEADER_ONLY=1, its
// parser compiled again in every translation unit that includes it) and
// "TOML_HEADER_ONLY=0 everywhere, TOML_IMPLEMENTATION in exactly one
// translation unit". This is that one unit; cmake/LatticeDependencies.cmake
// gives every other target TOML_HEADER_ONLY=0. Debian's libtomlplusplus.so
// is not used: it would pull in the shared libstdc++ that `lattice` leaves
// out (LATTICE_STATIC_CXX, docs/memory.md).
#define TOML_IMPLEMENTATION 1
#include <toml++/toml.h>
