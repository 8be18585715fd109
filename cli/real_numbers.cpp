#include "cli/real_numbers.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <system_error>

#include "cli/error.h"
#include "cli/text.h"

namespace octopoint::cli {
namespace {

std::string range(double low, double high) { return realText(low) + ".." + realText(high); }

}  // namespace

double parseReal(std::string_view option, std::string_view text, double low, double high,
                 std::string_view shown_range) {
  const std::string range_text = shown_range.empty() ? range(low, high) : std::string(shown_range);
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-') digits.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  const bool whole = !digits.empty() && end == digits.data() + digits.size();
  if (!whole || (error != std::errc() && error != std::errc::result_out_of_range) ||
      std::isnan(value)) {
    throw Error(std::string(option) + ": " + inQuotes(text) + " is not a number (" + range_text +
                ")");
  }
  // Beyond double's range: 1e400 is outside every range we state; 1e-400 is zero (strtod says
  // which: it returns a huge value for overflow and a tiny one for underflow).
  if (error == std::errc::result_out_of_range)
    value = std::strtod(std::string(digits).c_str(), nullptr);
  if (!std::isfinite(value) || std::fabs(value) == HUGE_VAL || value < low || value > high) {
    throw Error(std::string(option) + ": " + printable(text) + " is outside " + range_text);
  }
  return value;
}

Angle parseDegrees(std::string_view option, std::string_view text) {
  const double degrees = parseReal(option, text, -kMaxDegrees, kMaxDegrees);
  return Angle::fromMilliDegrees(std::llround(degrees * 1000));
}

Q16 parseZoom(std::string_view option, std::string_view text) {
  const double zoom = parseReal(option, text, kMinZoom, kMaxZoom, "1/65536..32767");
  return Q16::fromRaw(static_cast<std::int32_t>(std::llround(zoom * Q16::kOneRaw)));
}

}  // namespace octopoint::cli
