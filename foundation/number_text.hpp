#pragma once
// Every number a user types (a flag's value, a `--set` value, an `--at` item,
// a size with a unit) is read here, so NaN, infinities, overflow and values
// outside a setting's range are refused in one place and in one form:
// "WHAT: 'TEXT' is not a number; give one from MIN to MAX" (lattice::Error,
// Usage, exit 2). Decimal text only: an optional '-', digits, an optional
// fraction and exponent; no hex, no leading '+' or space, nothing after.
#include <limits>
#include <string>
#include <string_view>

namespace lattice {

struct NumberRange {
  double min = -std::numeric_limits<double>::max();
  double max = std::numeric_limits<double>::max();
  bool whole = false;  // integers in digits only: "2.5", "1e3" and "4.0" are refused
};

// The value of `text`, or Error(Usage) naming `what` (a flag or key) and the range.
double parseNumberText(std::string_view what, std::string_view text, NumberRange range);
// The same for an int-typed setting; its range must lie within int's.
int parseIntText(std::string_view what, std::string_view text, NumberRange range);
// Why `text` is refused, or "" when it is a number in range: for callers that
// report through another channel (CLI11's validators).
std::string numberTextProblem(std::string_view text, NumberRange range);
// "1 to 16384", "a whole number from 0 to 100", "any finite number": the range in words.
std::string describeRange(NumberRange range);

}  // namespace lattice
