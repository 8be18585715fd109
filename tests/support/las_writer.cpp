#include "tests/support/las_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "tests/support/copc_octree.h"

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

constexpr std::uint16_t kLaszipRecordId = 22204;

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
  if (layout.copc && (layout.format < 6 || layout.format > 8 || layout.minor() != 4)) {
    throw std::runtime_error("COPC holds point formats 6 to 8 of LAS 1.4");
  }
  if (layout.copc) layout_.laz_variable_chunks = true;  // each node is a chunk of its own size
  std::vector<std::uint8_t> head(headerBytes(layout.minor()), 0);  // patched in finish()
  if (layout.copc && layout.laz) {  // the COPC info VLR comes first; its payload in finish()
    std::vector<std::uint8_t> vlr(54 + 160, 0);
    putText(vlr, 2, "copc", 16);
    put<std::uint16_t>(vlr, 18, 1);
    put<std::uint16_t>(vlr, 20, 160);
    putText(vlr, 22, "COPC info", 32);
    copc_info_at_ = head.size() + 54;
    head.insert(head.end(), vlr.begin(), vlr.end());
  }
  for (int i = 0; i < layout.vlrs; ++i) {
    const std::vector<std::uint8_t> vlr = extendedRecord(false, i);
    head.insert(head.end(), vlr.begin(), vlr.end());
  }
  if (layout.laz) {  // LASzip's VLR
    laz_ = std::make_unique<LazChunkEncoder>(layout.format, layout.extra_bytes);
    const std::vector<std::uint8_t> payload =
        laz_->vlrPayload(layout_.laz_variable_chunks ? 0xffffffffu : layout.laz_chunk_points);
    std::vector<std::uint8_t> vlr(54, 0);
    putText(vlr, 2, "laszip encoded", 16);
    put<std::uint16_t>(vlr, 18, kLaszipRecordId);
    put<std::uint16_t>(vlr, 20, static_cast<std::uint16_t>(payload.size()));
    putText(vlr, 22, "octopoint tests LAZ", 32);
    head.insert(head.end(), vlr.begin(), vlr.end());
    head.insert(head.end(), payload.begin(), payload.end());
  }
  if (layout.minor() == 0)
    head.insert(head.end(), {0xdd, 0xcc});  // 1.0's point data start signature
  point_offset_ = head.size();
  if (laz_) head.resize(head.size() + 8, 0);  // where the chunk table will be, patched in finish()
  out_.write(reinterpret_cast<const char*>(head.data()), static_cast<std::streamsize>(head.size()));
}

// Variable chunks cycle through a full chunk, one of a third and one of a single point.
std::uint64_t LasWriter::nextChunkPoints() const {
  if (!layout_.laz_variable_chunks) return layout_.laz_chunk_points;
  const std::size_t kind = chunk_points_.size() % 3;
  return kind == 0 ? layout_.laz_chunk_points : kind == 1 ? layout_.laz_chunk_points / 3 + 1 : 1;
}

void LasWriter::finishLazChunk() {
  if (laz_->points() == 0) return;
  chunk_points_.push_back(laz_->points());
  const std::vector<std::uint8_t> chunk = laz_->finishChunk();
  chunk_bytes_.push_back(chunk.size());
  out_.write(reinterpret_cast<const char*>(chunk.data()),
             static_cast<std::streamsize>(chunk.size()));
}

// The last chunk, the chunk table, and the pointer to it before the first chunk.
void LasWriter::finishLaz() {
  finishLazChunk();
  const auto table_start = static_cast<std::uint64_t>(out_.tellp());
  const std::vector<std::uint8_t> table =
      lazChunkTable(chunk_points_, chunk_bytes_, layout_.laz_variable_chunks);
  out_.write(reinterpret_cast<const char*>(table.data()),
             static_cast<std::streamsize>(table.size()));
  evlr_start_ = table_start + table.size();
  out_.seekp(static_cast<std::streamoff>(point_offset_));
  out_.write(reinterpret_cast<const char*>(&table_start), 8);
  out_.seekp(0, std::ios::end);
}

