// One libFuzzer harness, built once per surface (fuzz/CMakeLists.txt
// defines LATTICE_FUZZ_ENTRY as the target's entry function in
// fuzz/entries.hpp): fuzz_scene, fuzz_lht, fuzz_tek4125, fuzz_tek4027,
// fuzz_png, fuzz_sixel. libFuzzer supplies main(); scripts/fuzz.sh runs them.
#include <cstddef>
#include <cstdint>

#include "fuzz/entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  lattice::fuzz::LATTICE_FUZZ_ENTRY({data, size});
  return 0;
}
