#include "renderer/cell_table.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "octopoint/scene.h"
#include "renderer/cell_table_bytes.h"

namespace octopoint {
namespace {

using cell_bytes::kHeaderBytes;
using cell_bytes::readLe;
using cell_bytes::readVarint;

// A cell's head: its run count and, when it is a difference, how many cells back its reference is
// (0: none). An empty cell (no bytes) has no runs and no reference.
struct CellHead {
  std::uint32_t runs = 0, back = 0;
};

CellTableError readHead(const std::uint8_t*& at, const std::uint8_t* end, bool references,
                        std::uint32_t cell, CellHead* head) {
  *head = {};
  if (at == end) return CellTableError::kNone;
  std::uint32_t h = 0;
  if (!readVarint(at, end, &h)) return CellTableError::kBadRun;
  if (!references) {  // OCTCELL1: the run count alone
    head->runs = h;
    return CellTableError::kNone;
  }
  head->runs = h >> 1;
  if ((h & 1u) == 0) return CellTableError::kNone;
  if (!readVarint(at, end, &head->back)) return CellTableError::kBadRun;
  return head->back >= 1 && head->back <= cell ? CellTableError::kNone
                                               : CellTableError::kBadReference;
}

// Walks `runs` runs of ranks, calling `take(first, length)`; kNone when they are well formed, every
// rank below `instances` and no byte left, with *count the ranks.
template <typename Take>
CellTableError walkRuns(const std::uint8_t* at, const std::uint8_t* end, std::uint32_t runs,
                        std::uint32_t instances, std::uint64_t* count, Take take) {
  *count = 0;
  std::uint64_t next = 0;  // the first rank the next run may start at
  for (std::uint32_t r = 0; r < runs; ++r) {
    std::uint32_t gap = 0, length = 0;
    if (!readVarint(at, end, &gap) || !readVarint(at, end, &length)) return CellTableError::kBadRun;
    const std::uint64_t first = next + gap, last = first + length;  // 64 bits: no overflow
    if (last >= instances) return CellTableError::kBadRun;
    take(static_cast<std::uint32_t>(first), length + std::uint64_t{1});
    *count += length + std::uint64_t{1};
    next = last + 1;
  }
  return at == end ? CellTableError::kNone : CellTableError::kTrailingBytes;
}

// The ids' own order: rank k is id k (OCTCELL1's, and OCTCELL2's without order bytes).
std::vector<std::uint32_t> identityOrder(std::uint32_t instances) {
  std::vector<std::uint32_t> order(instances);
  for (std::uint32_t id = 0; id < instances; ++id) order[id] = id;
  return order;
}

// The order's runs of ids into `order` (rank -> id): kNone when every id below `instances` comes
// exactly once and no byte is left. No bytes: the ids' own order.
CellTableError readOrder(const std::uint8_t* at, const std::uint8_t* end, std::uint32_t instances,
                         std::vector<std::uint32_t>* order) {
  if (at == end) {
    *order = identityOrder(instances);
    return CellTableError::kNone;
  }
  order->clear();
  std::vector<bool> seen(instances);
  std::uint32_t runs = 0;
  if (!readVarint(at, end, &runs)) return CellTableError::kBadOrder;
  std::int64_t next = 0;  // the previous run's end
  for (std::uint32_t r = 0; r < runs; ++r) {
    std::uint32_t step = 0, length = 0;
    if (!readVarint(at, end, &step) || !readVarint(at, end, &length))
      return CellTableError::kBadOrder;
    const std::int64_t first = next + cell_bytes::unzigzag(step);
    const std::int64_t last = first + length;  // |values| < 2^34: no overflow
    if (first < 0 || last >= instances) return CellTableError::kBadOrder;
    for (std::int64_t id = first; id <= last; ++id) {  // at most `instances` ids, or refused
      if (seen[static_cast<std::size_t>(id)]) return CellTableError::kBadOrder;
      seen[static_cast<std::size_t>(id)] = true;
      order->push_back(static_cast<std::uint32_t>(id));
    }
    next = last + 1;
  }
  return at == end && order->size() == instances ? CellTableError::kNone
                                                 : CellTableError::kBadOrder;
}

// Toggles ranks [first, first + length) in `bits`; widens [*low, *high] to the words touched.
void toggle(std::uint64_t* bits, std::uint32_t first, std::uint64_t length, std::size_t* low,
            std::size_t* high) {
  const std::uint64_t end = first + length;  // at most the instance count
  std::size_t word = first >> 6;
  const std::size_t last_word = static_cast<std::size_t>((end - 1) >> 6);
  *low = std::min(*low, word);
  *high = std::max(*high, last_word);
  for (; word <= last_word; ++word) {
    const std::uint64_t from = std::max<std::uint64_t>(first, std::uint64_t{word} << 6);
    const std::uint64_t to = std::min<std::uint64_t>(end, (std::uint64_t{word} + 1) << 6);
    const std::uint64_t width = to - from;  // 1..64 bits
    const std::uint64_t mask = width == 64 ? ~std::uint64_t{0} : ((std::uint64_t{1} << width) - 1);
    bits[word] ^= mask << (from & 63);
  }
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
      return "not a cell table (no OCTCELL2 or OCTCELL1 magic)";
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
    case CellTableError::kBadOrder:
      return "with its instance order malformed (an id unknown, missing or twice)";
    case CellTableError::kBadReference:
      return "with a cell referring to no earlier cell, or a chain of differences too long";
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
  const bool version2 = std::memcmp(bytes.data(), cell_bytes::kMagic2, 8) == 0;
  if (!version2 && std::memcmp(bytes.data(), cell_bytes::kMagic1, 8) != 0)
    return fail(CellTableError::kBadMagic);
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
  const std::size_t layers_end = kHeaderBytes + 8 * (std::size_t{g.ny} + 1);
  if (bytes.size() < layers_end + (version2 ? 4 : 0)) return fail(CellTableError::kTruncated);
  for (std::uint32_t k = 0; k <= g.ny; ++k) {
    g.y.push_back(static_cast<std::int64_t>(readLe(p + kHeaderBytes + 8 * k, 8)));
    if (!within(g.y.back())) return fail(CellTableError::kBadGrid);
    if (k > 0 && g.y[k] <= g.y[k - 1]) return fail(CellTableError::kBadLayers);
  }
  std::size_t offsets_at = layers_end;
  if (version2) {
    const std::uint64_t order_bytes = readLe(p + layers_end, 4);
    if (bytes.size() - layers_end - 4 < order_bytes) return fail(CellTableError::kTruncated);
    const std::uint8_t* order = p + layers_end + 4;
    const CellTableError why = readOrder(order, order + order_bytes, g.instances, &table.order_);
    if (why != CellTableError::kNone) return fail(why);
    offsets_at = layers_end + 4 + static_cast<std::size_t>(order_bytes);
  } else {
    table.order_ = identityOrder(g.instances);
  }
  const std::size_t payload_at = offsets_at + 4 * (cells + 1);
  if (bytes.size() < payload_at) return fail(CellTableError::kTruncated);
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
  table.references_ = version2;
  // Per cell its chain's length and a bound on its set: its reference's bound plus its own ranks.
  std::vector<std::uint8_t> chain(cells);
  std::vector<std::uint32_t> bound(cells);
  for (std::uint32_t c = 0; c < cells; ++c) {
    const std::uint8_t* at = table.bytes_.data() + payload_at + table.offset(c);
    const std::uint8_t* end = table.bytes_.data() + payload_at + table.offset(c + 1);
    CellHead head;
    CellTableError why = readHead(at, end, version2, c, &head);
    if (why != CellTableError::kNone) return fail(why);
    std::uint64_t count = 0;
    why = walkRuns(at, end, head.runs, g.instances, &count, [](std::uint32_t, std::uint64_t) {});
    if (why != CellTableError::kNone) return fail(why);
    chain[c] = 1;
    if (head.back != 0) {
      if (chain[c - head.back] >= kMaxCellChain) return fail(CellTableError::kBadReference);
      chain[c] = static_cast<std::uint8_t>(chain[c - head.back] + 1);
      count += bound[c - head.back];
    }
    bound[c] = static_cast<std::uint32_t>(std::min<std::uint64_t>(count, g.instances));
    table.largest_ = std::max<std::size_t>(table.largest_, bound[c]);
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

CellTable::Scratch CellTable::scratch() const {
  return {std::vector<std::uint64_t>((std::size_t{grid_.instances} + 63) / 64, 0)};
}

std::size_t CellTable::decode(std::uint32_t cell, std::span<std::uint32_t> out,
                              Scratch& scratch) const {
  if (cell >= grid_.cellCount()) return 0;
  if (scratch.bits.size() != (std::size_t{grid_.instances} + 63) / 64) return 0;
  // The chain: the cell, the cell it refers to, and so on (validated on parse: each earlier, at
  // most kMaxCellChain long, every run well formed and below the instance count), each with its
  // runs' bytes (after its head) and their count.
  struct Link {
    const std::uint8_t *at, *end;
    std::uint32_t runs;
  };
  Link chain[kMaxCellChain];
  int length = 0;
  for (std::uint32_t c = cell;;) {
    Link& link = chain[length++];
    link.at = bytes_.data() + payload_at_ + offset(c);
    link.end = bytes_.data() + payload_at_ + offset(c + 1);
    CellHead head;
    static_cast<void>(readHead(link.at, link.end, references_, c, &head));
    link.runs = head.runs;
    if (head.back == 0 || length == kMaxCellChain) break;
    c -= head.back;
  }
  std::size_t written = 0;
  std::uint64_t count = 0;
  const auto runsOf = [&](const Link& link, auto take) {
    static_cast<void>(walkRuns(link.at, link.end, link.runs, grid_.instances, &count, take));
  };
  if (length == 1) {  // its own runs: the ranks straight out
    runsOf(chain[0], [&](std::uint32_t first, std::uint64_t run) {
      for (std::uint64_t k = 0; k < run && written < out.size(); ++k)
        out[written++] = order_[first + k];
    });
    return written;
  }
  // A difference: toggle every chain cell's runs in the scratch bits, then read them (clearing).
  std::vector<std::uint64_t>& bits = scratch.bits;
  std::size_t low = bits.size(), high = 0;
  for (int k = 0; k < length; ++k) {
    runsOf(chain[k], [&](std::uint32_t first, std::uint64_t run) {
      toggle(bits.data(), first, run, &low, &high);
    });
  }
  for (std::size_t word = low; word <= high && word < bits.size(); ++word) {
    std::uint64_t set = bits[word];
    bits[word] = 0;
    while (set != 0 && written < out.size()) {
      out[written++] = order_[word * 64 + static_cast<std::size_t>(std::countr_zero(set))];
      set &= set - 1;
    }
  }
  return written;
}

}  // namespace octopoint
