// LAS header checks and point decoding (codegen/las_reader.h). Layouts from the ASPRS LAS 1.4
// specification (R15): the public header block is 227 bytes in 1.0 to 1.2, 235 in 1.3 (start of
// the waveform data packet record) and 375 in 1.4 (EVLRs and the 64-bit point counts); a VLR header
// is 54 bytes with a 16-bit payload length, an EVLR header 60 bytes with a 64-bit one.

#include "codegen/las_reader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "codegen/laz_reader.h"
#include "codegen/little_endian.h"
#include "codegen/scan_header_check.h"

namespace octopoint::prepare {
namespace {

constexpr std::uint64_t kVlrHeaderBytes = 54;
constexpr std::uint64_t kEvlrHeaderBytes = 60;
constexpr std::uint64_t kSignatureBytes = 4;
constexpr std::uint64_t kLegacyHeaderBytes = 227;  // 1.0 to 1.2
constexpr std::array<std::uint64_t, 5> kHeaderBytes = {227, 227, 227, 235,
                                                       375};  // by minor version
// Offsets of the red channel in the formats that have colour (0 = none).
constexpr std::array<std::uint16_t, 11> kRgbOffset = {0, 0, 20, 28, 0, 28, 0, 30, 30, 0, 30};
// LASzip marks compressed point data in the format byte (bit 7; bit 6 for its 1.4 "native" layers)
// and describes it in a VLR of this user ID and record ID.
constexpr std::uint8_t kLazFormatBits = 0xc0;
constexpr std::string_view kLazVlrUser = "laszip encoded";
constexpr std::uint16_t kLazVlrRecord = 22204;
constexpr std::string_view kCopcVlrUser = "copc";
constexpr std::uint16_t kCopcInfoRecord = 1;

std::string byteWhere(std::uint64_t offset) { return "header byte " + std::to_string(offset); }

// A small read window over the file for walking the header records, so that thousands of tiny VLRs
// cost one read per 64 KiB rather than one per record.
class ByteWindow {
 public:
  explicit ByteWindow(const InputFile& file) : file_(file) {}

  // `n` (at most kWindow) bytes at `offset`, which the caller has checked lie inside the file.
  const std::uint8_t* at(std::uint64_t offset, std::size_t n, const std::string& what) {
    if (offset < start_ || offset + n > start_ + bytes_.size()) {
      const std::uint64_t length = std::min<std::uint64_t>(kWindow, file_.size() - offset);
      bytes_.resize(static_cast<std::size_t>(length));
      file_.readAt(offset, bytes_, what);
      start_ = offset;
    }
    return bytes_.data() + (offset - start_);
  }

