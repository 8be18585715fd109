// Checks a .pcd or .ply header against the file before PCL reads it (see scan_loader.cpp for why):
// every size the header declares must fit in the file. No PCL here: plain parsing of the text
// header and, for binary_compressed PCD, of its two size words.

#include "codegen/scan_header_check.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "cli/text.h"
#include "codegen/ascii_body.h"
#include "codegen/lzf_check.h"
#include "codegen/prepare_error.h"
#include "codegen/scan_layout_check.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

// A header longer than this is not a header: stops us scanning a huge garbage file for "DATA".
constexpr std::size_t kMaxHeaderBytes = 1 << 20;
// Generous limits that keep every size product below 2^64 and far from anything real.
constexpr std::uint64_t kMaxFieldCount = 1 << 16;
constexpr std::uint64_t kMaxPointBytes = 1 << 20;
constexpr std::uint64_t kMaxPoints = std::numeric_limits<std::uint32_t>::max();  // PCL's width
// The most bytes LZF (PCL's binary_compressed) can make of one compressed byte: a back reference
// of 3 bytes copies at most 7 + 255 + 2 = 264 bytes; a literal run never expands.
constexpr std::uint64_t kLzfMaxExpansion = 264 / 3;

}  // namespace

std::string printable(std::string_view text) { return cli::printable(text); }

std::uint64_t saturatingMul(std::uint64_t a, std::uint64_t b) {
  std::uint64_t product = 0;
  return __builtin_mul_overflow(a, b, &product) ? std::numeric_limits<std::uint64_t>::max()
                                                : product;
}

[[noreturn]] void fail(const fs::path& path, const std::string& what, const std::string& where) {
  throw PrepareError(cli::displayPath(path) + ": " + what + " (" + where + ")");
}

namespace {

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) {
  std::uint64_t sum = 0;
  return __builtin_add_overflow(a, b, &sum) ? std::numeric_limits<std::uint64_t>::max() : sum;
}

std::optional<std::uint64_t> parseUnsigned(std::string_view token) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (at < line.size()) {
    const std::size_t begin = line.find_first_not_of(" \t\r", at);
    if (begin == std::string_view::npos) break;
    const std::size_t end = std::min(line.find_first_of(" \t\r", begin), line.size());
    words.push_back(line.substr(begin, end - begin));
    at = end;
  }
  return words;
}

// The file's first bytes (at most kMaxHeaderBytes), where the header must lie.
std::string readHead(const fs::path& path, std::uint64_t file_size) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open the file for reading", "opening the scan");
  std::string head(std::min<std::uint64_t>(file_size, kMaxHeaderBytes), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

// One header line, split into words, with its 1-based line number for messages.
struct HeaderLine {
  std::size_t number = 0;
  std::vector<std::string_view> words;
};

std::uint64_t readLittleEndianU32(const fs::path& path, std::uint64_t offset) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(offset));
  unsigned char bytes[4] = {};
  in.read(reinterpret_cast<char*>(bytes), 4);
  return std::uint64_t{bytes[0]} | std::uint64_t{bytes[1]} << 8 | std::uint64_t{bytes[2]} << 16 |
         std::uint64_t{bytes[3]} << 24;
}

// Splits `head` into lines up to and including the one whose first word is `last_keyword`.
// Returns the lines and the byte offset after that line; fails if the header never ends.
std::vector<HeaderLine> headerLines(const fs::path& path, const std::string& head,
                                    std::string_view last_keyword, std::uint64_t& body_offset) {
  std::vector<HeaderLine> lines;
  std::size_t at = 0;
  for (std::size_t number = 1; at < head.size(); ++number) {
    const std::size_t newline = head.find('\n', at);
    if (newline == std::string::npos) break;  // a header line always ends with '\n'
    HeaderLine line{number, splitWords(std::string_view(head).substr(at, newline - at))};
    at = newline + 1;
    const bool last = !line.words.empty() && line.words[0] == last_keyword;
    lines.push_back(std::move(line));
    if (last) {
      body_offset = at;
      return lines;
    }
  }
  fail(path,
       "header ends before its '" + std::string(last_keyword) +
           "' line: empty, truncated or not a " + (last_keyword == "DATA" ? "PCD" : "PLY") +
           " file",
       "header, first " + std::to_string(head.size()) + " bytes");
}

