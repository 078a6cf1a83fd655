#include "lht/table/lht_precision.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"
#include "foundation/name_table.hpp"

namespace lattice::lht {

const LhtPrecisionInfo& lhtPrecisionInfo(LhtPrecision precision) {
  for (const LhtPrecisionInfo& info : kLhtPrecisions)
    if (info.precision == precision) return info;
  throw Error(ErrorKind::Internal, fmt::format("LHT precision code {} has no description",
                                               static_cast<unsigned>(precision)));
}

std::string_view lhtPrecisionName(LhtPrecision precision) { return lhtPrecisionInfo(precision).name; }

std::string lhtPrecisionChoices() {
  std::string out;
  for (const LhtPrecisionInfo& info : kLhtPrecisions)
    out += fmt::format("{}{} ({} B/entry)", out.empty() ? "" : ", ", info.name, info.entryBytes);
  return out;
}

std::optional<LhtPrecision> lhtPrecisionFromName(std::string_view name) {
  if (const LhtPrecisionInfo* info = findNamed(kLhtPrecisions, name)) return info->precision;
  return std::nullopt;
}

LhtPrecision parseLhtPrecision(std::string_view name, std::string_view what) {
  if (const auto precision = lhtPrecisionFromName(name)) return *precision;
  throw Error(ErrorKind::Usage,
              fmt::format("{}: unknown entry precision '{}'; use one of {}", what, name, lhtPrecisionChoices()));
}

std::optional<LhtPrecision> lhtPrecisionFromCode(std::uint16_t code) {
  for (const LhtPrecisionInfo& info : kLhtPrecisions)
    if (static_cast<std::uint16_t>(info.precision) == code) return info.precision;
  return std::nullopt;
}

}  // namespace lattice::lht
