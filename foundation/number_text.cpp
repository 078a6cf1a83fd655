#include "foundation/number_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "foundation/error.hpp"

namespace lattice {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::max();

// 268435456, not 2.68435e+08: a bound is something to type back.
std::string bound(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return fmt::format("{:.0f}", v);
  return fmt::format("{:g}", v);
}

}  // namespace

std::string describeRange(NumberRange range) {
  const char* kind = range.whole ? "a whole number" : "a number";
  const bool low = range.min > -kUnbounded, high = range.max < kUnbounded;
  if (low && high) return fmt::format("{} from {} to {}", kind, bound(range.min), bound(range.max));
  if (low) return fmt::format("{} of at least {}", kind, bound(range.min));
  if (high) return fmt::format("{} of at most {}", kind, bound(range.max));
  return range.whole ? "a whole number" : "a finite number";
}

namespace {

// The value of `text`, and why it is refused ("" when it is not).
struct Reading {
  double value = 0;
  std::string problem;
};

Reading readNumber(std::string_view text, NumberRange range) {
  Reading r;
  // from_chars reads "nan" and "inf" as numbers, and takes no '+' or space:
  // the finiteness test below is what refuses the first two.
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), r.value);
  const bool parsed = !text.empty() && ec == std::errc() && end == text.data() + text.size();
  if (!parsed || !std::isfinite(r.value))
    r.problem = fmt::format("'{}' is not {}; give {}", text,
                            ec == std::errc::result_out_of_range ? "a representable number" : "a finite number",
                            describeRange(range));
  // Whole numbers in digits only: an integer flag's own conversion (CLI11's)
  // reads no fraction or exponent, so 1e3 and 4.0 are refused here, not there.
  else if (range.whole && (r.value != std::floor(r.value) || text.find_first_of(".eE") != std::string_view::npos))
    r.problem = fmt::format("'{}' is not a whole number in digits; give {}", text, describeRange(range));
  else if (r.value < range.min || r.value > range.max)
    r.problem = fmt::format("'{}' is out of range; give {}", text, describeRange(range));
  return r;
}

}  // namespace

std::string numberTextProblem(std::string_view text, NumberRange range) { return readNumber(text, range).problem; }

double parseNumberText(std::string_view what, std::string_view text, NumberRange range) {
  const Reading r = readNumber(text, range);
  if (!r.problem.empty()) throw Error(ErrorKind::Usage, fmt::format("{}: {}", what, r.problem));
  return r.value;
}

int parseIntText(std::string_view what, std::string_view text, NumberRange range) {
  range.whole = true;
  const double value = parseNumberText(what, text, range);
  // Beyond int, whatever the caller's range: the setting could not hold it.
  if (value < double(std::numeric_limits<int>::min()) || value > double(std::numeric_limits<int>::max()))
    throw Error(ErrorKind::Usage, fmt::format("{}: '{}' is too large for this setting; give {}", what, text,
                                              describeRange({std::max(range.min, double(std::numeric_limits<int>::min())),
                                                             std::min(range.max, double(std::numeric_limits<int>::max())),
                                                             true})));
  return static_cast<int>(value);
}

}  // namespace lattice