// The PCD header's lines by keyword, comments skipped; fails on a keyword PCD does not have.
using PcdLines = std::map<std::string, HeaderLine, std::less<>>;

PcdLines pcdLinesByKeyword(const fs::path& path, const std::vector<HeaderLine>& lines) {
  PcdLines by_keyword;
  for (const HeaderLine& line : lines) {
    if (line.words.empty() || line.words[0].front() == '#') continue;
    static constexpr std::string_view kKeywords[] = {"VERSION", "FIELDS", "SIZE",   "TYPE",
                                                     "COUNT",   "WIDTH",  "HEIGHT", "VIEWPOINT",
                                                     "POINTS",  "DATA"};
    if (std::find(std::begin(kKeywords), std::end(kKeywords), line.words[0]) ==
        std::end(kKeywords)) {
      fail(path, "not a PCD header: unknown keyword '" + printable(line.words[0]) + "'",
           "header line " + std::to_string(line.number));
    }
    by_keyword[std::string(line.words[0])] = line;
  }
  return by_keyword;
}

const HeaderLine& pcdRequired(const fs::path& path, const PcdLines& by_keyword,
                              std::string_view keyword) {
  const auto found = by_keyword.find(keyword);
  if (found == by_keyword.end()) {
    fail(path, "PCD header has no " + std::string(keyword) + " line", "header");
  }
  return found->second;
}

std::uint64_t pcdNumber(const fs::path& path, const PcdLines& by_keyword,
                        std::string_view keyword) {
  const HeaderLine& line = pcdRequired(path, by_keyword, keyword);
  const auto value = line.words.size() == 2 ? parseUnsigned(line.words[1]) : std::nullopt;
  if (!value) {
    fail(path, "PCD " + std::string(keyword) + " is not a non-negative integer",
         "header line " + std::to_string(line.number));
  }
  return *value;
}

// Checks that FIELDS, SIZE, TYPE and COUNT agree and describe a point of sane size. Returns the
// point's layout (for checking ascii data lines; its count still 0) and sets its size in bytes.
AsciiElement pcdPointLayout(const fs::path& path, const PcdLines& by_keyword,
                            std::uint64_t& point_bytes) {
  const HeaderLine& fields = pcdRequired(path, by_keyword, "FIELDS");
  const HeaderLine& sizes = pcdRequired(path, by_keyword, "SIZE");
  const HeaderLine& types = pcdRequired(path, by_keyword, "TYPE");
  const std::size_t field_count = fields.words.size() - 1;
  if (field_count == 0) {
    fail(path, "PCD FIELDS line names no field", "header line " + std::to_string(fields.number));
  }
  const auto counts_line = by_keyword.find(std::string_view("COUNT"));
  for (const HeaderLine* line : {&sizes, &types}) {
    if (line->words.size() - 1 != field_count) {
      fail(path,
           "PCD " + std::string(line->words[0]) + " has " + std::to_string(line->words.size() - 1) +
               " entries for " + std::to_string(field_count) + " fields",
           "header line " + std::to_string(line->number));
    }
  }
  if (counts_line != by_keyword.end() && counts_line->second.words.size() - 1 != field_count) {
    fail(path,
         "PCD COUNT has " + std::to_string(counts_line->second.words.size() - 1) + " entries for " +
             std::to_string(field_count) + " fields",
         "header line " + std::to_string(counts_line->second.number));
  }

  point_bytes = 0;
  AsciiElement point_layout{"point", "points", 0, {}, "field"};
  for (std::size_t f = 1; f <= field_count; ++f) {
    const auto size = parseUnsigned(sizes.words[f]);
    const std::string_view type = types.words[f];
    const bool valid_size =
        size &&
        ((type == "F" && (*size == 4 || *size == 8)) ||
         ((type == "I" || type == "U") && (*size == 1 || *size == 2 || *size == 4 || *size == 8)));
    if (!valid_size) {
      fail(path,
           "PCD field '" + printable(fields.words[f]) + "' has invalid SIZE/TYPE " +
               printable(sizes.words[f]) + "/" + printable(type),
           "header line " + std::to_string(sizes.number));
    }
    std::uint64_t count = 1;
    if (counts_line != by_keyword.end()) {
      const auto parsed = parseUnsigned(counts_line->second.words[f]);
      if (!parsed || *parsed == 0 || *parsed > kMaxFieldCount) {
        fail(path,
             "PCD field '" + printable(fields.words[f]) + "' has invalid COUNT " +
                 printable(counts_line->second.words[f]),
             "header line " + std::to_string(counts_line->second.number));
      }
      count = *parsed;
    }
    point_bytes += *size * count;
    point_layout.properties.push_back(
        {std::string(fields.words[f]), {type.front(), *size}, count, false, {}, fields.number});
  }
  if (point_bytes > kMaxPointBytes) {
    fail(path, "PCD point size of " + std::to_string(point_bytes) + " bytes is absurd", "header");
  }
  return point_layout;
}

