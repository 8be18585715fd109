// LAZ read natively (codegen/laz_reader.h): LASzip's VLR, the chunk table, and the chunks decoded
// by the item decoders (codegen/laz_pointwise.h) in parallel, each thread with its own decoder.

#include "codegen/laz_reader.h"

#include <algorithm>
#include <cstring>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "codegen/copc_hierarchy.h"
#include "codegen/laz_arithmetic.h"
#include "codegen/laz_chunk_table.h"
#include "codegen/laz_integer.h"
#include "codegen/laz_layered.h"
#include "codegen/laz_pointwise.h"
#include "codegen/little_endian.h"
#include "codegen/scan_header_check.h"

namespace octopoint::prepare {
namespace {

using laz::Item;
using laz::ItemType;

enum class Compressor : std::uint16_t {
  kNone = 0,
  kPointwise = 1,
  kPointwiseChunked = 2,
  kLayered = 3
};

constexpr std::size_t kVlrFixedBytes = 34;  // before the items, 6 bytes each

struct LazLayout {
  Compressor compressor = Compressor::kNone;
  std::uint32_t chunk_size = 0;  // kVariableChunks: each chunk's size is in the chunk table
  std::vector<Item> items;
  std::string description;  // for the summary
};

// The items each point format has, in order (extra bytes come after, as a BYTE or BYTE14 item):
// point-wise for formats 0 to 5, layered for 6 to 10.
std::vector<ItemType> formatItems(int format) {
  if (format >= 6) {
    std::vector<ItemType> items = {ItemType::kPoint14};
    if (format == 7) items.push_back(ItemType::kRgb14);
    if (format == 8 || format == 10) items.push_back(ItemType::kRgbNir14);
    if (format == 9 || format == 10) items.push_back(ItemType::kWavePacket14);
    return items;
  }
  std::vector<ItemType> items = {ItemType::kPoint10};
  if (format == 1 || format >= 3) items.push_back(ItemType::kGpsTime11);
  if (format == 2 || format == 3 || format == 5) items.push_back(ItemType::kRgb12);
  if (format == 4 || format == 5) items.push_back(ItemType::kWavePacket13);
  return items;
}

std::uint16_t itemBytes(ItemType type) {
  switch (type) {
    case ItemType::kPoint10:
      return 20;
    case ItemType::kGpsTime11:
      return 8;
    case ItemType::kRgb12:
      return 6;
    case ItemType::kWavePacket13:
    case ItemType::kWavePacket14:
      return 29;
    case ItemType::kPoint14:
      return 30;
    case ItemType::kRgb14:
      return 6;
    case ItemType::kRgbNir14:
      return 8;
    default:
      return 0;
  }
}

// LASzip's VLR: the compressor, the chunk size and the items, checked against the point format.
LazLayout readLaszipVlr(const InputFile& file, const LasHeader& header) {
  const std::string where = "LASzip VLR at byte " + std::to_string(header.laszip_vlr_offset);
  const auto refuse = [&](const std::string& what) { fail(file.path(), what, where); };
  if (header.laszip_vlr_bytes < kVlrFixedBytes) {
    refuse("the VLR has " + std::to_string(header.laszip_vlr_bytes) + " bytes, at least " +
           std::to_string(kVlrFixedBytes) + " needed");
  }
  std::vector<std::uint8_t> vlr(header.laszip_vlr_bytes);
  file.readAt(header.laszip_vlr_offset, vlr, where);
  LazLayout layout;
  const auto compressor = readLittle<std::uint16_t>(&vlr[0]);
  layout.chunk_size = readLittle<std::uint32_t>(&vlr[12]);
  const auto item_count = readLittle<std::uint16_t>(&vlr[32]);
  if (kVlrFixedBytes + 6u * item_count > vlr.size()) {
    refuse("the VLR lists " + std::to_string(item_count) + " items, its " +
           std::to_string(vlr.size()) + " bytes hold " +
           std::to_string((vlr.size() - kVlrFixedBytes) / 6));
  }
  std::uint32_t total = 0;
  for (std::size_t i = 0; i < item_count; ++i) {
    const std::uint8_t* at = &vlr[kVlrFixedBytes + 6 * i];
    Item item{static_cast<ItemType>(readLittle<std::uint16_t>(at)),
              readLittle<std::uint16_t>(at + 2), readLittle<std::uint16_t>(at + 4)};
    total += item.size;
    layout.items.push_back(item);
  }
  if (compressor != static_cast<std::uint16_t>(Compressor::kPointwise) &&
      compressor != static_cast<std::uint16_t>(Compressor::kPointwiseChunked) &&
      compressor != static_cast<std::uint16_t>(Compressor::kLayered)) {
    refuse("unknown LASzip compressor " + std::to_string(compressor) +
           " (1 point-wise, 2 point-wise chunked, 3 layered chunked)");
  }
  layout.compressor = static_cast<Compressor>(compressor);
  const bool layered = layout.compressor == Compressor::kLayered;
  if (layered != (header.point_format >= 6)) {
    refuse("LASzip compressor " + std::to_string(compressor) + " for point format " +
           std::to_string(header.point_format) +
           ": formats 0 to 5 are read point-wise (compressors 1 and 2), 6 to 10 layered (3)");
  }
  const ItemType extra_bytes = layered ? ItemType::kByte14 : ItemType::kByte;
  // The items must be the point format's, in its order, then at most one BYTE item, and make up
  // exactly the record.
  const std::vector<ItemType> expected = formatItems(header.point_format);
  std::size_t matched = 0;
  for (const Item& item : layout.items) {
    const bool in_place = matched < expected.size()
                              ? item.type == expected[matched]
                              : item.type == extra_bytes && matched == expected.size();
    if (!in_place || (item.type != extra_bytes && item.size != itemBytes(item.type)) ||
        item.size == 0) {
      refuse("the items (" + laz::itemName(item) + " of " + std::to_string(item.size) +
             " bytes, item " + std::to_string(matched + 1) + ") do not fit point format " +
             std::to_string(header.point_format));
    }
    ++matched;
  }
  if (matched < expected.size() || total != header.record_length) {
    refuse("the items make " + std::to_string(total) + "-byte records with " +
           std::to_string(matched) + " items, point format " + std::to_string(header.point_format) +
           " has " + std::to_string(header.record_length) + "-byte records");
  }
  laz::ArithmeticDecoder probe;
  for (const Item& item : layout.items) {
    if (layered ? !laz::layeredDecoder(item) : !laz::pointwiseDecoder(item, probe)) {
      refuse("unknown LAZ item " + laz::itemName(item) +
             ": this reader knows versions 1 and 2 of POINT10, GPSTIME11, RGB12 and BYTE, "
             "WAVEPACKET13 version 1, and version 3 of POINT14, RGB14, RGBNIR14, WAVEPACKET14 and "
             "BYTE14");
    }
  }
  if (layout.compressor != Compressor::kPointwise &&
      (layout.chunk_size == 0 ||
       (layout.chunk_size != kVariableChunks && layout.chunk_size > kMaxLazChunkPoints))) {
    refuse("chunks of " + std::to_string(layout.chunk_size) + " points are not read (1 to " +
           std::to_string(kMaxLazChunkPoints) + ", or variable)");
  }
  const std::string kind = layered ? "layered" : "point-wise";
  layout.description = layout.compressor == Compressor::kPointwise ? "point-wise, one chunk"
                       : layout.chunk_size == kVariableChunks
                           ? kind + ", variable chunks"
                           : kind + ", chunks of " + std::to_string(layout.chunk_size);
  return layout;
}

// A chunk's cube: where its points lie, in the scan's coordinates.
struct ChunkCube {
  std::array<double, 3> low{};
  std::array<double, 3> high{};
};

// COPC: every chunk is the node of the hierarchy that names its offset, byte size and point count,
// and every node with points is a chunk. Returns each chunk's cube, widened by one coordinate step
// on each side (a writer rounds a point on a cube's face to either side).
std::vector<ChunkCube> copcChunkCubes(const InputFile& file, const LasHeader& header,
                                      const std::vector<LazChunk>& chunks,
                                      std::string& description) {
  const auto& path = file.path();
  const CopcHierarchy hierarchy = readCopcHierarchy(file, header, chunks.front().offset,
                                                    chunks.back().offset + chunks.back().bytes);
  std::unordered_map<std::uint64_t, std::size_t> chunk_at;
  for (std::size_t i = 0; i < chunks.size(); ++i) chunk_at.emplace(chunks[i].offset, i);
  std::vector<ChunkCube> cubes(chunks.size());
  std::vector<bool> claimed(chunks.size(), false);
  int deepest = 0;
  for (const CopcNode& node : hierarchy.nodes) {
    const std::string where =
        "COPC node " + copcKeyName(node.key) + ", chunk at byte " + std::to_string(node.offset);
    const auto found = chunk_at.find(node.offset);
    if (found == chunk_at.end()) {
      fail(path, "the hierarchy names a chunk that the chunk table does not list", where);
    }
    const LazChunk& chunk = chunks[found->second];
    if (chunk.bytes != node.bytes || chunk.points != node.points) {
      fail(path,
           "the hierarchy gives the chunk " + std::to_string(node.points) + " points in " +
               std::to_string(node.bytes) + " bytes, the chunk table " +
               std::to_string(chunk.points) + " in " + std::to_string(chunk.bytes),
           where);
    }
    if (claimed[found->second]) fail(path, "two nodes of the hierarchy name this chunk", where);
    claimed[found->second] = true;
    ChunkCube& cube = cubes[found->second];
    for (std::size_t axis = 0; axis < 3; ++axis) {
      cube.low[axis] = node.low[axis] - header.scale[axis];
      cube.high[axis] = node.high[axis] + header.scale[axis];
    }
    deepest = std::max(deepest, node.key.level);
  }
  if (hierarchy.nodes.size() != chunks.size()) {
    fail(path,
         "the chunk table lists " + std::to_string(chunks.size()) + " chunks, the COPC hierarchy " +
             std::to_string(hierarchy.nodes.size()) + " nodes with points",
         "COPC info VLR at byte " + std::to_string(header.copc_vlr_offset));
  }
  description = "COPC, " + std::to_string(chunks.size()) + " nodes to level " +
                std::to_string(deepest) + " in " + std::to_string(hierarchy.pages) +
                (hierarchy.pages == 1 ? " hierarchy page" : " hierarchy pages");
  return cubes;
}

// One thread's chunk decoder: the arithmetic decoder and an item decoder per item (point-wise),
// or the item decoders that read the layers of `fields` (layered).
class ChunkDecoder {
 public:
  ChunkDecoder(const LazLayout& layout, RecordFields fields)
      : layered_(layout.compressor == Compressor::kLayered) {
    std::size_t at = 0;
    for (const Item& item : layout.items) {
      if (layered_) {
        layered_items_.push_back({laz::layeredDecoder(item, fields), at});
      } else {
        items_.push_back({laz::pointwiseDecoder(item, decoder_), at});
      }
      at += item.size;
    }
    record_bytes_ = at;
  }

