#include "renderer/cell_table.h"

#include <algorithm>
#include <cstring>

#include "octopoint/scene.h"

namespace octopoint {
namespace {

constexpr char kMagic[8] = {'O', 'C', 'T', 'C', 'E', 'L', 'L', '1'};
constexpr std::size_t kHeaderBytes = 8 + 4 * 4 + 3 * 8;

std::uint64_t readLe(const std::uint8_t* at, int bytes) {
  std::uint64_t value = 0;
  for (int i = bytes - 1; i >= 0; --i) value = value << 8 | at[i];
  return value;
}

void writeLe(std::vector<std::uint8_t>& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

void writeVarint(std::vector<std::uint8_t>& out, std::uint32_t value) {
  while (value >= 0x80) {
    out.push_back(static_cast<std::uint8_t>(value | 0x80));
    value >>= 7;
  }
  out.push_back(static_cast<std::uint8_t>(value));
}

// A LEB128 varint of at most 5 bytes and 32 bits from [*at, end); false when it is not one.
bool readVarint(const std::uint8_t*& at, const std::uint8_t* end, std::uint32_t* value) {
  std::uint64_t v = 0;
  for (int shift = 0; shift < 35; shift += 7) {
    if (at == end) return false;
    const std::uint8_t byte = *at++;
    v |= std::uint64_t{byte & 0x7fu} << shift;
    if ((byte & 0x80) == 0) {
      if (v > 0xffffffffu) return false;
      *value = static_cast<std::uint32_t>(v);
      return true;
    }
  }
  return false;
}

// Walks one cell's runs, calling `take(first, length)`; kNone when they are well formed and every
// id is below `instances`, with *count the ids.
template <typename Take>
CellTableError walkRuns(const std::uint8_t* at, const std::uint8_t* end, std::uint32_t instances,
                        std::size_t* count, Take take) {
  std::uint32_t runs = 0;
  *count = 0;
  if (at == end) return CellTableError::kNone;  // an empty cell may hold no bytes at all
  if (!readVarint(at, end, &runs)) return CellTableError::kBadRun;
  std::uint64_t next = 0;  // the first id the next run may start at
  for (std::uint32_t r = 0; r < runs; ++r) {
    std::uint32_t gap = 0, length = 0;
    if (!readVarint(at, end, &gap) || !readVarint(at, end, &length)) return CellTableError::kBadRun;
    const std::uint64_t first = next + gap, last = first + length;  // 64 bits: no overflow
    if (last >= instances) return CellTableError::kBadRun;
    take(static_cast<std::uint32_t>(first), length + std::uint64_t{1});
    *count += length + std::size_t{1};
    next = last + 1;
  }
  return at == end ? CellTableError::kNone : CellTableError::kTrailingBytes;
}

}  // namespace

const char* describe(CellTableError error) {
  switch (error) {
    case CellTableError::kNone:
      return "accepted";
    case CellTableError::kTooLarge:
      return "larger than 64 MiB";
    case CellTableError::kTruncated:
      return "truncated";
    case CellTableError::kBadMagic:
      return "not a cell table (no OCTCELL1 magic)";
    case CellTableError::kWrongScene:
      return "made for a scene of another instance count";
    case CellTableError::kBadGrid:
      return "a grid count, edge or bound outside its limits";
    case CellTableError::kBadLayers:
      return "layer bounds not increasing";
    case CellTableError::kBadOffsets:
      return "cell offsets out of order or past the payload";
    case CellTableError::kBadRun:
      return "a cell's runs malformed or naming an unknown instance";
    case CellTableError::kTrailingBytes:
      return "bytes after a cell's runs";
  }
  return "unknown error";
}

CellTable CellTable::parse(std::span<const std::uint8_t> bytes, std::uint32_t scene_instances,
                           CellTableError* error) {
  CellTable table;
  const auto fail = [&](CellTableError why) {
    *error = why;
    return CellTable{};
  };
  if (bytes.size() > kMaxCellTableBytes) return fail(CellTableError::kTooLarge);
  if (bytes.size() < kHeaderBytes) return fail(CellTableError::kTruncated);
  if (std::memcmp(bytes.data(), kMagic, 8) != 0) return fail(CellTableError::kBadMagic);
  const std::uint8_t* p = bytes.data();
  CellGrid& g = table.grid_;
  g.instances = static_cast<std::uint32_t>(readLe(p + 8, 4));
  g.nx = static_cast<std::uint32_t>(readLe(p + 12, 4));
  g.nz = static_cast<std::uint32_t>(readLe(p + 16, 4));
  g.ny = static_cast<std::uint32_t>(readLe(p + 20, 4));
  g.origin_x = static_cast<std::int64_t>(readLe(p + 24, 8));
  g.origin_z = static_cast<std::int64_t>(readLe(p + 32, 8));
  g.edge = static_cast<std::int64_t>(readLe(p + 40, 8));
  if (g.instances != scene_instances) return fail(CellTableError::kWrongScene);
  if (g.nx < 1 || g.nx > kMaxCellsPerAxis || g.nz < 1 || g.nz > kMaxCellsPerAxis || g.ny < 1 ||
      g.ny > kMaxCellLayers || std::uint64_t{g.nx} * g.nz * g.ny > kMaxCells) {
    return fail(CellTableError::kBadGrid);
  }
  // Every corner of the grid within kMaxSceneCoordinate: edge * 4096 <= 2^44 keeps it exact.
  const auto within = [](std::int64_t v) {
    return v >= -kMaxSceneCoordinate && v <= kMaxSceneCoordinate;
  };
  if (g.edge < 1 || g.edge > kMaxSceneCoordinate / kMaxCellsPerAxis || !within(g.origin_x) ||
      !within(g.origin_z) || !within(g.origin_x + g.edge * g.nx) ||
      !within(g.origin_z + g.edge * g.nz)) {
    return fail(CellTableError::kBadGrid);
  }
  const std::size_t cells = g.cellCount();
  const std::size_t offsets_at = kHeaderBytes + 8 * (std::size_t{g.ny} + 1);
  const std::size_t payload_at = offsets_at + 4 * (cells + 1);
  if (bytes.size() < payload_at) return fail(CellTableError::kTruncated);
  for (std::uint32_t k = 0; k <= g.ny; ++k) {
    g.y.push_back(static_cast<std::int64_t>(readLe(p + kHeaderBytes + 8 * k, 8)));
    if (!within(g.y.back())) return fail(CellTableError::kBadGrid);
    if (k > 0 && g.y[k] <= g.y[k - 1]) return fail(CellTableError::kBadLayers);
  }
  const std::size_t payload = bytes.size() - payload_at;
  std::uint64_t previous = 0;
  for (std::size_t i = 0; i <= cells; ++i) {
    const std::uint64_t offset = readLe(p + offsets_at + 4 * i, 4);
    if ((i == 0 && offset != 0) || offset < previous || offset > payload ||
        (i == cells && offset != payload)) {
      return fail(CellTableError::kBadOffsets);
    }
    previous = offset;
  }
  table.bytes_.assign(bytes.begin(), bytes.end());
  table.offsets_at_ = offsets_at;
  table.payload_at_ = payload_at;
  for (std::uint32_t c = 0; c < cells; ++c) {
    const std::uint8_t* at = table.bytes_.data() + payload_at + table.offset(c);
    const std::uint8_t* end = table.bytes_.data() + payload_at + table.offset(c + 1);
    std::size_t count = 0;
    const CellTableError why =
        walkRuns(at, end, g.instances, &count, [](std::uint32_t, std::uint64_t) {});
    if (why != CellTableError::kNone) return fail(why);
    table.largest_ = std::max(table.largest_, count);
  }
  *error = CellTableError::kNone;
  return table;
}

std::uint32_t CellTable::offset(std::uint32_t i) const {
  return static_cast<std::uint32_t>(readLe(bytes_.data() + offsets_at_ + 4 * std::size_t{i}, 4));
}

std::int64_t CellTable::cellAt(const Point3<std::int64_t>& eye) const {
  if (grid_.nx == 0) return -1;
  // |eye - origin| < 2^46: no overflow; floor division by a positive edge.
  const std::int64_t dx = eye.x - grid_.origin_x, dz = eye.z - grid_.origin_z;
  if (dx < 0 || dz < 0) return -1;
  const std::int64_t x = dx / grid_.edge, z = dz / grid_.edge;
  if (x >= grid_.nx || z >= grid_.nz) return -1;
  if (eye.y < grid_.y.front() || eye.y >= grid_.y.back()) return -1;
  std::int64_t layer = 0;
  while (eye.y >= grid_.y[static_cast<std::size_t>(layer) + 1]) ++layer;
  return (layer * grid_.nz + z) * grid_.nx + x;
}

std::size_t CellTable::decode(std::uint32_t cell, std::span<std::uint32_t> out) const {
  if (cell >= grid_.cellCount()) return 0;
  const std::uint8_t* at = bytes_.data() + payload_at_ + offset(cell);
  const std::uint8_t* end = bytes_.data() + payload_at_ + offset(cell + 1);
  std::size_t count = 0, written = 0;
  // Validated on parse: the runs are well formed and hold at most grid_.instances distinct ids.
  static_cast<void>(
      walkRuns(at, end, grid_.instances, &count, [&](std::uint32_t first, std::uint64_t length) {
        for (std::uint64_t k = 0; k < length && written < out.size(); ++k)
          out[written++] = first + static_cast<std::uint32_t>(k);
      }));
  return written;
}

std::vector<std::uint8_t> encodeCellTable(const CellGrid& grid,
                                          const std::vector<std::vector<std::uint32_t>>& sets) {
  std::vector<std::uint8_t> payload;
  std::vector<std::uint32_t> offsets{0};
  for (const std::vector<std::uint32_t>& set : sets) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;  // first, length - 1
    for (const std::uint32_t id : set) {
      if (!runs.empty() && runs.back().first + runs.back().second + 1 == id) {
        ++runs.back().second;
      } else {
        runs.push_back({id, 0});
      }
    }
    if (!runs.empty()) {
      writeVarint(payload, static_cast<std::uint32_t>(runs.size()));
      std::uint32_t next = 0;
      for (const auto& [first, extra] : runs) {
        writeVarint(payload, first - next);
        writeVarint(payload, extra);
        next = first + extra + 1;
      }
    }
    offsets.push_back(static_cast<std::uint32_t>(payload.size()));
  }
  std::vector<std::uint8_t> out(kMagic, kMagic + 8);
  for (const std::uint32_t v : {grid.instances, grid.nx, grid.nz, grid.ny}) writeLe(out, v, 4);
  for (const std::int64_t v : {grid.origin_x, grid.origin_z, grid.edge})
    writeLe(out, static_cast<std::uint64_t>(v), 8);
  for (const std::int64_t v : grid.y) writeLe(out, static_cast<std::uint64_t>(v), 8);
  for (const std::uint32_t v : offsets) writeLe(out, v, 4);
  out.insert(out.end(), payload.begin(), payload.end());
  return out;
}

}  // namespace octopoint
