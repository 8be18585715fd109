#pragma once
// Little-endian reads and the failure report shared by the model readers (renderer/model*.cpp).
// Internal to the model readers: apps do not include it.

#include <cstddef>
#include <cstdint>

#include "octopoint/model.h"

namespace octopoint::model_bytes {

inline std::uint16_t readU16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | p[1] << 8);
}

inline std::uint32_t readU32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

inline std::uint64_t readU64(const std::uint8_t* p) {
  return static_cast<std::uint64_t>(readU32(p)) | static_cast<std::uint64_t>(readU32(p + 4)) << 32;
}

inline std::int16_t readI16(const std::uint8_t* p) { return static_cast<std::int16_t>(readU16(p)); }

// Records the issue (when asked for) and returns false, so that readers can `return fail(...)`: a
// problem of the file's header or level table, whose offset is in the file.
inline bool fail(ModelIssue* issue, ModelError error, std::size_t offset, int depth = 0) {
  if (issue != nullptr) *issue = ModelIssue{error, offset, depth, true};
  return false;
}

// The same for the header readers, which return the offset where the level table starts: 0 is
// never one, so it means "refused".
inline std::size_t refuse(ModelIssue* issue, ModelError error, std::size_t offset) {
  fail(issue, error, offset);
  return 0;
}

// The offset of the first non-zero byte in [from, to), or `to` when all are zero (the reserved
// palette entries past the count).
inline std::size_t firstNonZero(const std::uint8_t* p, std::size_t from, std::size_t to) {
  for (std::size_t at = from; at < to; ++at) {
    if (p[at] != 0) return at;
  }
  return to;
}

}  // namespace octopoint::model_bytes
