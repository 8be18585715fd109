// Binary PCD and binary PLY files (either byte order) of a plain layout, streamed in chunks without
// PCL:
// fixed-size records at a known offset, float32 x/y/z, and the colour or intensity field exactly as
// scan_loader.cpp picks it through PCL (PCD: "rgb" (float32 or uint32), else "rgba" (uint32), else
// a float32 "intensity"; PLY: uchar red/green/blue, else a float "intensity"). Anything else
// (ascii, binary_compressed, lists or other elements before the vertices, other field
// types, ambiguous fields) returns null and goes through PCL, which either reads it or says what is
// wrong. tests/preparer/streamed_prepare_test.cpp checks that both readers give the same points.

#include "codegen/binary_scan_source.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "codegen/file_io.h"
#include "codegen/scan_header_check.h"

namespace octopoint::prepare {
namespace {

// Where the fields the preparer reads sit inside one record.
struct RecordLayout {
  std::uint64_t body_offset = 0;
  std::uint64_t stride = 0;
  std::uint64_t points = 0;
  std::size_t xyz[3] = {};
  std::optional<std::size_t> rgb;        // 4 bytes, 0x??RRGGBB little-endian (PCD)
  std::optional<std::size_t> rgb_bytes;  // three bytes red, green, blue (PLY)
  std::optional<std::size_t> intensity;  // float32
  bool organized = false;
  bool big_endian = false;  // a binary_big_endian PLY: every float32 byte-swapped
};

struct Field {
  std::string type;  // PCD: F/I/U + size, e.g. "F4"; PLY: the type name
  std::uint64_t bytes = 0;
  std::size_t offset = 0;
};

// The named fields, or nullopt when a name repeats (PCL's choice would then be a guess).
std::optional<std::map<std::string, Field>> uniqueFields(
    const std::vector<std::pair<std::string, Field>>& list) {
  std::map<std::string, Field> fields;
  for (const auto& [name, field] : list) {
    if (name != "_" && !fields.emplace(name, field).second)
      return std::nullopt;  // "_" pads PCD records
  }
  return fields;
}

bool is(const std::map<std::string, Field>& fields, const char* name,
        std::initializer_list<const char*> types) {
  const auto found = fields.find(name);
  return found != fields.end() && std::any_of(types.begin(), types.end(), [&](const char* t) {
           return found->second.type == t;
         });
}

std::optional<RecordLayout> pcdLayout(const std::filesystem::path& path, std::uint64_t file_size) {
  const HeaderWords header = readHeaderWords(path, file_size, "DATA");
  std::map<std::string, std::vector<std::string>> by_keyword;
  for (const auto& words : header.lines) {
    if (!words.empty() && words[0][0] != '#') by_keyword[words[0]] = words;
  }
  if (by_keyword["DATA"].size() != 2 || by_keyword["DATA"][1] != "binary") return std::nullopt;
  const auto& names = by_keyword["FIELDS"];
  const auto& sizes = by_keyword["SIZE"];
  const auto& types = by_keyword["TYPE"];
  const auto& counts = by_keyword["COUNT"];
  std::vector<std::pair<std::string, Field>> list;
  std::size_t offset = 0;
  for (std::size_t f = 1; f < names.size(); ++f) {  // checkPcdHeader has matched the lines' lengths
    const std::uint64_t size = std::stoull(sizes[f]);
    const std::uint64_t count = counts.empty() ? 1 : std::stoull(counts[f]);
    list.push_back({names[f], {count == 1 ? types[f] + sizes[f] : "array", size * count, offset}});
    offset += static_cast<std::size_t>(size * count);
  }
  const auto fields = uniqueFields(list);
  if (!fields) return std::nullopt;
  RecordLayout layout;
  layout.body_offset = header.body_offset;
  layout.stride = offset;
  layout.points = std::stoull(by_keyword["POINTS"][1]);
  layout.organized = std::stoull(by_keyword["HEIGHT"][1]) > 1;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const char* name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
    if (!is(*fields, name, {"F4"})) return std::nullopt;
    layout.xyz[axis] = fields->at(name).offset;
  }
  if (fields->count("rgb") && fields->count("rgba")) return std::nullopt;
  if (fields->count("rgb") || fields->count("rgba")) {
    const bool usable = is(*fields, "rgb", {"F4", "U4"}) || is(*fields, "rgba", {"U4"});
    if (!usable) return std::nullopt;
    layout.rgb = fields->count("rgb") ? fields->at("rgb").offset : fields->at("rgba").offset;
  } else if (fields->count("intensity")) {
    if (!is(*fields, "intensity", {"F4"})) return std::nullopt;
    layout.intensity = fields->at("intensity").offset;
  }
  return layout;
}

std::optional<RecordLayout> plyLayout(const std::filesystem::path& path, std::uint64_t file_size) {
  const HeaderWords header = readHeaderWords(path, file_size, "end_header");
  std::vector<std::pair<std::string, Field>> list;
  std::size_t offset = 0;
  bool in_vertex = false;
  bool seen_element = false;
  RecordLayout layout;
  for (const auto& words : header.lines) {
    if (words.empty()) continue;
    // PCL reads big-endian PLY too, but through a per-value callback: a 1 GiB file took 23 s and
    // 3.5 GB to read whole (and as long to refuse when its points were all alike); streamed it
    // costs what a little-endian one does.
    if (words[0] == "format") {
      if (words.size() != 3 ||
          (words[1] != "binary_little_endian" && words[1] != "binary_big_endian"))
        return std::nullopt;
      layout.big_endian = words[1] == "binary_big_endian";
    }
    if (words[0] == "element") {
      if (!seen_element && (words.size() != 3 || words[1] != "vertex"))
        return std::nullopt;  // vertices first
      in_vertex = !seen_element;
      if (in_vertex) layout.points = std::stoull(words[2]);
      seen_element = true;
    } else if (words[0] == "property" && in_vertex) {
      if (words.size() != 3) return std::nullopt;  // a list, or something PCL may read otherwise
      const std::uint64_t bytes = plyTypeBytes(words[1]);
      list.push_back({words[2], {words[1], bytes, offset}});
      offset += static_cast<std::size_t>(bytes);
    }
  }
  const auto fields = uniqueFields(list);
  if (!fields || fields->count("rgb") || fields->count("rgba")) return std::nullopt;
  layout.body_offset = header.body_offset;
  layout.stride = offset;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const char* name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
    if (!is(*fields, name, {"float", "float32"})) return std::nullopt;
    layout.xyz[axis] = fields->at(name).offset;
  }
  const bool any_colour = fields->count("red") || fields->count("green") || fields->count("blue");
  if (any_colour) {
    const std::size_t red = fields->count("red") ? fields->at("red").offset : 0;
    for (const char* channel : {"red", "green", "blue"}) {
      if (!is(*fields, channel, {"uchar", "uint8"})) return std::nullopt;
    }
    if (fields->at("green").offset != red + 1 || fields->at("blue").offset != red + 2)
      return std::nullopt;
    if (fields->count("alpha") && !is(*fields, "alpha", {"uchar", "uint8"})) return std::nullopt;
    layout.rgb_bytes = red;
  } else if (fields->count("intensity")) {
    if (!is(*fields, "intensity", {"float", "float32"})) return std::nullopt;
    layout.intensity = fields->at("intensity").offset;
  }
  return layout;
}

