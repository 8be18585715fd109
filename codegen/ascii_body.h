#pragma once
// Checking the data lines of an ascii PCD or PLY scan before PCL reads them. PCL parses each value
// with a stream and keeps 0 (PCD) or NaN (PLY) where that fails, so "10.5 10.5 oops" became a
// point at the origin (stretching the fitted cube tenfold) or a silently dropped point; a short
// last line became garbage. Here every data line must hold exactly the values its element
// declares, each a number of its property's type and range, and there must be exactly as many
// data lines as the header declares items.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace octopoint::prepare {

// A number's type in a scan header: PCD TYPE/SIZE, or a PLY scalar type.
struct ValueType {
  char kind = 'F';         // 'F' floating point, 'I' signed integer, 'U' unsigned integer
  std::uint64_t size = 4;  // bytes: 1, 2, 4 or 8
};

// One property of an element: `repeat` values of `type` (a PCD field's COUNT), or, for a PLY
// list, a count of `list_count` type followed by that many values of `type`.
struct AsciiProperty {
  std::string name;
  ValueType type;
  std::uint64_t repeat = 1;
  bool is_list = false;
  ValueType list_count;
  std::size_t header_line = 0;  // the header line that declares it, for messages
};

// `count` data lines, one per item (a PCD has one element: its points).
struct AsciiElement {
  std::string name;    // "point", "vertex": one item, in messages
  std::string plural;  // "points", "'vertex' items": many, in messages
  std::uint64_t count = 0;
  std::vector<AsciiProperty> properties;
  std::string property_word =
      "property";  // what the format calls them: PCD "field", PLY "property"
};

// Reads the body from `body_offset` (line `first_line` of the file) and throws PrepareError
// "PATH: what (line N)" at the first line that does not parse, or "truncated: ..." when the data
// ends before every declared item. Blank lines are skipped, as PCL does; when the data is short
// and held blank lines, the message counts them and names the first instead (a blank line where
// a point was meant is not a truncated file).
void checkAsciiBody(const std::filesystem::path& path, std::uint64_t body_offset,
                    std::size_t first_line, const std::vector<AsciiElement>& elements);

}  // namespace octopoint::prepare
