#include "app/cli/setting_flags.hpp"

#include <vector>

#include "app/cli/number_flags.hpp"
#include "foundation/byte_count.hpp"

namespace lattice::app {

CLI::Validator settingFlagCheck(const settings_detail::RowType& type) {
  const std::string unset(type.unset);
  switch (type.kind) {
    case SettingKind::Whole:
    case SettingKind::Number:
      return unset.empty() ? numberIn(type.range) : numberIn(type.range, unset);
    case SettingKind::Choice: {
      std::vector<std::string> names(type.choices.begin(), type.choices.end());
      if (!unset.empty()) names.push_back(unset);
      return CLI::IsMember(names);
    }
    case SettingKind::Bytes:
      // The one size parser decides, so the flag refuses what --set does.
      return CLI::Validator(
          [unset](std::string& text) { return !unset.empty() && text == unset ? std::string() : byteCountProblem(text); },
          unset.empty() ? std::string() : "or " + unset, "lattice-size");
    case SettingKind::Switch:
    case SettingKind::Reported:
      break;
  }
  return CLI::Validator();
}

}  // namespace lattice::app
