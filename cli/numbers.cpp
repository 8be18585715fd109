#include "cli/numbers.h"

#include <charconv>
#include <string>
#include <system_error>

#include "cli/error.h"
#include "cli/text.h"

namespace octopoint::cli {
namespace {

std::string range(std::int64_t low, std::int64_t high) {
  return std::to_string(low) + ".." + std::to_string(high);
}

[[noreturn]] void outside(std::string_view option, std::string_view text, std::int64_t low,
                          std::int64_t high) {
  throw Error(std::string(option) + ": " + printable(text) + " is outside " + range(low, high));
}

// The whole of `text` as an integer: nullopt-like false when it is not one; `too_large` when it
// is digits that do not fit 64 bits (then it is outside every range we state).
bool wholeNumber(std::string_view text, std::int64_t* value, bool* too_large) {
  *too_large = false;
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), *value);
  if (end != text.data() + text.size()) return false;
  if (error == std::errc::result_out_of_range) {
    *too_large = true;
    return true;
  }
  return error == std::errc();
}

}  // namespace

std::int64_t parseInteger(std::string_view option, std::string_view text, std::int64_t low,
                          std::int64_t high) {
  std::int64_t value = 0;
  bool too_large = false;
  if (!wholeNumber(text, &value, &too_large)) {
    throw Error(std::string(option) + ": " + inQuotes(text) + " is not a whole number (" +
                range(low, high) + ")");
  }
  if (too_large || value < low || value > high) outside(option, text, low, high);
  return value;
}

std::vector<int> parseIntList(std::string_view option, std::string_view text, int low, int high,
                              std::size_t max_count, ListOrder order) {
  std::vector<int> values;
  std::size_t at = 0;
  for (std::size_t item = 1;; ++item) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string_view part = text.substr(at, comma - at);
    if (part.empty()) {
      throw Error(std::string(option) + ": item " + std::to_string(item) + " of " + inQuotes(text) +
                  " is empty (give a comma-separated list of whole numbers)");
    }
    if (values.size() == max_count) {
      throw Error(std::string(option) + ": " + inQuotes(text) + " has more than " +
                  std::to_string(max_count) + " items");
    }
    const int value = parseInt(option, part, low, high);
    if (order == ListOrder::kStrictlyAscending && !values.empty() && value <= values.back()) {
      throw Error(std::string(option) + ": " + inQuotes(text) + " is not strictly ascending");
    }
    values.push_back(value);
    if (comma == text.size()) break;
    at = comma + 1;
  }
  return values;
}

FrameSize parseFrameSize(std::string_view option, std::string_view text, int low, int high,
                         std::int64_t max_pixels) {
  const std::size_t x = text.find_first_of("xX");
  std::int64_t width = 0;
  std::int64_t height = 0;
  bool too_large_w = false;
  bool too_large_h = false;
  if (x == std::string_view::npos || !wholeNumber(text.substr(0, x), &width, &too_large_w) ||
      !wholeNumber(text.substr(x + 1), &height, &too_large_h) || too_large_w || too_large_h ||
      width < low || width > high || height < low || height > high) {
    throw Error(std::string(option) + ": " + inQuotes(text) + " is not WxH with each side in " +
                range(low, high));
  }
  if (width * height > max_pixels) {
    throw Error(std::string(option) + ": " + std::to_string(width) + "x" + std::to_string(height) +
                " is " + std::to_string(width * height) + " pixels, at most " +
                std::to_string(max_pixels));
  }
  return {static_cast<std::int32_t>(width), static_cast<std::int32_t>(height)};
}

std::size_t parseChoice(std::string_view option, std::string_view text,
                        std::initializer_list<std::string_view> choices) {
  std::string names;
  std::size_t index = 0;
  for (std::string_view choice : choices) {
    if (choice == text) return index;
    names += (index++ == 0 ? "" : ", ") + std::string(choice);
  }
  throw Error(std::string(option) + ": " + inQuotes(text) + " is not one of " + names);
}

}  // namespace octopoint::cli