// POINTS, after checking it is WIDTH x HEIGHT, not 0 and within what PCL can hold.
std::uint64_t pcdPointCount(const fs::path& path, const PcdLines& by_keyword) {
  const std::uint64_t width = pcdNumber(path, by_keyword, "WIDTH");
  const std::uint64_t height = pcdNumber(path, by_keyword, "HEIGHT");
  const std::uint64_t points = pcdNumber(path, by_keyword, "POINTS");
  if (saturatingMul(width, height) != points) {
    fail(path,
         "PCD WIDTH x HEIGHT (" + std::to_string(width) + " x " + std::to_string(height) +
             ") differs from POINTS " + std::to_string(points),
         "header line " + std::to_string(pcdRequired(path, by_keyword, "POINTS").number));
  }
  if (points == 0) fail(path, "empty cloud (0 points)", "PCD header POINTS");
  if (points > kMaxPoints) {
    fail(path, "PCD declares " + std::to_string(points) + " points, more than PCL can hold",
         "header line " + std::to_string(pcdRequired(path, by_keyword, "POINTS").number));
  }
  return points;
}

// A binary_compressed body: uint32 compressed size, uint32 uncompressed size, then the LZF bytes.
// `needed`: the bytes the header's points take uncompressed.
void checkPcdCompressedBody(const fs::path& path, std::uint64_t body_offset,
                            std::uint64_t body_bytes, std::uint64_t points, std::uint64_t needed) {
  const std::string data_where = "data at byte " + std::to_string(body_offset);
  if (body_bytes < 8) {
    fail(path,
         "truncated: binary_compressed data needs an 8-byte size prefix, " +
             std::to_string(body_bytes) + " bytes follow",
         data_where);
  }
  const std::uint64_t compressed = readLittleEndianU32(path, body_offset);
  const std::uint64_t uncompressed = readLittleEndianU32(path, body_offset + 4);
  if (uncompressed != needed) {
    fail(path,
         "corrupt: binary_compressed data says " + std::to_string(uncompressed) +
             " uncompressed bytes, header declares " + std::to_string(points) + " points needing " +
             std::to_string(needed),
         data_where);
  }
  // LZF's largest expansion is a 3-byte back reference copying 264 bytes: 88 times. A declared
  // size beyond that is a lie that PCL would allocate before finding out (8.4 GB for 188 bytes).
  if (uncompressed > saturatingMul(compressed, kLzfMaxExpansion)) {
    fail(path,
         "corrupt: binary_compressed data says " + std::to_string(compressed) +
             " compressed bytes expand to " + std::to_string(uncompressed) +
             ", more than LZF's largest ratio (" + std::to_string(kLzfMaxExpansion) + "x) allows",
         data_where);
  }
  if (body_bytes - 8 < compressed) {
    fail(path,
         "truncated: header declares " + std::to_string(compressed) +
             " bytes of compressed data, but " + std::to_string(body_bytes - 8) + " bytes follow",
         data_where);
  }
  // PCL says no more than that its reader rejected a stream that does not expand to that size.
  checkLzfStream(path, body_offset + 8, compressed, uncompressed);
}

}  // namespace

