# CMake toolchain file for the firmware (docs/firmware.md): an ARM Cortex-M3
# with no FPU and no operating system, Debian's gcc-arm-none-eabi with newlib
# (nano) and its libstdc++. Used only by firmware/CMakeLists.txt through
# scripts/firmware.sh; the host build never reads it.
#   cmake -S firmware -B build-firmware -DCMAKE_TOOLCHAIN_FILE=cmake/arm-cortex-m3.cmake
#
# Tunables: the CPU flags below. -mfloat-abi=soft because the M3 has no FPU
# (every double becomes a libgcc call, which the fixed-point path must not
# make); -ffunction-sections/-fdata-sections with --gc-sections keep only
# what the image reaches (the core's file and thread code never links).
set(CMAKE_SYSTEM_NAME Generic)
# LATTICE_FIRMWARE_CPU: the board's core (firmware/boards/BOARD/board.tsv; an M4 runs
# M3 code too, and its own build may use UMAAL and the DSP instructions).
if(NOT LATTICE_FIRMWARE_CPU)
  set(LATTICE_FIRMWARE_CPU cortex-m3)
endif()
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES LATTICE_FIRMWARE_CPU)
set(CMAKE_SYSTEM_PROCESSOR ${LATTICE_FIRMWARE_CPU})
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_OBJCOPY arm-none-eabi-objcopy CACHE FILEPATH "objcopy")
set(CMAKE_SIZE arm-none-eabi-size CACHE FILEPATH "size")
# A bare-metal compiler cannot link a test program without a linker script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(LATTICE_CPU_FLAGS "-mcpu=${LATTICE_FIRMWARE_CPU} -mthumb -mfloat-abi=soft")
set(CMAKE_C_FLAGS_INIT "${LATTICE_CPU_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${LATTICE_CPU_FLAGS} -ffunction-sections -fdata-sections")
# Full newlib, not nano.specs: Debian's libstdc++_nano is built without
# exception support (a throw ends in std::terminate), and the core reports
# bad input by throwing lattice::Error (docs/firmware.md).
set(CMAKE_EXE_LINKER_FLAGS_INIT "${LATTICE_CPU_FLAGS} -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