 private:
  static constexpr std::size_t kWindow = 1 << 16;
  const InputFile& file_;
  std::vector<std::uint8_t> bytes_;
  std::uint64_t start_ = 0;
};

void checkScaleAndOffset(const InputFile& file, const LasHeader& header) {
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const double scale = header.scale[axis];
    const double offset = header.offset[axis];
    const char name = "XYZ"[axis];
    if (!(scale >= kMinLasScale && scale <= kMaxLasScale)) {  // also refuses NaN
      std::ostringstream what;
      what << "absurd " << name << " scale factor " << scale << " (expected " << kMinLasScale
           << " to " << kMaxLasScale << ")";
      fail(file.path(), what.str(), byteWhere(131 + 8 * axis));
    }
    if (!(std::fabs(offset) <= kMaxLasOffset)) {
      std::ostringstream what;
      what << "absurd " << name << " offset " << offset << " (expected a finite value within +-"
           << kMaxLasOffset << ")";
      fail(file.path(), what.str(), byteWhere(155 + 8 * axis));
    }
  }
}

// Walks the VLRs between the header and the point data; notes LASzip's.
void walkVlrs(const InputFile& file, ByteWindow& window, std::uint64_t header_bytes,
              LasHeader& header) {
  const std::uint64_t room = header.point_offset - header_bytes;
  if (header.vlr_count > room / kVlrHeaderBytes) {
    fail(file.path(),
         "header declares " + std::to_string(header.vlr_count) + " VLRs, but only " +
             std::to_string(room) + " bytes lie between the header and the point data",
         byteWhere(100));
  }
  std::uint64_t at = header_bytes;
  for (std::uint32_t i = 0; i < header.vlr_count; ++i) {
    const std::string where = "VLR " + std::to_string(i + 1) + " of " +
                              std::to_string(header.vlr_count) + " at byte " + std::to_string(at);
    if (at + kVlrHeaderBytes > header.point_offset) {
      fail(file.path(),
           "VLR header runs into the point data at byte " + std::to_string(header.point_offset),
           where);
    }
    const std::uint8_t* record = window.at(at, kVlrHeaderBytes, where);
    const std::string_view user(reinterpret_cast<const char*>(record + 2), 16);
    const std::uint64_t length = readLittle<std::uint16_t>(record + 20);
    const std::string_view user_id = user.substr(0, user.find('\0'));
    const auto record_id = readLittle<std::uint16_t>(record + 18);
    if (user_id == kLazVlrUser && record_id == kLazVlrRecord) {
      header.laszip_vlr_offset = at + kVlrHeaderBytes;
      header.laszip_vlr_bytes = static_cast<std::uint16_t>(length);
    }
    if (user_id == kCopcVlrUser && record_id == kCopcInfoRecord) {
      header.copc_vlr_offset = at + kVlrHeaderBytes;
      header.copc_vlr_bytes = static_cast<std::uint16_t>(length);
    }
    at += kVlrHeaderBytes + length;
    if (at > header.point_offset) {
      fail(file.path(),
           "VLR of " + std::to_string(length) + " bytes runs into the point data at byte " +
               std::to_string(header.point_offset),
           where);
    }
  }
}

// Walks `count` extended records (EVLRs, or the 1.3 waveform record) from `start`; returns their
// end.
std::uint64_t walkExtendedRecords(const InputFile& file, ByteWindow& window, std::uint64_t start,
                                  std::uint64_t count, const std::string& kind) {
  const std::uint64_t room = file.size() - std::min(start, file.size());
  if (start > file.size() || count > room / kEvlrHeaderBytes) {
    fail(file.path(),
         "header declares " + std::to_string(count) + " " + kind + "s from byte " +
             std::to_string(start) + ", more than the " + std::to_string(room) +
             " bytes there can hold",
         "LAS header");
  }
  std::uint64_t at = start;
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::string where = kind + " " + std::to_string(i + 1) + " of " + std::to_string(count) +
                              " at byte " + std::to_string(at);
    if (at > file.size() || file.size() - at < kEvlrHeaderBytes) {
      fail(file.path(), "truncated: the file ends inside the record header", where);
    }
    const std::uint64_t length =
        readLittle<std::uint64_t>(window.at(at, kEvlrHeaderBytes, where) + 20);
    if (length > file.size() - at - kEvlrHeaderBytes) {
      fail(file.path(),
           "truncated: the record declares " + std::to_string(length) + " bytes, the file ends " +
               std::to_string(file.size() - at - kEvlrHeaderBytes) + " bytes after its header",
           where);
    }
    at += kEvlrHeaderBytes + length;
  }
  return at;
}

// The point format must be one LAS has, allowed by the file's version, and its records long
// enough for it.
void checkPointFormat(const std::filesystem::path& path, const LasHeader& header) {
  const int minor = header.version_minor;
  if (header.point_format >= static_cast<int>(kLasFormatBytes.size())) {
    fail(path, "unknown point format " + std::to_string(header.point_format) + " (LAS has 0 to 10)",
         byteWhere(104));
  }
  if (header.point_format > 5 && minor < 4) {
    fail(path,
         "point format " + std::to_string(header.point_format) +
             " needs LAS 1.4, the file is LAS 1." + std::to_string(minor),
         byteWhere(104));
  }
  const std::uint16_t needed = kLasFormatBytes[static_cast<std::size_t>(header.point_format)];
  if (header.record_length < needed) {
    fail(path,
         "point records of " + std::to_string(header.record_length) +
             " bytes are shorter than format " + std::to_string(header.point_format) + "'s " +
             std::to_string(needed),
         byteWhere(105));
  }
}