class BinaryScanSource final : public PointSource {
 public:
  BinaryScanSource(const std::filesystem::path& path, const RecordLayout& layout,
                   const char* format)
      : file_(path), layout_(layout) {
    info_.points = layout.points;
    info_.payload = layout.rgb || layout.rgb_bytes ? PointPayload::kRgb
                    : layout.intensity             ? PointPayload::kIntensity
                                                   : PointPayload::kNone;
    info_.shading = info_.payload == PointPayload::kRgb         ? ScanShading::kColour
                    : info_.payload == PointPayload::kIntensity ? ScanShading::kIntensity
                                                                : ScanShading::kNone;
    info_.coordinate_limit = kMaxAbsCoordinate;
    info_.organized = layout.organized;
    info_.format = format;
    file_.adviseSequential();
  }

  const SourceInfo& info() const override { return info_; }

  void read(std::uint64_t first, std::size_t count, PointChunk& chunk) const override {
    std::vector<std::uint8_t>& bytes = chunk.raw;
    const std::size_t stride = static_cast<std::size_t>(layout_.stride);
    bytes.resize(count * stride);
    file_.readAt(layout_.body_offset + first * stride, bytes, "point " + std::to_string(first));
    chunk.resize(count, info_);
    const std::uint8_t* record = bytes.data();
    for (std::size_t i = 0; i < count; ++i, record += stride) {
      for (std::size_t axis = 0; axis < 3; ++axis)
        chunk.xyz[i][axis] = floatAt(record + layout_.xyz[axis], layout_.big_endian);
      if (layout_.rgb) {
        std::uint32_t packed;
        std::memcpy(&packed, record + *layout_.rgb, 4);
        chunk.rgb[i] = {static_cast<std::uint16_t>(packed >> 16 & 0xffu),
                        static_cast<std::uint16_t>(packed >> 8 & 0xffu),
                        static_cast<std::uint16_t>(packed & 0xffu)};
      } else if (layout_.rgb_bytes) {
        const std::uint8_t* rgb = record + *layout_.rgb_bytes;
        chunk.rgb[i] = {rgb[0], rgb[1], rgb[2]};
      } else if (layout_.intensity) {
        chunk.intensity[i] = floatAt(record + *layout_.intensity, layout_.big_endian);
      }
    }
  }

 private:
  static float floatAt(const std::uint8_t* bytes, bool big_endian) {
    static_assert(std::endian::native == std::endian::little);
    std::uint32_t word;
    std::memcpy(&word, bytes, sizeof word);
    return std::bit_cast<float>(big_endian ? __builtin_bswap32(word) : word);
  }

  InputFile file_;
  RecordLayout layout_;
  SourceInfo info_;
};

}  // namespace

std::unique_ptr<PointSource> openBinaryScanSource(const std::filesystem::path& path,
                                                  std::uint64_t file_size, bool is_ply) {
  const std::optional<RecordLayout> layout =
      is_ply ? plyLayout(path, file_size) : pcdLayout(path, file_size);
  if (!layout || layout->stride == 0) return nullptr;
  return std::make_unique<BinaryScanSource>(path, *layout, is_ply ? "binary PLY" : "binary PCD");
}

}  // namespace octopoint::prepare
