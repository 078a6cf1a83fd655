#include "lht/table/lht_form.hpp"

#include <fmt/format.h>

#include <array>

#include "foundation/error.hpp"
#include "foundation/name_table.hpp"

namespace lattice::lht {

namespace {

constexpr std::array<EnumName<LhtForm>, 3> kForms = {{
    {LhtForm::Hashed, "hashed"},
    {LhtForm::Compressed, "compressed"},
    {LhtForm::OnDemand, "on-demand"},
}};

}  // namespace

std::string_view lhtFormName(LhtForm form) { return nameOfValue(kForms, form); }

std::string lhtFormChoices() { return namesOf(kForms); }

std::optional<LhtForm> lhtFormFromName(std::string_view name) { return valueNamed(kForms, name); }

std::optional<LhtForm> lhtFormFromCode(std::uint16_t code) { return valueWithCode(kForms, code); }

LhtForm parseLhtForm(std::string_view name, std::string_view what) {
  if (const auto form = lhtFormFromName(name)) return *form;
  throw Error(ErrorKind::Usage, fmt::format("{}: unknown LHT form '{}'; use one of {}", what, name, lhtFormChoices()));
}

}  // namespace lattice::lht