// Reads the fixed part of the header; fails on what it alone can tell.
LasHeader readFixedHeader(const InputFile& file, std::vector<std::uint8_t>& head,
                          std::uint64_t& header_bytes) {
  const auto& path = file.path();
  const std::uint64_t size = file.size();
  head.assign(static_cast<std::size_t>(std::min<std::uint64_t>(size, kHeaderBytes.back())), 0);
  file.readAt(0, head, "LAS header");
  if (size < kSignatureBytes || std::memcmp(head.data(), "LASF", kSignatureBytes) != 0) {
    fail(path, "not a LAS file: it does not start with 'LASF'", "byte 0");
  }
  if (size < kLegacyHeaderBytes) {
    fail(path, "truncated: a LAS header has at least 227 bytes, the file " + std::to_string(size),
         "LAS header");
  }
  const int major = head[24];
  const int minor = head[25];
  if (major != 1 || minor > 4) {
    fail(path,
         "LAS version " + std::to_string(major) + "." + std::to_string(minor) +
             " is not supported (1.0 to 1.4)",
         byteWhere(24));
  }
  const std::uint8_t format_byte = head[104];
  LasHeader header;
  header.version_minor = minor;
  header.compressed = (format_byte & kLazFormatBits) != 0;
  header.point_format = format_byte & ~kLazFormatBits;
  header_bytes = readLittle<std::uint16_t>(&head[94]);
  const std::uint64_t minimum = kHeaderBytes[static_cast<std::size_t>(minor)];
  if (header_bytes < minimum) {
    fail(path,
         "header size " + std::to_string(header_bytes) + " is below LAS 1." +
             std::to_string(minor) + "'s " + std::to_string(minimum) + " bytes",
         byteWhere(94));
  }
  if (size < minimum) {
    fail(path,
         "truncated: a LAS 1." + std::to_string(minor) + " header has " + std::to_string(minimum) +
             " bytes, the file " + std::to_string(size),
         "LAS header");
  }
  header.record_length = readLittle<std::uint16_t>(&head[105]);
  checkPointFormat(path, header);
  header.rgb_offset = kRgbOffset[static_cast<std::size_t>(header.point_format)];
  header.point_offset = readLittle<std::uint32_t>(&head[96]);
  header.vlr_count = readLittle<std::uint32_t>(&head[100]);
  for (std::size_t axis = 0; axis < 3; ++axis) {
    header.scale[axis] = readLittle<double>(&head[131 + 8 * axis]);
    header.offset[axis] = readLittle<double>(&head[155 + 8 * axis]);
    header.stated_high[axis] = readLittle<double>(&head[179 + 16 * axis]);
    header.stated_low[axis] = readLittle<double>(&head[187 + 16 * axis]);
  }
  const std::uint64_t legacy_count = readLittle<std::uint32_t>(&head[107]);
  header.point_count = legacy_count;
  if (minor >= 4) {
    header.point_count = readLittle<std::uint64_t>(&head[247]);
    header.evlr_count = readLittle<std::uint32_t>(&head[243]);
    if (legacy_count != 0 && legacy_count != header.point_count) {
      fail(path,
           "the legacy point count " + std::to_string(legacy_count) +
               " differs from the 1.4 point count " + std::to_string(header.point_count),
           byteWhere(107));
    }
  }
  return header;
}

// The point data must start after the header and within the file.
void checkPointOffset(const InputFile& file, const LasHeader& header, std::uint64_t header_bytes) {
  const auto& path = file.path();
  if (header.point_offset < header_bytes) {
    fail(path,
         "the point data at byte " + std::to_string(header.point_offset) +
             " would start inside the " + std::to_string(header_bytes) + "-byte header",
         byteWhere(96));
  }
  if (header.point_offset > file.size()) {
    fail(path,
         "truncated: the point data should start at byte " + std::to_string(header.point_offset) +
             ", the file has " + std::to_string(file.size()) + " bytes",
         byteWhere(96));
  }
}

// Where the point data ends, after checking the file holds every point the header declares.
std::uint64_t pointDataEnd(const InputFile& file, const LasHeader& header) {
  const std::uint64_t point_bytes = saturatingMul(header.point_count, header.record_length);
  const std::uint64_t available = file.size() - header.point_offset;
  if (point_bytes > available) {
    fail(file.path(),
         "truncated: header declares " + std::to_string(header.point_count) + " points of " +
             std::to_string(header.record_length) + " bytes, but " + std::to_string(available) +
             " bytes follow the start of the point data",
         "point data at byte " + std::to_string(header.point_offset));
  }
  return header.point_offset + point_bytes;
}

