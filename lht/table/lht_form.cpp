#include "lht/table/lht_form.hpp"

#include <fmt/format.h>

#include <array>
#include <utility>

#include "foundation/error.hpp"

namespace lattice::lht {

namespace {

constexpr std::array<std::pair<LhtForm, std::string_view>, 3> kForms = {{
    {LhtForm::Hashed, "hashed"},
    {LhtForm::Compressed, "compressed"},
    {LhtForm::OnDemand, "on-demand"},
}};

}  // namespace

std::string_view lhtFormName(LhtForm form) {
  for (const auto& [f, name] : kForms)
    if (f == form) return name;
  return "unknown";
}

std::string lhtFormChoices() {
  std::string out;
  for (const auto& [f, name] : kForms) out += fmt::format("{}{}", out.empty() ? "" : ", ", name);
  return out;
}

std::optional<LhtForm> lhtFormFromName(std::string_view name) {
  for (const auto& [f, n] : kForms)
    if (n == name) return f;
  return std::nullopt;
}

std::optional<LhtForm> lhtFormFromCode(std::uint16_t code) {
  for (const auto& [f, n] : kForms)
    if (static_cast<std::uint16_t>(f) == code) return f;
  return std::nullopt;
}

LhtForm parseLhtForm(std::string_view name, std::string_view what) {
  if (const auto form = lhtFormFromName(name)) return *form;
  throw Error(ErrorKind::Usage, fmt::format("{}: unknown LHT form '{}'; use one of {}", what, name, lhtFormChoices()));
}

}  // namespace lattice::lht