  // Decodes the chunk's points [skip, skip + take) into `out`.
  void decode(const InputFile& file, const LazChunk& chunk, std::size_t chunk_index,
              std::uint64_t skip, std::size_t take, std::uint8_t* out) {
    const std::string where =
        "LAZ chunk " + std::to_string(chunk_index + 1) + " at byte " + std::to_string(chunk.offset);
    if (layered_) {
      decodeLayered(file, chunk, where, skip, take, out);
      return;
    }
    FileInput input(file, chunk.offset, chunk.offset + chunk.bytes, where);
    decoder_.attach(input);
    scratch_.resize(record_bytes_);
    std::uint8_t* record = skip == 0 ? out : scratch_.data();
    for (std::size_t b = 0; b < record_bytes_; ++b) record[b] = decoder_.rawByte();
    decoder_.start();
    for (auto& [item, at] : items_) item->start(record + at);
    const std::uint64_t end = skip + take;
    for (std::uint64_t i = 1; i < end; ++i) {
      std::uint8_t* next = i >= skip ? out + (i - skip) * record_bytes_ : scratch_.data();
      for (auto& [item, at] : items_) item->decode(next + at);
      if (decoder_.overrun() > 0) [[unlikely]] {  // stop a corrupt chunk at once
        fail(file.path(),
             "corrupt LAZ: the arithmetic code runs past the chunk's " +
                 std::to_string(chunk.bytes) + " bytes at its point " + std::to_string(i + 1) +
                 " of " + std::to_string(chunk.points),
             where);
      }
    }
    if (decoder_.failed()) fail(file.path(), "corrupt LAZ: a raw value out of range", where);
    // A whole chunk's code ends exactly where the chunk does (LASzip's reader checks the same): a
    // chunk table that lies about a size or an offset cannot go unnoticed.
    const std::uint64_t consumed = input.handed() - decoder_.unread();
    if (end == chunk.points && consumed != chunk.bytes) {
      fail(file.path(),
           "corrupt LAZ: the chunk table gives the chunk " + std::to_string(chunk.bytes) +
               " bytes, its " + std::to_string(chunk.points) + " points take " +
               std::to_string(consumed),
           where);
    }
  }

