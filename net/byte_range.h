#pragma once
// The one byte range an HTTP request asks for (RFC 9110, 14.1.2), as octopoint-serve reads it: a
// single range of the form a-b, a- or -n. Several ranges at once are not served (answered 416, like
// every malformed or unsatisfiable range), so that a response is always one contiguous piece.

#include <cstdint>
#include <optional>
#include <string_view>

namespace octopoint::net {

struct ByteRange {
  std::uint64_t first = 0;
  std::uint64_t last = 0;  // inclusive
  std::uint64_t size() const { return last - first + 1; }
};

enum class RangeVerdict {
  kWhole,          // no Range header: the whole file (200)
  kPartial,        // a satisfiable range (206)
  kUnsatisfiable,  // malformed, several ranges, or outside the file (416)
};

// Reads `header` (the Range header's value; empty when there is none) for a file of `file_size`
// bytes. A last byte past the end is clamped to it; a range starting at or past the end, an empty
// suffix, or anything but "bytes=" and digits is unsatisfiable.
RangeVerdict parseRange(std::string_view header, bool has_header, std::uint64_t file_size,
                        ByteRange* range);

}  // namespace octopoint::net