// Where the EVLRs (or LAS 1.3's waveform record) end, at least `points_end`, after checking they
// start after the points with nothing between.
std::uint64_t extendedRecordsEnd(const InputFile& file, ByteWindow& window,
                                 const std::vector<std::uint8_t>& head, const LasHeader& header,
                                 std::uint64_t points_end) {
  const auto& path = file.path();
  std::uint64_t accounted_end = points_end;
  if (header.evlr_count > 0) {
    const std::uint64_t evlr_start = readLittle<std::uint64_t>(&head[235]);
    if (evlr_start < points_end) {
      fail(path,
           "the first EVLR at byte " + std::to_string(evlr_start) +
               " lies inside the point data, which ends at byte " + std::to_string(points_end),
           byteWhere(235));
    }
    if (evlr_start - points_end >=
        header.record_length) {  // a count too small, like trailing bytes below
      fail(path,
           std::to_string(evlr_start - points_end) + " bytes lie between the last of the " +
               std::to_string(header.point_count) +
               " points and the first EVLR: the point count is too small?",
           "byte " + std::to_string(points_end));
    }
    accounted_end = std::max(
        accounted_end, walkExtendedRecords(file, window, evlr_start, header.evlr_count, "EVLR"));
  }
  const std::uint16_t global_encoding = readLittle<std::uint16_t>(&head[6]);
  const std::uint64_t waveform_start =
      header.version_minor >= 3 ? readLittle<std::uint64_t>(&head[227]) : 0;
  if (header.version_minor == 3 && (global_encoding & 2u) &&
      waveform_start != 0) {  // 1.4: one of the EVLRs
    if (waveform_start < points_end) {
      fail(path,
           "the waveform data at byte " + std::to_string(waveform_start) +
               " lies inside the point data",
           byteWhere(227));
    }
    accounted_end = std::max(
        accounted_end, walkExtendedRecords(file, window, waveform_start, 1, "waveform record"));
  }
  return accounted_end;
}

// LAZ: where the compressed point data ends (the first EVLR, else the end of the file), after
// checking that LASzip's VLR is there and walking the EVLRs. The chunk table is the LAZ reader's.
std::uint64_t compressedPointsEnd(const InputFile& file, ByteWindow& window,
                                  const std::vector<std::uint8_t>& head, const LasHeader& header) {
  if (header.laszip_vlr_offset == 0) {
    fail(file.path(),
         "the point format byte says LAZ (compressed), but no LASzip VLR (\"laszip encoded\") "
         "describes the compression",
         byteWhere(104));
  }
  if (header.evlr_count == 0) return file.size();
  const std::uint64_t evlr_start = readLittle<std::uint64_t>(&head[235]);
  if (evlr_start < header.point_offset || evlr_start > file.size()) {
    fail(file.path(),
         "the first EVLR at byte " + std::to_string(evlr_start) + " lies outside the point data (" +
             std::to_string(header.point_offset) + " to " + std::to_string(file.size()) + ")",
         byteWhere(235));
  }
  walkExtendedRecords(file, window, evlr_start, header.evlr_count, "EVLR");
  return evlr_start;
}

}  // namespace

LasHeader readLasHeader(const InputFile& file) {
  const auto& path = file.path();
  const std::uint64_t size = file.size();
  std::vector<std::uint8_t> head;
  std::uint64_t header_bytes = 0;
  LasHeader header = readFixedHeader(file, head, header_bytes);
  checkPointOffset(file, header, header_bytes);
  ByteWindow window(file);
  walkVlrs(file, window, header_bytes, header);
  if (header.point_count == 0) fail(path, "empty cloud (0 points)", "LAS header point count");
  checkScaleAndOffset(file, header);
  if (header.compressed) {
    header.points_end = compressedPointsEnd(file, window, head, header);
    return header;
  }
  const std::uint64_t points_end = pointDataEnd(file, header);
  header.points_end = points_end;
  const std::uint64_t accounted_end = extendedRecordsEnd(file, window, head, header, points_end);
  // A count too small (a 1.2 file past 2^32 points, a header that lies) leaves points unread:
  // refuse rather than silently drop them. Less than one record is padding some writers add.
  if (size - accounted_end >= header.record_length) {
    fail(path,
         std::to_string(size - accounted_end) + " bytes follow the last of the " +
             std::to_string(header.point_count) +
             " points the header declares, and no EVLR accounts for them",
         "byte " + std::to_string(accounted_end));
  }
  // Every point record has a return number of at least 1, so no record is all zero bytes: a hole
  // in the point data (a sparse file) is not point data.
  const std::uint64_t hole = file.nextHole(header.point_offset);
  if (hole < points_end) {
    fail(path, "the point data has a hole (a sparse file): LAS points are never all zero bytes",
         "byte " + std::to_string(hole));
  }
  return header;
}

