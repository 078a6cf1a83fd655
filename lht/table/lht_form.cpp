#include "lht/table/lht_form.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"
#include "foundation/name_table.hpp"
#include "lht/table/table_forms.hpp"

namespace lattice::lht {

namespace {

// Whether .lht files hold the form whose code is `code`.
bool inFiles(std::size_t code) {
  return withForm(
      static_cast<LhtForm>(code), [](auto i) { return FormAt<decltype(i)::value>::kInFiles; }, [] { return false; });
}

}  // namespace

std::string_view lhtFormName(LhtForm form) {
  const auto code = static_cast<std::size_t>(form);
  return code < kLhtFormNames.size() ? kLhtFormNames[code] : std::string_view("unknown");
}

std::string lhtFormChoices() { return namesOf(kLhtFormNames); }

std::optional<LhtForm> lhtFormFromName(std::string_view name) {
  if (const auto* found = findNamed(kLhtFormNames, name))
    return static_cast<LhtForm>(found - kLhtFormNames.data());
  return std::nullopt;
}

std::optional<LhtForm> lhtFormFromCode(std::uint16_t code) {
  if (code < kLhtFormCount && inFiles(code)) return static_cast<LhtForm>(code);
  return std::nullopt;
}

std::string lhtFiledFormCodes() {
  std::string codes;
  for (std::size_t code = 0; code < kLhtFormCount; ++code)
    if (inFiles(code)) codes += fmt::format("{}{} {}", codes.empty() ? "" : ", ", code, kLhtFormNames[code]);
  return codes;
}

std::string lhtFiledFormNames() {
  std::vector<std::string_view> names;
  for (std::size_t code = 0; code < kLhtFormCount; ++code)
    if (inFiles(code)) names.push_back(kLhtFormNames[code]);
  return choicesOf(names);
}

LhtForm parseLhtForm(std::string_view name, std::string_view what) {
  if (const auto form = lhtFormFromName(name)) return *form;
  throw Error(ErrorKind::Usage, fmt::format("{}: unknown LHT form '{}'; use one of {}", what, name, lhtFormChoices()));
}

}  // namespace lattice::lht
