// One libFuzzer harness, built once per surface (fuzz/CMakeLists.txt
// defines LATTICE_FUZZ_TARGET, the target's name, and LATTICE_FUZZ_ENTRY, its
// entry function in fuzz/entries.hpp): fuzz_scene, fuzz_lht, fuzz_tek4125,
// fuzz_tek4027, fuzz_png. libFuzzer supplies main(); scripts/fuzz.sh runs them.
#include <cstddef>
#include <cstdint>

#include "fuzz/entries.hpp"
#include "fuzz/held_back.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // -1: libFuzzer keeps a held-back input out of the corpus.
  if (lattice::fuzz::heldBack(LATTICE_FUZZ_TARGET, {data, size})) return -1;
  lattice::fuzz::LATTICE_FUZZ_ENTRY({data, size});
  return 0;
}
