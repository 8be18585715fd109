#include "tests/support/las_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace octopoint::testing {
namespace {

constexpr std::array<std::uint16_t, 11> kFormatBytes = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
constexpr std::array<std::uint16_t, 11> kRgbOffset = {0, 0, 20, 28, 0, 28, 0, 30, 30, 0, 30};
constexpr std::uint16_t kVlrPayload = 16;
constexpr std::uint64_t kEvlrPayload = 24;
constexpr std::size_t kFlushBytes = 1 << 22;

// The buffers are sized before these fill them.
template <typename T>
void put(std::vector<std::uint8_t>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

void putText(std::vector<std::uint8_t>& bytes, std::size_t at, const std::string& text,
             std::size_t width) {
  std::memcpy(bytes.data() + at, text.data(), std::min(text.size(), width));
}

std::uint64_t headerBytes(int minor) { return minor <= 2 ? 227 : minor == 3 ? 235 : 375; }

// A record of the extended-record shape: reserved, user ID, record ID, length, description.
std::vector<std::uint8_t> extendedRecord(bool evlr, int index) {
  const std::size_t header = evlr ? 60 : 54;
  std::vector<std::uint8_t> record(header + (evlr ? kEvlrPayload : kVlrPayload), 0x5a);
  std::fill(record.begin(), record.begin() + 20, 0);
  putText(record, 2, "octopoint_test", 16);
  put<std::uint16_t>(record, 18, static_cast<std::uint16_t>(1000 + index));
  if (evlr) {
    put<std::uint64_t>(record, 20, kEvlrPayload);
  } else {
    put<std::uint16_t>(record, 20, kVlrPayload);
  }
  std::fill(record.begin() + static_cast<std::ptrdiff_t>(header) - 32,
            record.begin() + static_cast<std::ptrdiff_t>(header), 0);
  putText(record, header - 32, "a record the reader must skip", 32);
  return record;
}

}  // namespace

std::uint16_t LasWriter::recordLength(const LasLayout& layout) {
  return static_cast<std::uint16_t>(kFormatBytes.at(static_cast<std::size_t>(layout.format)) +
                                    layout.extra_bytes);
}

LasWriter::LasWriter(const std::filesystem::path& path, const LasLayout& layout)
    : layout_(layout), out_(path, std::ios::binary | std::ios::trunc) {
  if (!out_) throw std::runtime_error("cannot write " + path.string());
  if (layout.format < 0 || layout.format > 10 || (layout.format > 5 && layout.minor() < 4)) {
    throw std::runtime_error("point format " + std::to_string(layout.format) +
                             " cannot go in LAS 1." + std::to_string(layout.minor()));
  }
  low_.fill(std::numeric_limits<double>::infinity());
  high_.fill(-std::numeric_limits<double>::infinity());
  std::vector<std::uint8_t> head(headerBytes(layout.minor()), 0);  // patched in finish()
  for (int i = 0; i < layout.vlrs; ++i) {
    const std::vector<std::uint8_t> vlr = extendedRecord(false, i);
    head.insert(head.end(), vlr.begin(), vlr.end());
  }
  if (layout.minor() == 0)
    head.insert(head.end(), {0xdd, 0xcc});  // 1.0's point data start signature
  point_offset_ = head.size();
  out_.write(reinterpret_cast<const char*>(head.data()), static_cast<std::streamsize>(head.size()));
}

void LasWriter::add(const LandscapePoint& point) {
  const std::size_t at = buffer_.size();
  buffer_.resize(at + recordLength(layout_), 0);
  std::uint8_t* record = buffer_.data() + at;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const auto raw = static_cast<std::int32_t>(std::lround(point.xyz[axis] / layout_.scale[axis]));
    std::memcpy(record + 4 * axis, &raw, 4);
    const double stored = raw * layout_.scale[axis] + layout_.offset[axis];
    low_[axis] = std::min(low_[axis], stored);
    high_[axis] = std::max(high_[axis], stored);
  }
  std::memcpy(record + 12, &point.intensity, 2);
  record[14] = layout_.format >= 6 ? 0x11 : 0x09;  // return 1 of 1 (a return number is never 0)
  if (const std::uint16_t rgb = kRgbOffset[static_cast<std::size_t>(layout_.format)]) {
    for (std::size_t ch = 0; ch < 3; ++ch) {
      const std::uint16_t value =
          layout_.colour_16bit ? static_cast<std::uint16_t>(point.rgb[ch] * 257) : point.rgb[ch];
      std::memcpy(record + rgb + 2 * ch, &value, 2);
    }
  }
  for (int i = 0; i < layout_.extra_bytes; ++i)
    record[kFormatBytes[static_cast<std::size_t>(layout_.format)] + i] = 0xee;
  ++count_;
  if (buffer_.size() >= kFlushBytes) flush();
}

void LasWriter::flush() {
  out_.write(reinterpret_cast<const char*>(buffer_.data()),
             static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

void LasWriter::finish() {
  flush();
  using namespace las_offsets;
  const int minor = layout_.minor();
  const std::uint64_t evlr_start = point_offset_ + count_ * recordLength(layout_);
  for (int i = 0; i < layout_.evlrs; ++i) {
    const std::vector<std::uint8_t> evlr = extendedRecord(true, i);
    out_.write(reinterpret_cast<const char*>(evlr.data()),
               static_cast<std::streamsize>(evlr.size()));
  }
  std::vector<std::uint8_t> head(headerBytes(minor), 0);
  std::memcpy(head.data(), "LASF", 4);
  head[24] = 1;
  head[25] = static_cast<std::uint8_t>(minor);
  putText(head, 26, "octopoint make_large_scan", 32);
  putText(head, 58, "octopoint tests/tools", 32);
  put<std::uint16_t>(head, kHeaderSize, static_cast<std::uint16_t>(headerBytes(minor)));
  put<std::uint32_t>(head, kPointOffset, static_cast<std::uint32_t>(point_offset_));
  put<std::uint32_t>(head, kVlrCount, static_cast<std::uint32_t>(layout_.vlrs));
  head[kFormat] = static_cast<std::uint8_t>(layout_.format);
  put<std::uint16_t>(head, kRecordLength, recordLength(layout_));
  const bool legacy =
      minor < 4 || (layout_.format < 6 && count_ <= std::numeric_limits<std::uint32_t>::max());
  put<std::uint32_t>(head, kLegacyCount, legacy ? static_cast<std::uint32_t>(count_) : 0);
  put<std::uint32_t>(head, 111,
                     legacy ? static_cast<std::uint32_t>(count_) : 0);  // all first returns
  for (std::size_t axis = 0; axis < 3; ++axis) {
    put<double>(head, kScale + 8 * axis, layout_.scale[axis]);
    put<double>(head, kOffset + 8 * axis, layout_.offset[axis]);
    put<double>(head, 179 + 16 * axis, high_[axis]);
    put<double>(head, 187 + 16 * axis, low_[axis]);
  }
  if (minor >= 4) {
    put<std::uint64_t>(head, kEvlrStart, layout_.evlrs ? evlr_start : 0);
    put<std::uint32_t>(head, kEvlrCount, static_cast<std::uint32_t>(layout_.evlrs));
    put<std::uint64_t>(head, kCount, count_);
    put<std::uint64_t>(head, 255, count_);
  }
  out_.seekp(0);
  out_.write(reinterpret_cast<const char*>(head.data()), static_cast<std::streamsize>(head.size()));
  out_.close();
  if (!out_) throw std::runtime_error("writing the LAS file failed");
}

}  // namespace octopoint::testing
