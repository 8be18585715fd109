// The header of a version 2, 4 or 6 `.oct` file (octopoint/model.h): the validator of those
// versions' headers. Version 2 widens the metric size to picometres in 64 bits and may carry
// normals; version 4 adds the cube's placement in the scan after the normal palette; version 6 has
// version 4's header (its levels' sample reach is in the level table, checked in model.cpp).
#include "octopoint/model.h"
#include "renderer/cube_placement.h"
#include "renderer/model_bytes.h"

namespace octopoint {

using model_bytes::readU16;
using model_bytes::readU64;
using model_bytes::refuse;

std::size_t ModelView::readHeaderV2(std::span<const std::uint8_t> bytes, ModelView& view,
                                    ModelIssue* issue, std::uint16_t version) {
  namespace v2 = format::v2;
  if (bytes.size() < v2::kFixedHeaderBytes)
    return refuse(issue, ModelError::kTruncatedHeader, bytes.size());
  const std::uint8_t* p = bytes.data();
  view.format_version_ = version;
  const bool with_placement = version != format::kVersion2;
  view.level_count_ = p[6];
  if (view.level_count_ < 1 || view.level_count_ > format::kMaxLevels) {
    return refuse(issue, ModelError::kBadLevelCount, 6);
  }
  const std::uint8_t flags = p[7];
  // Unknown flags are reserved: a later version may give them a meaning.
  if ((flags & ~v2::kKnownFlags) != 0) return refuse(issue, ModelError::kBadReservedField, 7);
  view.colour_is_synthetic_ = (flags & v2::kFlagSyntheticColour) != 0;
  view.cube_edge_pm_ = readU64(p + 8);
  view.palette_count_ = readU16(p + 16);
  if (view.palette_count_ < 1 || view.palette_count_ > format::kPaletteEntries) {
    return refuse(issue, ModelError::kBadPaletteCount, 16);
  }
  const int normal_count = readU16(p + 18);
  const bool with_normals = (flags & v2::kFlagNormals) != 0;
  if (with_normals != (normal_count > 0) || normal_count > format::kMaxNormals) {
    return refuse(issue, ModelError::kBadNormalCount, 18);
  }
  view.palette_rgb_ = p + v2::kPaletteOffset;
  const std::size_t unused_from =
      v2::kPaletteOffset + 3 * static_cast<std::size_t>(view.palette_count_);
  const std::size_t non_zero = model_bytes::firstNonZero(p, unused_from, v2::kNormalPaletteOffset);
  if (non_zero != v2::kNormalPaletteOffset)
    return refuse(issue, ModelError::kBadReservedField, non_zero);

  const std::size_t normals_end =
      v2::kNormalPaletteOffset + v2::kNormalEntryBytes * static_cast<std::size_t>(normal_count);
  if (bytes.size() < normals_end) return refuse(issue, ModelError::kTruncatedHeader, bytes.size());
  view.normal_count_ = normal_count;
  view.normal_bytes_ = normal_count > 0 ? p + v2::kNormalPaletteOffset : nullptr;
  if (!validateNormalPalette(view, issue, v2::kNormalPaletteOffset)) return 0;
  if (!with_placement) return normals_end;
  const std::size_t placement_end = normals_end + format::kCubePlacementBytes;
  if (bytes.size() < placement_end)
    return refuse(issue, ModelError::kTruncatedHeader, bytes.size());
  if (!readCubePlacement(p + normals_end, &view.cube_))
    return refuse(issue, ModelError::kBadCubePlacement, normals_end);
  return placement_end;
}

}  // namespace octopoint
