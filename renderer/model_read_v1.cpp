// The header of a version 1 `.oct` file (octopoint/model.h): the validator of that version.
// It stays here unchanged so that old files keep reading exactly as they did.
#include "octopoint/model.h"
#include "renderer/model_bytes.h"

namespace octopoint {

using model_bytes::readU16;
using model_bytes::readU32;
using model_bytes::refuse;

std::size_t ModelView::readHeaderV1(std::span<const std::uint8_t> bytes, ModelView& view,
                                    ModelIssue* issue) {
  if (bytes.size() < format::v1::kHeaderBytes)
    return refuse(issue, ModelError::kTruncatedHeader, bytes.size());
  const std::uint8_t* p = bytes.data();
  view.format_version_ = format::kVersion1;
  view.level_count_ = p[6];
  if (view.level_count_ < 1 || view.level_count_ > format::kMaxLevels) {
    return refuse(issue, ModelError::kBadLevelCount, 6);
  }
  if (p[7] != 0 || readU16(p + 14) != 0)
    return refuse(issue, ModelError::kBadReservedField, p[7] != 0 ? 7 : 14);
  // Micrometres in a u32: at most 4.29 km, which is why version 2 stores picometres in a u64.
  view.cube_edge_pm_ = std::uint64_t{readU32(p + 8)} * 1'000'000;
  view.palette_count_ = readU16(p + 12);
  if (view.palette_count_ < 1 || view.palette_count_ > format::kPaletteEntries) {
    return refuse(issue, ModelError::kBadPaletteCount, 12);
  }
  view.palette_rgb_ = p + format::v1::kPaletteOffset;
  // Entries past the count are reserved: zero, so that a later version may give them a meaning.
  const std::size_t unused_from =
      format::v1::kPaletteOffset + 3 * static_cast<std::size_t>(view.palette_count_);
  const std::size_t non_zero = model_bytes::firstNonZero(p, unused_from, format::v1::kHeaderBytes);
  if (non_zero != format::v1::kHeaderBytes)
    return refuse(issue, ModelError::kBadReservedField, non_zero);
  return format::v1::kHeaderBytes;
}

}  // namespace octopoint
