# Sourced by the scripts that configure a build folder (build.sh,
# check-static.sh, check-sanitizers.sh, fuzz.sh): the generator and compiler
# launcher they share, so every build folder is made the same way.
#   lattice_cmake_args DIR   sets the array cmake_args
# Ninja where it is installed (scripts/setup.sh installs it): it compiles the
# objects of every target as soon as their sources are known, where Make
# waits for each library's link before the next folder starts. A folder
# already configured keeps its generator (CMake refuses to switch one).
# ccache where it is installed: a rebuild after a small change, or a second
# clone on the same machine, compiles only what changed. On a fresh machine
# neither the cache nor ccache is there, and nothing changes. The tests'
# precompiled headers (tests/CMakeLists.txt) are cached only with the
# sloppiness ccache's manual asks for ("Precompiled headers").
lattice_cmake_args() {
  local dir=$1
  cmake_args=()
  if [[ ! -f $dir/CMakeCache.txt ]] && command -v ninja >/dev/null; then cmake_args+=(-G Ninja); fi
  if command -v ccache >/dev/null; then cmake_args+=("-DCMAKE_CXX_COMPILER_LAUNCHER=env;CCACHE_SLOPPINESS=pch_defines,time_macros;ccache"); fi
}
