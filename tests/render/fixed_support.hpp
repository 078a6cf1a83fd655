#pragma once
// Comparing a Fixed32 render with the double render of the same scene: the
// measure docs/fixed-point.md quotes (PSNR over all channels, and the share
// of channels more than 4 levels of 255 apart).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/png.hpp"

namespace lattice::testing {

struct FixedVsDouble {
  double psnr = 0.0;           // dB; +inf when identical
  double farFraction = 0.0;    // channels with |difference| > 4
  int maxDelta = 0;
};

inline FixedVsDouble compareRenders(const RgbImage& fixedImage, const RgbImage& doubleImage) {
  FixedVsDouble out;
  double squared = 0.0;
  long far = 0;
  for (std::size_t i = 0; i < fixedImage.rgb.size(); ++i) {
    const int d = std::abs(int(fixedImage.rgb[i]) - int(doubleImage.rgb[i]));
    squared += double(d) * d;
    if (d > 4) ++far;
    if (d > out.maxDelta) out.maxDelta = d;
  }
  const double n = double(fixedImage.rgb.size());
  out.psnr = squared == 0.0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / (squared / n));
  out.farFraction = double(far) / n;
  return out;
}

// Every function of a static library instantiated for Fixed32 (or in the
// fixed-point root solver), and those among them that hold an SSE/x87
// floating-point instruction or call a libm function, from objdump's
// disassembly. Empty sets if objdump is missing (callers require that the
// per-pixel functions were seen, so that cannot pass silently).
struct FixedPointScan {
  std::set<std::string> fixedFunctions;
  std::set<std::string> withFloatingPoint;
  // Callee -> the functions whose code calls or jumps to it (relocations of
  // the library's objects), names without objdump's "<" and ">:".
  std::map<std::string, std::set<std::string>> callers;
};

// "<name>:\n" or "name-0x4" as objdump prints them -> name.
inline std::string plainFunctionName(std::string name) {
  if (name.size() >= 3 && name.compare(name.size() - 3, 3, ">:\n") == 0) name.resize(name.size() - 3);
  if (const auto at = name.rfind("-0x"); at != std::string::npos && name.find(')', at) == std::string::npos)
    name.resize(at);
  if (const auto at = name.rfind("+0x"); at != std::string::npos && name.find(')', at) == std::string::npos)
    name.resize(at);
  while (!name.empty() && (name.back() == '\n' || name.back() == ' ')) name.pop_back();
  return name;
}

inline bool isFloatingPointInstruction(const std::string& line) {
  static const char* heads[] = {"\tcvt", "\tadd", "\tsub", "\tmul", "\tdiv", "\tsqrt", "\tmin",
                                "\tmax", "\tucomi", "\tcomi", "\tround"};
  for (const char* h : heads) {
    const auto at = line.find(h);
    if (at == std::string::npos) continue;
    const auto end = line.find_first_of(" \t\n", at + 1);
    const std::string mnemonic = line.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
    for (const char* suffix : {"sd", "ss", "pd", "ps"})
      if (mnemonic.size() > 2 && mnemonic.compare(mnemonic.size() - 2, 2, suffix) == 0) return true;
  }
  for (const char* x87 : {"\tfld", "\tfst", "\tfmul", "\tfadd", "\tfdiv", "\tfsub"})
    if (line.find(x87) != std::string::npos) return true;
  if (line.find("call") != std::string::npos)
    for (const char* libm : {"<pow", "<sqrt", "<exp", "<log", "<round", "<floor", "<ceil", "<ldexp", "<fma",
                             "<nextafter", "<ilogb"})
      if (line.find(libm) != std::string::npos) return true;
  return false;
}

// extraFunctions: substrings of further function names to scan as
// fixed-point per-pixel code although their names do not say Fixed<32>
// (integer helpers the Fixed32 path calls, e.g. the LHT entry decoder).
inline FixedPointScan scanFixedPointCode(const std::string& library,
                                         const std::vector<std::string>& extraFunctions = {}) {
  FixedPointScan scan;
  const std::string command = "objdump -dr -C --no-show-raw-insn '" + library + "' 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return scan;
  std::string current;
  bool inFixed = false;
  char buffer[8192];
  while (std::fgets(buffer, sizeof buffer, pipe)) {
    const std::string line(buffer);
    if (line.size() > 3 && line.compare(line.size() - 3, 3, ">:\n") == 0) {
      current = line.substr(line.find('<') + 1);
      inFixed = current.find("Fixed<32>") != std::string::npos || current.find("fixed_roots::") != std::string::npos;
      for (const std::string& extra : extraFunctions) inFixed = inFixed || current.find(extra) != std::string::npos;
      if (inFixed) scan.fixedFunctions.insert(current);
      continue;
    }
    if (const auto reloc = line.find("R_X86_64_PLT32\t"); reloc != std::string::npos)
      scan.callers[plainFunctionName(line.substr(reloc + 15))].insert(plainFunctionName(current));
    // A local clone (".part.0", ".isra.0") is called through a PC32 relocation.
    if (const auto reloc = line.find("R_X86_64_PC32\t"); reloc != std::string::npos && line.find("[clone ") != std::string::npos)
      scan.callers[plainFunctionName(line.substr(reloc + 14))].insert(plainFunctionName(current));
    if (inFixed && isFloatingPointInstruction(line)) scan.withFloatingPoint.insert(current);
  }
  ::pclose(pipe);
  return scan;
}

// Scene set-up, which converts the double scene description once, may use
// floating point: constructors and builders.
inline bool isSetUpFunction(const std::string& name) {
  static const std::vector<std::string> setUp = {"::Camera(", "::Renderer(", "::build(", "::Bvh(",
                                                 "makeQuarticLeaf<", "makeCapsule<", "makeQuarticCapsule<", "paddedBox<",
                                                 "buildPrimitive<", "buildNode<", "::QuarticLeaf(", "makeCsgNode<",
                                                 "::LatticeLeafBase(", "makePolyline<", "makeLatticeLeaf<",
                                                 "::QuarticArithmetic(", "QuarticArithmetic<lattice::Fixed<32> >::prepare(",
                                                 "::EntryReader(", "::buildInto(", "::buildAs<", "BvhBuilder<"};
  for (const std::string& s : setUp)
    if (name.find(s) != std::string::npos) return true;
  return false;
}

// Set-up by name, or a helper the compiler kept out of line (e.g. glm's
// double -> Fixed32 vector conversion) that only set-up functions call.
inline bool isSetUpCode(const FixedPointScan& scan, const std::string& name) {
  if (isSetUpFunction(name)) return true;
  const auto found = scan.callers.find(plainFunctionName(name));
  if (found == scan.callers.end() || found->second.empty()) return false;
  for (const std::string& caller : found->second)
    if (!isSetUpFunction(caller)) return false;
  return true;
}

}  // namespace lattice::testing
