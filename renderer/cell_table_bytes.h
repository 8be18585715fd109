#pragma once
// The cell table's byte-level pieces (renderer/cell_table.h), shared by its reader
// (cell_table.cpp) and its writer (cell_table_encode.cpp): little-endian fields, LEB128 varints
// and zigzag for the order's signed steps.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace octopoint::cell_bytes {

inline constexpr char kMagic1[8] = {'O', 'C', 'T', 'C', 'E', 'L', 'L', '1'};
inline constexpr char kMagic2[8] = {'O', 'C', 'T', 'C', 'E', 'L', 'L', '2'};
// Magic, u32 instances, nx, nz, ny, i64 origin x, origin z, edge.
inline constexpr std::size_t kHeaderBytes = 8 + 4 * 4 + 3 * 8;

inline std::uint64_t readLe(const std::uint8_t* at, int bytes) {
  std::uint64_t value = 0;
  for (int i = bytes - 1; i >= 0; --i) value = value << 8 | at[i];
  return value;
}

inline void writeLe(std::vector<std::uint8_t>& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

inline void writeVarint(std::vector<std::uint8_t>& out, std::uint32_t value) {
  while (value >= 0x80) {
    out.push_back(static_cast<std::uint8_t>(value | 0x80));
    value >>= 7;
  }
  out.push_back(static_cast<std::uint8_t>(value));
}

// A LEB128 varint of at most 5 bytes and 32 bits from [*at, end); false when it is not one.
inline bool readVarint(const std::uint8_t*& at, const std::uint8_t* end, std::uint32_t* value) {
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

// Zigzag: 0, -1, 1, -2 ... as 0, 1, 2, 3 ... (a step of the order may go back).
inline std::uint32_t zigzag(std::int64_t step) {
  return static_cast<std::uint32_t>(step >= 0 ? 2 * step : -2 * step - 1);
}
inline std::int64_t unzigzag(std::uint32_t coded) {
  return (coded & 1u) != 0 ? -(std::int64_t{coded} + 1) / 2 : std::int64_t{coded} / 2;
}

}  // namespace octopoint::cell_bytes