// The records in the octree's order: as LAS, or as COPC (each node a chunk, then the chunk table
// and the hierarchy pages; the info VLR is patched in by finish()).
void LasWriter::finishCopc() {
  const std::size_t record_bytes = recordLength(layout_);
  const CopcOctree octree =
      buildCopcOctree(copc_records_.data(), record_bytes, static_cast<std::size_t>(count_),
                      layout_.scale, layout_.offset, low_, high_, layout_.laz_chunk_points);
  std::vector<CopcChunkPlace> places;
  for (const CopcWriterNode& node : octree.nodes) {
    const auto offset = static_cast<std::uint64_t>(out_.tellp());
    for (std::size_t i = node.first; i < node.first + node.count; ++i) {
      const std::uint8_t* record =
          copc_records_.data() + std::size_t{octree.order[i]} * record_bytes;
      if (laz_) {
        laz_->add(record);
      } else {
        out_.write(reinterpret_cast<const char*>(record),
                   static_cast<std::streamsize>(record_bytes));
      }
    }
    if (laz_) finishLazChunk();
    places.push_back({offset, static_cast<std::uint64_t>(out_.tellp()) - offset});
  }
  copc_records_ = {};
  if (!laz_) {
    evlr_start_ = static_cast<std::uint64_t>(out_.tellp());
    return;
  }
  finishLaz();
  std::uint64_t root_bytes = 0;
  copc_pages_ = copcHierarchyPages(octree, places, evlr_start_ + 60, root_bytes);
  const std::vector<std::uint8_t> info = copcInfoPayload(octree, evlr_start_ + 60, root_bytes);
  out_.seekp(static_cast<std::streamoff>(copc_info_at_));
  out_.write(reinterpret_cast<const char*>(info.data()), static_cast<std::streamsize>(info.size()));
  out_.seekp(0, std::ios::end);
}

std::uint32_t LasWriter::evlrCount() const {
  return static_cast<std::uint32_t>(layout_.evlrs + (copc_pages_.empty() ? 0 : 1));
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
  if (layout_.varied_fields) varyFields(record);
  if (const std::uint16_t rgb = kRgbOffset[static_cast<std::size_t>(layout_.format)]) {
    for (std::size_t ch = 0; ch < 3; ++ch) {
      const std::uint16_t value =
          layout_.colour_16bit ? static_cast<std::uint16_t>(point.rgb[ch] * 257) : point.rgb[ch];
      std::memcpy(record + rgb + 2 * ch, &value, 2);
    }
  }
  for (int i = 0; i < layout_.extra_bytes; ++i) {
    // varied: a byte that steps now and then, one that follows the intensity, one that is noise
    const std::uint64_t hash = (count_ * 0x9e3779b97f4a7c15ull) >> 40;
    const std::uint64_t kinds[3] = {count_ / 90, point.intensity, hash >> 3};
    record[kFormatBytes[static_cast<std::size_t>(layout_.format)] + i] =
        layout_.varied_fields ? static_cast<std::uint8_t>(kinds[i % 3] + static_cast<unsigned>(i))
                              : 0xee;
  }
  ++count_;
  if (layout_.copc) {
    copc_records_.insert(copc_records_.end(), buffer_.begin(), buffer_.end());
    buffer_.clear();
    return;
  }
  if (laz_) {
    laz_->add(record);
    buffer_.clear();
    if (laz_->points() == nextChunkPoints()) finishLazChunk();
    return;
  }
  if (buffer_.size() >= kFlushBytes) flush();
}

