// LAZ's chunk table (codegen/laz_chunk_table.h), read and checked against the file.

#include "codegen/laz_chunk_table.h"

#include <algorithm>
#include <string>

#include "codegen/laz_arithmetic.h"
#include "codegen/laz_integer.h"
#include "codegen/laz_reader.h"
#include "codegen/little_endian.h"
#include "codegen/scan_header_check.h"

namespace octopoint::prepare {
namespace {

constexpr std::size_t kInputWindow = 1 << 16;
// The most chunks a chunk table may list (24 bytes each in memory): 2 * 10^11 points in LASzip's
// chunks of 50,000.
constexpr std::uint64_t kMaxLazChunks = 1u << 22;

}  // namespace

std::span<const std::uint8_t> FileInput::more() {
  const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(kInputWindow, end_ - next_));
  if (n == 0) return {};
  window_.resize(n);
  file_.readAt(next_, window_, what_);
  next_ += n;
  handed_ += n;
  return window_;
}

std::vector<LazChunk> readChunkTable(const InputFile& file, const LasHeader& header,
                                     std::uint32_t chunk_size) {
  const auto& path = file.path();
  const std::uint64_t data_start = header.point_offset + 8;
  const std::string where = "chunk table pointer at byte " + std::to_string(header.point_offset);
  if (header.points_end < data_start)
    fail(path, "truncated: the point data ends before its chunk table pointer", where);
  std::uint8_t pointer_bytes[8];
  file.readAt(header.point_offset, pointer_bytes, where);
  auto table_offset = readLittle<std::int64_t>(pointer_bytes);
  if (table_offset == -1) {  // written by a streaming compressor: the pointer is at the file's end
    file.readAt(file.size() - 8, pointer_bytes, "chunk table pointer at the end of the file");
    table_offset = readLittle<std::int64_t>(pointer_bytes);
  }
  if (table_offset == static_cast<std::int64_t>(header.point_offset)) {
    fail(path, "no chunk table: the compressor was interrupted before writing it", where);
  }
  if (table_offset < static_cast<std::int64_t>(data_start) ||
      static_cast<std::uint64_t>(table_offset) + 8 > header.points_end) {
    fail(path,
         "the chunk table at byte " + std::to_string(table_offset) +
             " lies outside the point data (" + std::to_string(data_start) + " to " +
             std::to_string(header.points_end) + ")",
         where);
  }
  const auto table_start = static_cast<std::uint64_t>(table_offset);
  const std::string table_where = "chunk table at byte " + std::to_string(table_start);
  std::uint8_t head[8];
  file.readAt(table_start, head, table_where);
  if (readLittle<std::uint32_t>(head) != 0) {
    fail(path, "unknown chunk table version " + std::to_string(readLittle<std::uint32_t>(head)),
         table_where);
  }
  const std::uint64_t chunk_count = readLittle<std::uint32_t>(head + 4);
  // Every chunk holds at least its first point raw.
  const std::uint64_t room = table_start - data_start;
  if (chunk_count == 0 || chunk_count > room / header.record_length) {
    fail(path,
         "the chunk table declares " + std::to_string(chunk_count) + " chunks, the " +
             std::to_string(room) + " bytes of point data hold 1 to " +
             std::to_string(room / header.record_length),
         table_where);
  }
  const bool variable = chunk_size == kVariableChunks;
  if (!variable && chunk_count != (header.point_count + chunk_size - 1) / chunk_size) {
    fail(path,
         "the header declares " + std::to_string(header.point_count) + " points, which take " +
             std::to_string((header.point_count + chunk_size - 1) / chunk_size) + " chunks of " +
             std::to_string(chunk_size) + ", the chunk table lists " + std::to_string(chunk_count),
         table_where);
  }
  if (chunk_count > kMaxLazChunks) {
    fail(path,
         "the chunk table declares " + std::to_string(chunk_count) + " chunks, more than the " +
             std::to_string(kMaxLazChunks) + " read",
         table_where);
  }
  FileInput input(file, table_start + 8, header.points_end, table_where);
  laz::ArithmeticDecoder decoder;
  decoder.attach(input);
  decoder.start();
  laz::IntegerModels sizes(32, 2);
  sizes.reset();
  std::vector<LazChunk> chunks(static_cast<std::size_t>(chunk_count));
  std::uint64_t first_point = 0;
  std::uint64_t offset = data_start;
  std::int32_t last_points = 0;
  std::int32_t last_bytes = 0;
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    LazChunk& chunk = chunks[i];
    if (variable) last_points = sizes.decode(decoder, last_points, 0);
    last_bytes = sizes.decode(decoder, last_bytes, 1);
    if (decoder.overrun() > 0) {
      fail(path,
           "truncated: the chunk table ends after " + std::to_string(i) + " of its " +
               std::to_string(chunk_count) + " chunks",
           table_where);
    }
    chunk.points =
        variable ? static_cast<std::uint32_t>(last_points)
                 : std::min<std::uint64_t>(
                       chunk_size, header.point_count - std::min(header.point_count, first_point));
    chunk.bytes = static_cast<std::uint32_t>(last_bytes);
    chunk.first_point = first_point;
    chunk.offset = offset;
    const std::string chunk_where = "chunk " + std::to_string(i + 1) + " of " +
                                    std::to_string(chunk_count) + ", " + table_where;
    if (chunk.points == 0 || chunk.points > kMaxLazChunkPoints) {
      fail(path,
           "a chunk of " + std::to_string(chunk.points) + " points (1 to " +
               std::to_string(kMaxLazChunkPoints) + " are read)",
           chunk_where);
    }
    if (chunk.bytes < header.record_length || chunk.bytes > table_start - offset) {
      fail(path,
           "a chunk of " + std::to_string(chunk.bytes) + " bytes at byte " +
               std::to_string(offset) + " does not fit between its first point's " +
               std::to_string(header.record_length) + " bytes and the chunk table",
           chunk_where);
    }
    first_point += chunk.points;
    offset += chunk.bytes;
    if (first_point > header.point_count) break;  // reported below
  }
  if (first_point != header.point_count) {
    fail(path,
         "the header declares " + std::to_string(header.point_count) + " points, the " +
             std::to_string(chunk_count) + " chunks of the chunk table hold " +
             (first_point > header.point_count ? "more" : std::to_string(first_point)),
         table_where);
  }
  return chunks;
}

std::vector<LazChunk> wholeFileChunk(const InputFile& file, const LasHeader& header) {
  if (header.point_count > kMaxLazChunkPoints) {
    fail(file.path(),
         "LAZ without chunks (LASzip's point-wise compressor) of more than " +
             std::to_string(kMaxLazChunkPoints) + " points is not read",
         "LASzip VLR");
  }
  return {LazChunk{0, header.point_count, header.point_offset,
                   header.points_end - header.point_offset}};
}

}  // namespace octopoint::prepare
