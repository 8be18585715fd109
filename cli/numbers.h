#pragma once
// Strict parsing of the whole numbers users pass as options: the whole text is the number (an
// optional sign and decimal digits, nothing before or after), it lies in a stated range, and
// anything else is refused with a cli::Error naming the option. No floating point here, so the
// device's own tools (targets/armel/) can use it.

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string_view>
#include <vector>

namespace octopoint::cli {

// "--depth: '8.7' is not a whole number" / "--depth: 40 is outside 1..16".
std::int64_t parseInteger(std::string_view option, std::string_view text, std::int64_t low,
                          std::int64_t high);

// parseInteger for an int option (low and high are ints, so the result fits).
inline int parseInt(std::string_view option, std::string_view text, int low, int high) {
  return static_cast<int>(parseInteger(option, text, low, high));
}

enum class ListOrder { kAny, kStrictlyAscending };

// A comma-separated list of whole numbers, each in [low, high], 1..max_count items:
// "--depths: item 2 of '7,,8' is empty", "--depths: 0 is outside 1..16",
// "--depths: '8,7' is not strictly ascending", "--depths: 12 items, at most 8".
std::vector<int> parseIntList(std::string_view option, std::string_view text, int low, int high,
                              std::size_t max_count, ListOrder order);

struct FrameSize {
  std::int32_t width = 0;
  std::int32_t height = 0;
};

// "WxH" with each side in [low, high] and width * height <= max_pixels:
// "--size: '4294967616x240' is not WxH with each side in 1..8192",
// "--size: 8192x8192 is 67108864 pixels, at most 16777216".
FrameSize parseFrameSize(std::string_view option, std::string_view text, int low, int high,
                         std::int64_t max_pixels = std::numeric_limits<std::int64_t>::max());

// The index of `text` among `choices`: "--axes: 'x' is not one of y-down, y-up".
std::size_t parseChoice(std::string_view option, std::string_view text,
                        std::initializer_list<std::string_view> choices);

}  // namespace octopoint::cli