// Deterministic, from the point's index: runs of equal values broken now and then, as in scans.
void LasWriter::varyFields(std::uint8_t* record) const {
  const std::uint64_t i = count_;
  const std::uint64_t hash = (i * 0x9e3779b97f4a7c15ull) >> 40;
  if (layout_.format < 6) {
    const std::uint64_t returns = 1 + hash % 3;
    const std::uint64_t number = 1 + (hash >> 3) % returns;
    record[14] = static_cast<std::uint8_t>(number | (returns << 3) | ((i / 40 % 2) << 6) |
                                           ((hash % 97 == 0 ? 1u : 0u) << 7));
    record[15] = static_cast<std::uint8_t>(i / 7 % 5 == 0 ? hash % 19 : 2);
    record[16] =
        static_cast<std::uint8_t>(static_cast<std::int8_t>(static_cast<int>(i / 50 % 60) - 30));
    record[17] = static_cast<std::uint8_t>(hash % 3 == 0 ? hash >> 8 : 7);
    const auto source = static_cast<std::uint16_t>(i / 1000 + (hash % 501 == 0 ? 40000 : 0));
    std::memcpy(record + 18, &source, 2);
  } else {
    // Up to 15 returns; the four scanner channels in runs, now and then a lone point of another
    // channel (so that a channel's context is left and taken up again).
    const std::uint64_t returns = 1 + hash % (hash % 31 == 0 ? 15 : 3);
    const std::uint64_t number = hash % 53 == 0 ? hash % 16 : 1 + (hash >> 3) % returns;
    record[14] = static_cast<std::uint8_t>(number | (returns << 4));
    const std::uint64_t channel = hash % 41 == 0       ? hash % 4
                                  : (i / 300) % 4 == 3 ? 2
                                                       : (i / 300) % 3;
    record[15] = static_cast<std::uint8_t>((hash % 89 == 0 ? hash % 16 : 0) | (channel << 4) |
                                           ((i / 40 % 2) << 6) | ((hash % 97 == 0 ? 1u : 0u) << 7));
    record[16] = static_cast<std::uint8_t>(i / 7 % 5 == 0 ? hash % 67 : 2);
    record[17] = static_cast<std::uint8_t>(hash % 3 == 0 ? hash >> 8 : 7);
    const auto angle = static_cast<std::int16_t>(static_cast<int>(i / 50 % 6000) - 3000);
    std::memcpy(record + 18, &angle, 2);
    const auto source = static_cast<std::uint16_t>(i / 1000 + (hash % 501 == 0 ? 40000 : 0));
    std::memcpy(record + 20, &source, 2);
    if (layout_.format == 8 || layout_.format == 10) {  // near infrared
      const auto nir = static_cast<std::uint16_t>(hash % 5 == 0 ? hash & 0xffff : 300 + i % 700);
      std::memcpy(record + 36, &nir, 2);
    }
  }
  const bool has_time = layout_.format == 1 || layout_.format >= 3;
  if (has_time) {
    const std::size_t at = layout_.format >= 6 ? 22 : 20;
    // Two flight lines interleaved in runs, each steady but for a pulse now and then out of step
    // (by up to 600 periods either way); now and then a jump or a repeat.
    const double line = (i / 37) % 3 == 0 ? 250000.0 : 0.0;
    const double out_of_step = hash % 7 == 0 ? static_cast<double>(hash % 1200) - 600.0 : 0.0;
    double time = 1000.0 + line + (static_cast<double>(i) + out_of_step) * 1.5e-5;
    if (hash % 211 == 0) time += 1e6;
    if (hash % 13 == 0) time = 1000.0 + line;
    std::memcpy(record + at, &time, 8);
  }
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
  if (layout_.copc) {
    finishCopc();
  } else if (laz_) {
    finishLaz();
  } else {
    evlr_start_ = point_offset_ + count_ * recordLength(layout_);
  }
  const std::uint64_t evlr_start = evlr_start_;
  if (!copc_pages_.empty()) {  // COPC's hierarchy EVLR
    std::vector<std::uint8_t> evlr(60, 0);
    putText(evlr, 2, "copc", 16);
    put<std::uint16_t>(evlr, 18, 1000);
    put<std::uint64_t>(evlr, 20, copc_pages_.size());
    putText(evlr, 28, "COPC hierarchy", 32);
    evlr.insert(evlr.end(), copc_pages_.begin(), copc_pages_.end());
    out_.write(reinterpret_cast<const char*>(evlr.data()),
               static_cast<std::streamsize>(evlr.size()));
  }
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
  put<std::uint32_t>(
      head, kVlrCount,
      static_cast<std::uint32_t>(layout_.vlrs + (laz_ ? 1 : 0) + (copc_info_at_ != 0 ? 1 : 0)));
  head[kFormat] = static_cast<std::uint8_t>(layout_.format | (laz_ ? 0x80 : 0));  // LASzip's mark
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
    put<std::uint64_t>(head, kEvlrStart, evlrCount() != 0 ? evlr_start : 0);
    put<std::uint32_t>(head, kEvlrCount, evlrCount());
    put<std::uint64_t>(head, kCount, count_);
    put<std::uint64_t>(head, 255, count_);
  }
  out_.seekp(0);
  out_.write(reinterpret_cast<const char*>(head.data()), static_cast<std::streamsize>(head.size()));
  out_.close();
  if (!out_) throw std::runtime_error("writing the LAS file failed");
}

}  // namespace octopoint::testing