 private:
  // A layered chunk: its first point raw, its point count, every layer's size (32 bits each,
  // item by item), then the layers in the same order. The chunk is read whole: its layers are
  // decoded side by side.
  void decodeLayered(const InputFile& file, const LazChunk& chunk, const std::string& where,
                     std::uint64_t skip, std::size_t take, std::uint8_t* out) {
    const auto refuse = [&](const std::string& what) {
      fail(file.path(), "corrupt LAZ: " + what, where);
    };
    // A layered chunk is at most twice its raw records (the code of random values outgrows them
    // by a few percent): a chunk table giving more is refused before the chunk is read.
    const std::uint64_t most = 2 * chunk.points * record_bytes_ + 4096;
    if (chunk.bytes > most) {
      refuse("the chunk table gives " + std::to_string(chunk.points) + " points " +
             std::to_string(chunk.bytes) + " bytes, more than the " + std::to_string(most) +
             " a layered chunk of them may take");
    }
    bytes_.resize(static_cast<std::size_t>(chunk.bytes));
    file.readAt(chunk.offset, bytes_, where);
    std::size_t layer_count = 0;
    for (const auto& part : layered_items_) layer_count += part.decoder->layerCount();
    const std::size_t head = record_bytes_ + 4 + 4 * layer_count;
    if (bytes_.size() < head) {
      refuse("the chunk's " + std::to_string(bytes_.size()) +
             " bytes end before its first point, point count and " + std::to_string(layer_count) +
             " layer sizes (" + std::to_string(head) + " bytes)");
    }
    const std::uint8_t* first = bytes_.data();
    const auto count = readLittle<std::uint32_t>(first + record_bytes_);
    if (count != chunk.points) {
      refuse("the chunk says it has " + std::to_string(count) + " points, the chunk table " +
             std::to_string(chunk.points));
    }
    // Every layer's size is checked against the chunk's bytes before any layer is read, the layers
    // to be stepped over too.
    layers_.clear();
    std::uint64_t at = head;
    for (std::size_t i = 0; i < layer_count; ++i) {
      const std::uint64_t size = readLittle<std::uint32_t>(first + record_bytes_ + 4 + 4 * i);
      if (size > bytes_.size() - at) {
        refuse("layer " + std::to_string(i + 1) + " of " + std::to_string(layer_count) + " has " +
               std::to_string(size) + " bytes, " + std::to_string(bytes_.size() - at) +
               " of the chunk's are left for it");
      }
      layers_.push_back(std::span<const std::uint8_t>(bytes_).subspan(at, size));
      at += size;
    }
    if (at != bytes_.size()) {
      refuse("the chunk table gives the chunk " + std::to_string(bytes_.size()) +
             " bytes, its layers end after " + std::to_string(at));
    }
    const std::uint32_t first_channel = (first[15] >> 4) & 3u;  // POINT14's scanner channel
    std::size_t layer = 0;
    for (auto& [item, offset] : layered_items_) {
      const std::size_t n = item->layerCount();
      item->start(first + offset, std::span(layers_).subspan(layer, n), first_channel);
      layer += n;
    }
    scratch_.resize(record_bytes_);
    if (skip == 0) std::memcpy(out, first, record_bytes_);
    const std::uint64_t end = skip + take;
    for (std::uint64_t i = 1; i < end; ++i) {
      std::uint8_t* next = i >= skip ? out + (i - skip) * record_bytes_ : scratch_.data();
      std::uint32_t channel = 0;  // set by POINT14 on a change of channel only (LayeredItemDecoder)
      for (auto& [item, offset] : layered_items_) item->decode(next + offset, channel);
      // POINT14's first layer is read for every point: stop a corrupt chunk at once
      if (layered_items_[0].decoder->overrunLayer() >= 0) [[unlikely]] {
        refuse("the " + layered_items_[0].decoder->layerName(0) + " runs past its bytes at point " +
               std::to_string(i + 1) + " of " + std::to_string(chunk.points));
      }
    }
    if (end != chunk.points) return;
    // A whole chunk's layers each end exactly at their last byte.
    for (const auto& part : layered_items_) {
      const int bad = part.decoder->inexactLayer();
      if (bad >= 0) {
        refuse("the " + part.decoder->layerName(static_cast<std::size_t>(bad)) +
               " does not end where its size says (a size or the code is wrong)");
      }
    }
  }