namespace {

// The coordinate of the record nearest to `stated` on its axis's grid (int32 * scale + offset),
// or nullopt past the int32 range or not a number. A writer that took the box from its points
// before rounding them to the grid (to nearest) gives the extreme records' coordinates too.
std::optional<double> snapped(double stated, double scale, double offset) {
  const double raw = std::round((stated - offset) / scale);
  if (!(raw >= std::numeric_limits<std::int32_t>::min() &&
        raw <= std::numeric_limits<std::int32_t>::max())) {
    return std::nullopt;
  }
  return lasCoordinate(static_cast<std::int32_t>(raw), scale, offset);
}

// The header's box snapped to the records' grid, when it is one: every axis low <= high and
// inside the int32 grid (a header of zeros is one of no volume, which the preparer does not try).
std::optional<HeaderBox> headerBox(const LasHeader& header) {
  HeaderBox box;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const auto low = snapped(header.stated_low[axis], header.scale[axis], header.offset[axis]);
    const auto high = snapped(header.stated_high[axis], header.scale[axis], header.offset[axis]);
    if (!low || !high || *low > *high) return std::nullopt;
    box.low[axis] = *low;
    box.high[axis] = *high;
  }
  return box;
}

}  // namespace

SourceInfo lasSourceInfo(const LasHeader& header) {
  SourceInfo info;
  info.header_box = headerBox(header);
  info.intensity_16bit = true;
  info.points = header.point_count;
  info.payload = header.rgb_offset ? PointPayload::kRgb : PointPayload::kIntensity;
  info.shading = header.rgb_offset ? ScanShading::kColour : ScanShading::kIntensity;
  info.colour_bits_detected = header.rgb_offset != 0;
  info.has_intensity = true;
  info.float_coordinates = false;
  info.compressed = header.compressed;
  info.format = std::string(header.compressed ? "LAZ" : "LAS") + " 1." +
                std::to_string(header.version_minor) + ", point format " +
                std::to_string(header.point_format) + ", " + std::to_string(header.record_length) +
                "-byte records";
  return info;
}

void decodeLasRecords(const LasHeader& header, const std::uint8_t* records, PointChunk& chunk) {
  const std::size_t stride = header.record_length;
  const std::uint8_t* record = records;
  for (std::size_t i = 0; i < chunk.xyz.size(); ++i, record += stride) {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const auto raw = readLittle<std::int32_t>(record + 4 * axis);
      chunk.xyz[i][axis] = lasCoordinate(raw, header.scale[axis], header.offset[axis]);
    }
    chunk.intensity[i] = readLittle<std::uint16_t>(record + 12);
    if (header.rgb_offset) {
      for (std::size_t ch = 0; ch < 3; ++ch) {
        chunk.rgb[i][ch] = readLittle<std::uint16_t>(record + header.rgb_offset + 2 * ch);
      }
    }
  }
}

namespace {

class LasSource final : public PointSource {
 public:
  LasSource(std::unique_ptr<InputFile> file, const LasHeader& header)
      : file_(std::move(file)), header_(header), info_(lasSourceInfo(header)) {
    file_->adviseSequential();
  }

  const SourceInfo& info() const override { return info_; }

  void read(std::uint64_t first, std::size_t count, PointChunk& chunk) const override {
    std::vector<std::uint8_t>& bytes = chunk.raw;
    const std::size_t stride = header_.record_length;
    bytes.resize(count * stride);
    file_->readAt(header_.point_offset + first * stride, bytes, "point " + std::to_string(first));
    chunk.resize(count, info_);
    decodeLasRecords(header_, bytes.data(), chunk);
  }

 private:
  std::unique_ptr<InputFile> file_;
  LasHeader header_;
  SourceInfo info_;
};

}  // namespace

std::unique_ptr<PointSource> openLasSource(const std::filesystem::path& path, RecordFields fields) {
  auto file = std::make_unique<InputFile>(path);
  const LasHeader header = readLasHeader(*file);
  if (header.compressed) return openLazSource(std::move(file), header, fields);
  return std::make_unique<LasSource>(std::move(file), header);
}

}  // namespace octopoint::prepare
