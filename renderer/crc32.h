#pragma once
// CRC-32 as zlib, PNG and Ethernet compute it (polynomial 0x04C11DB7 reflected, 0xEDB88320; initial
// value and final xor 0xFFFFFFFF): crc32("123456789") = 0xCBF43926. The chunked format
// (octopoint/progressive.h) stores one per chunk and per directory part, so that a chunk that
// arrives damaged is refused on its own. A 256-entry table built at compile time; integer only.

#include <array>
#include <cstdint>
#include <span>

namespace octopoint {

namespace crc32_detail {

constexpr std::array<std::uint32_t, 256> makeTable() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t byte = 0; byte < 256; ++byte) {
    std::uint32_t crc = byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc & 1u) ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
    table[byte] = crc;
  }
  return table;
}

inline constexpr std::array<std::uint32_t, 256> kTable = makeTable();

}  // namespace crc32_detail

// The CRC of `bytes`; pass a previous result as `crc` to continue over a following piece
// (crc32(b, crc32(a)) == crc32(a followed by b)).
constexpr std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc = 0) {
  crc = ~crc;
  for (const std::uint8_t byte : bytes)
    crc = crc32_detail::kTable[(crc ^ byte) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}

}  // namespace octopoint