// PCD: https://pointclouds.org/documentation/tutorials/pcd_file_format.html
// Returns the declared number of points after checking the file can hold them.
std::uint64_t checkPcdHeader(const fs::path& path, std::uint64_t file_size) {
  const std::string head = readHead(path, file_size);  // the lines' words point into it
  std::uint64_t body_offset = 0;
  const std::vector<HeaderLine> lines = headerLines(path, head, "DATA", body_offset);
  const PcdLines by_keyword = pcdLinesByKeyword(path, lines);
  std::uint64_t point_bytes = 0;
  AsciiElement point_layout = pcdPointLayout(path, by_keyword, point_bytes);
  const std::uint64_t points = pcdPointCount(path, by_keyword);
  requireFloatXyz(path, point_layout);

  const HeaderLine& data = pcdRequired(path, by_keyword, "DATA");
  const std::string_view encoding = data.words.size() == 2 ? data.words[1] : "";
  const std::uint64_t body_bytes = file_size - body_offset;
  const std::uint64_t needed = saturatingMul(points, point_bytes);
  if (encoding == "ascii") {
    // PCL reads one point per line, keeps 0 for a value it cannot parse and, we found, accepts a
    // short last line: every line is checked (codegen/ascii_body.h). A cut inside the very last
    // number stays undetectable in ascii.
    point_layout.count = points;
    checkAsciiBody(path, body_offset, lines.back().number + 1, {point_layout});
  } else if (encoding == "binary") {
    if (body_bytes < needed) {
      fail(path,
           "truncated: header declares " + std::to_string(points) + " points needing " +
               std::to_string(needed) + " bytes of binary data, but " + std::to_string(body_bytes) +
               " bytes follow",
           "data at byte " + std::to_string(body_offset));
    }
  } else if (encoding == "binary_compressed") {
    checkPcdCompressedBody(path, body_offset, body_bytes, points, needed);
  } else {
    fail(path,
         "PCD DATA is '" + printable(encoding) + "', expected ascii, binary or binary_compressed",
         "header line " + std::to_string(data.number));
  }
  return points;
}

namespace {

// A PLY scalar type's kind and size; size 0 for an unknown type.
ValueType plyType(std::string_view type) {
  static const std::map<std::string_view, ValueType> kTypes = {
      {"char", {'I', 1}},  {"uchar", {'U', 1}},   {"int8", {'I', 1}},   {"uint8", {'U', 1}},
      {"short", {'I', 2}}, {"ushort", {'U', 2}},  {"int16", {'I', 2}},  {"uint16", {'U', 2}},
      {"int", {'I', 4}},   {"uint", {'U', 4}},    {"int32", {'I', 4}},  {"uint32", {'U', 4}},
      {"float", {'F', 4}}, {"float32", {'F', 4}}, {"double", {'F', 8}}, {"float64", {'F', 8}}};
  const auto found = kTypes.find(type);
  return found == kTypes.end() ? ValueType{'F', 0} : found->second;
}

}  // namespace

std::uint64_t plyTypeBytes(std::string_view type) { return plyType(type).size; }

namespace {

// One PLY element as declared: its name, its count and the least one item takes.
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t min_bytes = 0;   // binary size of one element with empty lists
  std::uint64_t min_tokens = 0;  // ascii words of one element with empty lists
};

// The PLY header's format and elements (and the same elements as an ascii layout, for checking
// ascii data lines).
struct PlyHeader {
  std::string format;
  std::vector<PlyElement> elements;
  std::vector<AsciiElement> ascii_layout;
};

// Adds a property line to the last element declared: its least size (a list's count alone).
void addPlyProperty(const fs::path& path, const HeaderLine& line, const std::string& where,
                    PlyHeader& header) {
  if (header.elements.empty()) fail(path, "PLY property before any element", where);
  const bool list = line.words.size() == 5 && line.words[1] == "list";
  const ValueType count_type = list ? plyType(line.words[2]) : ValueType{};
  const ValueType type =
      list ? plyType(line.words[3]) : plyType(line.words.size() == 3 ? line.words[1] : "");
  const std::uint64_t bytes =
      list ? (type.size != 0 && count_type.kind != 'F' ? count_type.size : 0) : type.size;
  if (bytes == 0) fail(path, "PLY property line with an unknown type or shape", where);
  header.ascii_layout.back().properties.push_back(
      {std::string(line.words.back()), type, 1, list, count_type, line.number});
  header.elements.back().min_bytes += bytes;
  header.elements.back().min_tokens += 1;
}

