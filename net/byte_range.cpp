#include "net/byte_range.h"

#include <algorithm>
#include <cctype>

namespace octopoint::net {
namespace {

// Digits only, at most 19 of them (fits 63 bits); nullopt for anything else, including "".
std::optional<std::uint64_t> number(std::string_view text) {
  if (text.empty() || text.size() > 19) return std::nullopt;
  std::uint64_t value = 0;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return value;
}

}  // namespace

RangeVerdict parseRange(std::string_view header, bool has_header, std::uint64_t file_size,
                        ByteRange* range) {
  if (!has_header) {
    if (file_size == 0) return RangeVerdict::kWhole;
    *range = {0, file_size - 1};
    return RangeVerdict::kWhole;
  }
  constexpr std::string_view kUnit = "bytes=";
  if (!header.starts_with(kUnit)) return RangeVerdict::kUnsatisfiable;
  const std::string_view spec = header.substr(kUnit.size());
  const std::size_t dash = spec.find('-');
  if (dash == std::string_view::npos || spec.find(',') != std::string_view::npos)
    return RangeVerdict::kUnsatisfiable;
  const std::string_view first_text = spec.substr(0, dash);
  const std::string_view last_text = spec.substr(dash + 1);
  if (first_text.empty()) {  // -n: the last n bytes
    const std::optional<std::uint64_t> suffix = number(last_text);
    if (!suffix || *suffix == 0 || file_size == 0) return RangeVerdict::kUnsatisfiable;
    *range = {file_size - std::min(*suffix, file_size), file_size - 1};
    return RangeVerdict::kPartial;
  }
  const std::optional<std::uint64_t> first = number(first_text);
  if (!first || *first >= file_size) return RangeVerdict::kUnsatisfiable;
  std::uint64_t last = file_size - 1;
  if (!last_text.empty()) {
    const std::optional<std::uint64_t> given = number(last_text);
    if (!given || *given < *first) return RangeVerdict::kUnsatisfiable;
    last = std::min(*given, file_size - 1);
  }
  *range = {*first, last};
  return RangeVerdict::kPartial;
}

}  // namespace octopoint::net