  struct Part {
    std::unique_ptr<laz::ItemDecoder> decoder;
    std::size_t at;
  };
  struct LayeredPart {
    std::unique_ptr<laz::LayeredItemDecoder> decoder;
    std::size_t at;
  };
  bool layered_;
  laz::ArithmeticDecoder decoder_;
  std::vector<Part> items_;
  std::vector<LayeredPart> layered_items_;
  std::size_t record_bytes_ = 0;
  std::vector<std::uint8_t> scratch_;
  std::vector<std::uint8_t> bytes_;                    // a layered chunk
  std::vector<std::span<const std::uint8_t>> layers_;  // its layers
};

class LazSource final : public PointSource {
 public:
  LazSource(std::unique_ptr<InputFile> file, const LasHeader& header, RecordFields fields)
      : file_(std::move(file)), header_(header), info_(lasSourceInfo(header)), fields_(fields) {
    layout_ = readLaszipVlr(*file_, header_);
    chunks_ = layout_.compressor == Compressor::kPointwise
                  ? wholeFileChunk(*file_, header_)
                  : readChunkTable(*file_, header_, layout_.chunk_size);
    if (header_.copc_vlr_offset != 0) {
      std::string description;
      cubes_ = copcChunkCubes(*file_, header_, chunks_, description);
      layout_.description += ", " + description;
    }
    info_.format += ", " + layout_.description;
    file_->adviseSequential();
  }