// Fails on a line PLY does not have, a bad format, element or property line, or no format line.
PlyHeader parsePlyHeader(const fs::path& path, const std::vector<HeaderLine>& lines) {
  PlyHeader header;
  for (const HeaderLine& line : lines) {
    const std::string where = "header line " + std::to_string(line.number);
    if (line.words.empty()) continue;
    const std::string_view keyword = line.words[0];
    if (keyword == "ply" || keyword == "comment" || keyword == "obj_info" ||
        keyword == "end_header") {
      continue;
    }
    if (keyword == "format") {
      if (line.words.size() != 3 ||
          (line.words[1] != "ascii" && line.words[1] != "binary_little_endian" &&
           line.words[1] != "binary_big_endian")) {
        fail(path, "PLY format line is not ascii/binary_little_endian/binary_big_endian", where);
      }
      header.format = line.words[1];
    } else if (keyword == "element") {
      const auto count = line.words.size() == 3 ? parseUnsigned(line.words[2]) : std::nullopt;
      if (!count) fail(path, "PLY element line without a non-negative count", where);
      header.elements.push_back({std::string(line.words[1]), *count, 0, 0});
      header.ascii_layout.push_back(
          {std::string(line.words[1]), cli::inQuotes(line.words[1]) + " items", *count, {}});
    } else if (keyword == "property") {
      addPlyProperty(path, line, where, header);
    } else {
      fail(path, "not a PLY header: unknown keyword '" + printable(keyword) + "'", where);
    }
  }
  if (header.format.empty()) fail(path, "PLY header has no format line", "header");
  return header;
}

// The vertex count, after checking every element's count is bounded by what its items take and
// the vertices are some and within what PCL can hold.
std::uint64_t plyVertexCount(const fs::path& path, const std::vector<PlyElement>& elements) {
  for (const PlyElement& element : elements) {
    // Items without properties take no bytes, so nothing would bound their count: PCL spent 6 s
    // iterating over "element face 4000000000" without properties.
    if (element.count > 0 && element.min_tokens == 0) {
      fail(path,
           "PLY element '" + printable(element.name) + "' has " + std::to_string(element.count) +
               " items but no properties",
           "header");
    }
  }
  const auto vertex = std::find_if(elements.begin(), elements.end(),
                                   [](const PlyElement& e) { return e.name == "vertex"; });
  if (vertex == elements.end()) fail(path, "PLY header declares no vertex element", "header");
  if (vertex->count == 0) fail(path, "empty cloud (0 points)", "PLY header element vertex");
  if (vertex->count > kMaxPoints) {
    fail(path,
         "PLY declares " + std::to_string(vertex->count) + " vertices, more than PCL can hold",
         "header element vertex");
  }
  return vertex->count;
}

}  // namespace

// PLY: http://paulbourke.net/dataformats/ply/
// Returns the declared vertex count after checking the body can hold every declared element
// (lists counted at their smallest, zero items, which still bounds what PCL may allocate).
std::uint64_t checkPlyHeader(const fs::path& path, std::uint64_t file_size) {
  const std::string head = readHead(path, file_size);  // the lines' words point into it
  if (head.rfind("ply\n", 0) != 0 && head.rfind("ply\r\n", 0) != 0) {
    fail(path, "not a PLY file: it does not start with the line 'ply'", "byte 0");
  }
  std::uint64_t body_offset = 0;
  const std::vector<HeaderLine> lines = headerLines(path, head, "end_header", body_offset);
  const PlyHeader header = parsePlyHeader(path, lines);
  const std::uint64_t vertices = plyVertexCount(path, header.elements);
  for (const AsciiElement& element : header.ascii_layout) {
    checkPlyProperties(path, element);
    if (element.name == "vertex") requireFloatXyz(path, element);
  }

  if (header.format == "ascii") {
    // Every line is checked, and counted against each element's items (codegen/ascii_body.h).
    checkAsciiBody(path, body_offset, lines.back().number + 1, header.ascii_layout);
    return vertices;
  }
  std::uint64_t needed = 0;
  for (const PlyElement& element : header.elements)
    needed = saturatingAdd(needed, saturatingMul(element.count, element.min_bytes));
  const std::uint64_t body_bytes = file_size - body_offset;
  if (body_bytes < needed) {
    fail(path,
         "truncated: header declares " + std::to_string(vertices) +
             " vertices and other elements needing at least " + std::to_string(needed) +
             " bytes of binary data, but " + std::to_string(body_bytes) + " bytes follow",
         "data at byte " + std::to_string(body_offset));
  }
  return vertices;
}

HeaderWords readHeaderWords(const fs::path& path, std::uint64_t file_size,
                            std::string_view last_keyword) {
  HeaderWords words;
  const std::string head = readHead(path, file_size);  // the lines' words point into it
  for (const HeaderLine& line : headerLines(path, head, last_keyword, words.body_offset)) {
    words.lines.emplace_back(line.words.begin(), line.words.end());
  }
  return words;
}

}  // namespace octopoint::prepare
