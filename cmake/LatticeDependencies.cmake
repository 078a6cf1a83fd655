# How the third-party libraries are linked, decided in one place: every target
# links lattice_fmt, lattice_toml and lattice_png rather than the packages'
# own targets, so LATTICE_STATIC switches them all at once.
#
# LATTICE_STATIC builds a fully static `lattice`, the "firmware" form of the
# renderer (docs/memory.md): a dynamically linked C++ program maps libstdc++,
# libc and libm whole and the dynamic loader touches their relocation pages,
# about 5 MiB resident before main() runs, while a static executable carries
# only the code it calls. Debian ships no static libfmt or libtoml++, so both
# are compiled by us from their headers (deps/);
# libpng and zlib come from their -dev packages' .a files; libusb is left out
# (its libudev has no static library), so `send --wait` is unavailable there.
option(LATTICE_STATIC "Link lattice statically (low-memory 'firmware' build; no libusb)" OFF)

# LATTICE_STATIC_CXX (the ordinary build's default) links only the C++ side
# into `lattice`: libstdc++ statically, fmt and toml++ from deps/, while
# glibc, libgcc_s, libpng and libusb stay shared. (libgcc_s stays shared
# because glibc's pthread_once unwinds through it: with a static copy of the
# unwinder beside it, an exception leaving std::call_once aborts.) libstdc++.so alone is 1.7 MiB
# resident once mapped (fault-around brings in most of its code); the static
# copy carries only what we call. Measured on the fuzzy sphere's render, the
# process floor (`lattice --help`) falls from 6.2 to 4.9 MiB (docs/memory.md,
# "The ordinary build in 8 MiB"), which is what lets `--memory-budget 8MiB`
# fit. Off under the sanitizers (their runtimes expect the shared library).
# Only the `lattice` executable links this way: tests and benchmarks keep the
# shared libstdc++ (the Embree peer loads it anyway through libembree3).
if(LATTICE_SANITIZE OR LATTICE_FUZZ)
  set(_static_cxx_default OFF)
else()
  set(_static_cxx_default ON)
endif()
option(LATTICE_STATIC_CXX "Link lattice's C++ runtime, fmt and toml++ statically (glibc, libpng, libusb shared)"
  ${_static_cxx_default})
if(LATTICE_SANITIZE OR LATTICE_FUZZ)
  set(LATTICE_STATIC_CXX OFF CACHE BOOL "" FORCE)
endif()
find_package(fmt REQUIRED)
find_package(tomlplusplus REQUIRED)

# fmt and toml++ are compiled once, by us, from Debian's headers (deps/): every
# other translation unit sees only their declarations. Debian ships both only
# as shared libraries, which would bring the shared libstdc++ back into
# `lattice`; their header-only forms, used here until issue 27, compiled the
# formatting engine and the TOML parser again in every object that reached
# them, most of the build's time (docs/benchmarks.md, "Build time").
add_library(lattice_fmt_headers INTERFACE)
get_target_property(_fmt_includes fmt::fmt INTERFACE_INCLUDE_DIRECTORIES)
target_include_directories(lattice_fmt_headers SYSTEM INTERFACE ${_fmt_includes})
add_library(lattice_toml_headers INTERFACE)
get_target_property(_toml_includes tomlplusplus::tomlplusplus INTERFACE_INCLUDE_DIRECTORIES)
target_include_directories(lattice_toml_headers SYSTEM INTERFACE ${_toml_includes})
target_compile_definitions(lattice_toml_headers INTERFACE TOML_HEADER_ONLY=0)

add_library(lattice_fmt INTERFACE)
add_library(lattice_toml INTERFACE)
# lattice_png carries zlib too: io/png_encoder.cpp deflates with it directly.
add_library(lattice_png INTERFACE)
target_link_libraries(lattice_fmt INTERFACE lattice_fmt_runtime)
target_link_libraries(lattice_toml INTERFACE lattice_toml_runtime)

if(LATTICE_STATIC)
  set(LATTICE_WITH_LIBUSB OFF CACHE BOOL "" FORCE)
  find_library(LATTICE_PNG_STATIC NAMES libpng16.a libpng.a REQUIRED)
  find_library(LATTICE_Z_STATIC NAMES libz.a REQUIRED)
  find_path(LATTICE_PNG_INCLUDE png.h REQUIRED)
  target_include_directories(lattice_png SYSTEM INTERFACE ${LATTICE_PNG_INCLUDE})
  target_link_libraries(lattice_png INTERFACE ${LATTICE_PNG_STATIC} ${LATTICE_Z_STATIC} m)
else()
  find_package(PNG REQUIRED)
  target_link_libraries(lattice_png INTERFACE PNG::PNG)
endif()