  const SourceInfo& info() const override { return info_; }
  std::size_t pieceCount() const override { return chunks_.size(); }
  PointRange piece(std::size_t index) const override {
    return {chunks_[index].first_point, static_cast<std::size_t>(chunks_[index].points)};
  }

  bool pieceMayMeet(std::size_t index, const std::array<double, 3>& low,
                    const std::array<double, 3>& high) const override {
    if (cubes_.empty()) return true;
    const ChunkCube& cube = cubes_[index];
    for (std::size_t axis = 0; axis < 3; ++axis) {
      if (cube.high[axis] < low[axis] || cube.low[axis] > high[axis]) return false;
    }
    return true;
  }
  std::uint64_t bytesRead() const override { return file_->bytesRead(); }

  void read(std::uint64_t first, std::size_t count, PointChunk& chunk) const override {
    chunk.raw.resize(count * header_.record_length);
    std::unique_ptr<ChunkDecoder> decoder = takeDecoder();
    // The chunks that hold [first, first + count): the last one starting at or before `first`, on.
    auto it = std::upper_bound(
        chunks_.begin(), chunks_.end(), first,
        [](std::uint64_t point, const LazChunk& c) { return point < c.first_point; });
    std::size_t index = static_cast<std::size_t>(it - chunks_.begin()) - 1;
    std::uint64_t done = 0;
    while (done < count) {
      const LazChunk& c = chunks_[index];
      const std::uint64_t skip = first + done - c.first_point;
      const auto take =
          static_cast<std::size_t>(std::min<std::uint64_t>(c.points - skip, count - done));
      decoder->decode(*file_, c, index, skip, take,
                      chunk.raw.data() + done * header_.record_length);
      done += take;
      ++index;
    }
    giveBack(std::move(decoder));
    chunk.resize(count, info_);
    decodeLasRecords(header_, chunk.raw.data(), chunk);
  }

 private:
  // Decoders are kept between reads (their models are a few MB to set up), one per thread at most.
  std::unique_ptr<ChunkDecoder> takeDecoder() const {
    {
      const std::lock_guard lock(mutex_);
      if (!idle_.empty()) {
        auto decoder = std::move(idle_.back());
        idle_.pop_back();
        return decoder;
      }
    }
    return std::make_unique<ChunkDecoder>(layout_, fields_);
  }
  void giveBack(std::unique_ptr<ChunkDecoder> decoder) const {
    const std::lock_guard lock(mutex_);
    idle_.push_back(std::move(decoder));
  }

  std::unique_ptr<InputFile> file_;
  LasHeader header_;
  SourceInfo info_;
  RecordFields fields_;
  LazLayout layout_;
  std::vector<LazChunk> chunks_;
  std::vector<ChunkCube> cubes_;  // COPC: each chunk's cube; empty for other LAZ
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<ChunkDecoder>> idle_;
};

}  // namespace

std::unique_ptr<PointSource> openLazSource(std::unique_ptr<InputFile> file, const LasHeader& header,
                                           RecordFields fields) {
  return std::make_unique<LazSource>(std::move(file), header, fields);
}

}  // namespace octopoint::prepare
