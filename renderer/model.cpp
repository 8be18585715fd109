#include "octopoint/model.h"

#include <bit>
#include <cstring>
#include <utility>

#include "renderer/bit_scan.h"
#include "renderer/model_bytes.h"

namespace octopoint {

using model_bytes::fail;
using model_bytes::readI16;
using model_bytes::readU16;
using model_bytes::readU32;

namespace {

// A version 6 level's sample reach: one to eight footprints, in sixteenths.
bool validSampleReach(std::uint8_t reach) {
  return reach >= format::kOneSampleReachQ4 && reach <= format::kMaxSampleReachQ4;
}

}  // namespace

const char* describe(ModelError error) {
  switch (error) {
    case ModelError::kNone:
      return "no error";
    case ModelError::kTruncatedHeader:
      return "truncated header";
    case ModelError::kBadMagic:
      return "not an octopoint model (bad magic)";
    case ModelError::kUnsupportedVersion:
      return "unsupported format version";
    case ModelError::kBadLevelCount:
      return "bad level count";
    case ModelError::kBadReservedField:
      return "reserved field is not zero";
    case ModelError::kBadPaletteCount:
      return "bad palette colour count";
    case ModelError::kBadDepth:
      return "depth outside the supported range";
    case ModelError::kDepthsNotAscending:
      return "level depths are not strictly ascending";
    case ModelError::kSizeMismatch:
      return "declared sizes do not match the data length";
    case ModelError::kEmptyLevel:
      return "level has no nodes or no leaves";
    case ModelError::kEmptyNode:
      return "inner node without children (zero mask byte)";
    case ModelError::kStreamTruncated:
      return "node stream truncated";
    case ModelError::kTrailingNodeBytes:
      return "trailing bytes after the node stream";
    case ModelError::kLeafCountMismatch:
      return "leaf count does not match the tree";
    case ModelError::kLeafOutsidePalette:
      return "leaf colour index outside the palette";
    case ModelError::kImplausibleLevelSize:
      return "node bytes and leaf count impossible for the depth";
    case ModelError::kBadNormalCount:
      return "bad normal count";
    case ModelError::kBadNormalVector:
      return "normal palette entry is not a unit vector";
    case ModelError::kNormalOutsidePalette:
      return "leaf normal index outside the normal palette";
    case ModelError::kBadCubePlacement:
      return "cube placement not finite, edge not above 0, or unknown scan axes";
    case ModelError::kBadSampleReach:
      return "level sample reach outside 16..128 sixteenths of a footprint";
  }
  return "unknown error";
}

// Bounds any tree of `depth` levels obeys, checked before walking so that a hostile size is
// refused in constant time: every inner node (one byte) has at least one leaf below it and every
// leaf has exactly `depth` inner ancestors, so depth <= nodes <= depth * leaves; a leaf parent
// has at most 8 leaves, so leaves <= 8 * nodes; and a full tree caps both, (8^depth - 1) / 7
// nodes and 8^depth leaves, which only bites below depth 11 (8^11 > 2^32).
bool plausibleLevelSize(int depth, std::uint64_t nodes, std::uint64_t leaves) {
  if (depth < 1 || depth > format::kMaxDepth || nodes == 0 || leaves == 0) return false;
  const auto levels = static_cast<std::uint64_t>(depth);
  if (nodes < levels || nodes > levels * leaves || leaves > 8 * nodes) return false;
  if (depth <= 10) {
    const std::uint64_t full_leaves = std::uint64_t{1} << (3 * depth);
    // nodes > (8^depth - 1) / 7, without a division (a Cortex-M0+ has no divide instruction);
    // nodes < 2^32 (a u32 field), so 7 * nodes cannot wrap.
    if (leaves > full_leaves || 7 * nodes > full_leaves - 1) return false;
  }
  return true;
}

namespace {

// What a level's row of the level table shows wrong without any of the level's bytes: its depth,
// against the level before it (0 for none), and its sizes, against any tree of that depth.
ModelIssue levelRowIssue(int depth, int previous_depth, std::uint64_t nodes, std::uint64_t leaves) {
  if (depth < 1 || depth > format::kMaxDepth) return {ModelError::kBadDepth, 0, depth};
  if (depth <= previous_depth) return {ModelError::kDepthsNotAscending, 0, depth};
  if (nodes == 0 || leaves == 0) return {ModelError::kEmptyLevel, 0, depth};
  if (!plausibleLevelSize(depth, nodes, leaves))
    return {ModelError::kImplausibleLevelSize, 0, depth};
  return {};
}

}  // namespace

ModelIssue validateLevelStream(const LevelView& level, int palette_count, int normal_count) {
  const int depth = level.depth;
  const ModelIssue row_issue = levelRowIssue(depth, 0, level.nodes.size(), level.leaves.size());
  if (row_issue.error != ModelError::kNone) return row_issue;

  // Depth-first walk with an explicit stack of "children still to visit" per tree level, so a
  // hostile stream cannot drive the recursion; the stack is bounded by the depth.
  std::array<int, format::kMaxDepth> pending{};
  int top = 0;  // tree level of the next node byte
  pending[0] = 1;
  std::size_t node_at = 0;
  std::size_t leaf_total = 0;
  while (top >= 0) {
    if (pending[static_cast<std::size_t>(top)] == 0) {
      --top;
      continue;
    }
    --pending[static_cast<std::size_t>(top)];
    if (node_at == level.nodes.size()) return {ModelError::kStreamTruncated, node_at, depth};
    const std::uint8_t mask = level.nodes[node_at];
    if (mask == 0) return {ModelError::kEmptyNode, node_at, depth};
    ++node_at;
    const int children = childCount(mask);
    if (top + 1 == depth) {
      leaf_total += static_cast<std::size_t>(children);  // leaf parent: its children are leaves
    } else {
      ++top;
      pending[static_cast<std::size_t>(top)] = children;
    }
  }
  if (node_at != level.nodes.size()) return {ModelError::kTrailingNodeBytes, node_at, depth};
  if (leaf_total != level.leaves.size()) {
    return {ModelError::kLeafCountMismatch, level.leaves.size(), depth};
  }
  for (std::size_t i = 0; i < level.leaves.size(); ++i) {
    if (level.leaves[i] >= palette_count) return {ModelError::kLeafOutsidePalette, i, depth};
  }
  if (normal_count == 0) {
    if (!level.normals.empty()) return {ModelError::kBadNormalCount, 0, depth};
    return {};
  }
  if (level.normals.size() != level.leaves.size()) {
    return {ModelError::kLeafCountMismatch, level.normals.size(), depth};
  }
  for (std::size_t i = 0; i < level.normals.size(); ++i) {
    if (level.normals[i] >= normal_count) return {ModelError::kNormalOutsidePalette, i, depth};
  }
  return {};
}

namespace {

// The bytes of level data a level table row declares: node bytes, then a palette index per leaf
// and, in a model with normals, a normal index per leaf.
std::uint64_t levelDataBytes(const std::uint8_t* row, bool with_normals) {
  const std::uint64_t leaf_count = readU32(row + 8);
  return readU32(row + 4) + leaf_count * (with_normals ? 2 : 1);
}

// Where level `index`'s problem lies in a whole model image starting at `file`: in its node
// stream, its leaves, or its row of the level table (depth, then node bytes, then leaf count).
std::size_t fileOffsetOf(const ModelIssue& issue, const LevelView& level, int index,
                         const std::uint8_t* file, std::size_t table_at) {
  const std::size_t row = table_at + format::kLevelRowBytes * static_cast<std::size_t>(index);
  switch (issue.error) {
    case ModelError::kEmptyNode:
    case ModelError::kStreamTruncated:
    case ModelError::kTrailingNodeBytes:
      return static_cast<std::size_t>(level.nodes.data() - file) + issue.offset;
    case ModelError::kLeafOutsidePalette:
      return static_cast<std::size_t>(level.leaves.data() - file) + issue.offset;
    case ModelError::kNormalOutsidePalette:
      return static_cast<std::size_t>(level.normals.data() - file) + issue.offset;
    case ModelError::kLeafCountMismatch:
      return row + 8;
    case ModelError::kEmptyLevel:
    case ModelError::kImplausibleLevelSize:
      return row + 4;
    default:
      return row;  // the depth
  }
}

}  // namespace

bool ModelView::validateLevels(ModelView& view, ModelIssue* issue, const std::uint8_t* file,
                               std::size_t table_at) {
  int previous_depth = 0;
  for (int i = 0; i < view.level_count_; ++i) {
    const LevelView& level = view.level(i);
    ModelIssue found =
        levelRowIssue(level.depth, previous_depth, level.nodes.size(), level.leaves.size());
    if (found.error == ModelError::kNone)
      found = validateLevelStream(level, view.palette_count_, view.normal_count_);
    previous_depth = level.depth;
    if (found.error != ModelError::kNone) {
      if (file != nullptr) {
        found.offset = fileOffsetOf(found, level, i, file, table_at);
        found.offset_in_file = true;
      }
      if (issue != nullptr) *issue = found;
      return false;
    }
  }
  return true;
}

bool ModelView::validateNormalPalette(const ModelView& view, ModelIssue* issue,
                                      std::size_t offset) {
  constexpr std::int64_t kOneSquared = std::int64_t{format::kNormalOne} * format::kNormalOne;
  for (int i = 0; i < view.normal_count_; ++i) {
    const NormalQ14 n = view.normal(i);
    const std::int64_t squared =
        std::int64_t{n.x} * n.x + std::int64_t{n.y} * n.y + std::int64_t{n.z} * n.z;
    if (squared < kOneSquared - format::kNormalLengthTolerance ||
        squared > kOneSquared + format::kNormalLengthTolerance) {
      return fail(issue, ModelError::kBadNormalVector,
                  offset + format::v2::kNormalEntryBytes * static_cast<std::size_t>(i));
    }
  }
  return true;
}

bool ModelView::checkLevelTable(std::span<const std::uint8_t> head, std::size_t table_at,
                                std::uint64_t image_bytes, const ModelView& view,
                                ModelIssue* issue) {
  const std::uint8_t* p = head.data();
  const std::size_t table_end =
      table_at + format::kLevelRowBytes * static_cast<std::size_t>(view.level_count_);
  if (head.size() < table_end) return fail(issue, ModelError::kTruncatedHeader, head.size());
  // Sizes are added in 64 bits: three u32 counts per level cannot overflow it, so a hostile
  // header cannot wrap the sum around to the real length.
  std::uint64_t data_at = table_end;
  for (int i = 0; i < view.level_count_; ++i) {
    const std::uint8_t* row = p + table_at + format::kLevelRowBytes * static_cast<std::size_t>(i);
    // Version 6 gives byte 1 a meaning, the level's sample reach; older versions reserve it.
    if (view.format_version_ == format::kVersion6) {
      if (!validSampleReach(row[1]))
        return fail(issue, ModelError::kBadSampleReach, static_cast<std::size_t>(row - p) + 1);
    } else if (row[1] != 0) {
      return fail(issue, ModelError::kBadReservedField, static_cast<std::size_t>(row - p) + 1);
    }
    if (row[2] != 0 || row[3] != 0) {
      return fail(issue, ModelError::kBadReservedField,
                  static_cast<std::size_t>(row - p) + (row[2] != 0 ? 2 : 3));
    }
    data_at += levelDataBytes(row, view.normal_count_ > 0);
    if (data_at > image_bytes) {
      return fail(issue, ModelError::kSizeMismatch, static_cast<std::size_t>(image_bytes), row[0]);
    }
  }
  if (data_at != image_bytes)
    return fail(issue, ModelError::kSizeMismatch, static_cast<std::size_t>(data_at));
  return true;
}

bool ModelView::readLevels(std::span<const std::uint8_t> bytes, std::size_t table_at,
                           ModelView& view, ModelIssue* issue) {
  if (!checkLevelTable(bytes, table_at, bytes.size(), view, issue)) return false;
  const bool with_normals = view.normal_count_ > 0;
  std::size_t data_at =
      table_at + format::kLevelRowBytes * static_cast<std::size_t>(view.level_count_);
  for (int i = 0; i < view.level_count_; ++i) {
    const std::uint8_t* row =
        bytes.data() + table_at + format::kLevelRowBytes * static_cast<std::size_t>(i);
    const std::size_t node_bytes = readU32(row + 4);
    const std::size_t leaf_count = readU32(row + 8);
    const std::size_t normal_bytes = with_normals ? leaf_count : 0;
    LevelView& level = view.levels_[static_cast<std::size_t>(i)];
    if (view.format_version_ == format::kVersion6)
      view.reaches_[static_cast<std::size_t>(i)] = row[1];
    level.depth = row[0];
    level.nodes = bytes.subspan(data_at, node_bytes);
    level.leaves = bytes.subspan(data_at + node_bytes, leaf_count);
    level.normals = bytes.subspan(data_at + node_bytes + leaf_count, normal_bytes);
    data_at += node_bytes + leaf_count + normal_bytes;
  }
  return true;
}

std::size_t ModelView::readHeader(std::span<const std::uint8_t> bytes, ModelView& view,
                                  ModelIssue* issue) {
  // Magic and version first: they decide how every other byte is read.
  if (bytes.size() < 6)
    return model_bytes::refuse(issue, ModelError::kTruncatedHeader, bytes.size());
  if (std::memcmp(bytes.data(), format::kMagic, sizeof format::kMagic) != 0)
    return model_bytes::refuse(issue, ModelError::kBadMagic, 0);
  switch (readU16(bytes.data() + 4)) {
    case format::kVersion1:
      return readHeaderV1(bytes, view, issue);
    case format::kVersion2:
    case format::kVersion4:
    case format::kVersion6:
      return readHeaderV2(bytes, view, issue, readU16(bytes.data() + 4));
    default:
      return model_bytes::refuse(issue, ModelError::kUnsupportedVersion, 4);
  }
}

bool ModelView::checkDeclaredSizes(std::span<const std::uint8_t> head, std::uint64_t image_bytes,
                                   ModelIssue* issue) {
  ModelView view;
  const std::size_t table_at = readHeader(head, view, issue);
  if (table_at == 0 || !checkLevelTable(head, table_at, image_bytes, view, issue)) return false;
  int previous_depth = 0;
  for (int i = 0; i < view.level_count_; ++i) {
    const std::uint8_t* row =
        head.data() + table_at + format::kLevelRowBytes * static_cast<std::size_t>(i);
    ModelIssue found = levelRowIssue(row[0], previous_depth, readU32(row + 4), readU32(row + 8));
    if (found.error != ModelError::kNone) {
      found.offset = fileOffsetOf(found, LevelView{}, i, head.data(), table_at);
      found.offset_in_file = true;
      if (issue != nullptr) *issue = found;
      return false;
    }
    previous_depth = row[0];
  }
  return true;
}

std::optional<ModelView> ModelView::fromBytes(std::span<const std::uint8_t> bytes,
                                              ModelIssue* issue) {
  ModelView view;
  const std::size_t table_at = readHeader(bytes, view, issue);
  if (table_at == 0 || !readLevels(bytes, table_at, view, issue) ||
      !validateLevels(view, issue, bytes.data(), table_at)) {
    return std::nullopt;
  }
  view.indexSubtrees();
  if (issue != nullptr) *issue = {};
  return view;
}

std::optional<ModelView> ModelView::fromEmbedded(const EmbeddedModel& model, ModelIssue* issue) {
  if (model.format_version != format::kVersion2 && model.format_version != format::kVersion4 &&
      model.format_version != format::kVersion6) {
    fail(issue, ModelError::kUnsupportedVersion, 0);
    return std::nullopt;
  }
  // Version 2 has no placement; version 4's must be one a file may hold.
  if ((model.format_version == format::kVersion2 && model.cube.recorded()) ||
      !validCubePlacement(model.cube)) {
    fail(issue, ModelError::kBadCubePlacement, 0);
    return std::nullopt;
  }
  if ((model.flags & ~format::v2::kKnownFlags) != 0) {
    fail(issue, ModelError::kBadReservedField, 0);
    return std::nullopt;
  }
  if (model.level_count < 1 || model.level_count > format::kMaxLevels || model.levels == nullptr) {
    fail(issue, ModelError::kBadLevelCount, 0);
    return std::nullopt;
  }
  if (model.palette_count < 1 || model.palette_count > format::kPaletteEntries ||
      model.palette_rgb == nullptr) {
    fail(issue, ModelError::kBadPaletteCount, 0);
    return std::nullopt;
  }
  const bool with_normals = (model.flags & format::v2::kFlagNormals) != 0;
  if (with_normals != (model.normal_count > 0) || model.normal_count > format::kMaxNormals ||
      with_normals != (model.normal_xyz != nullptr)) {
    fail(issue, ModelError::kBadNormalCount, 0);
    return std::nullopt;
  }
  ModelView view;
  view.format_version_ = model.format_version;
  view.cube_edge_pm_ = model.cube_edge_pm;
  view.cube_ = model.cube;
  view.palette_count_ = model.palette_count;
  view.palette_rgb_ = model.palette_rgb;
  view.colour_is_synthetic_ = (model.flags & format::v2::kFlagSyntheticColour) != 0;
  view.normal_count_ = model.normal_count;
  view.normal_values_ = model.normal_xyz;
  if (!validateNormalPalette(view, issue, 0)) return std::nullopt;
  view.level_count_ = model.level_count;
  for (int i = 0; i < view.level_count_; ++i) {
    const EmbeddedLevel& source = model.levels[i];
    if (source.nodes == nullptr || source.leaves == nullptr ||
        with_normals != (source.normals != nullptr)) {
      fail(issue, ModelError::kEmptyLevel, 0, source.depth);
      return std::nullopt;
    }
    // Version 6 sources carry the reach; older ones end before it (0: one footprint).
    if (model.format_version == format::kVersion6 ? !validSampleReach(source.sample_reach)
                                                  : source.sample_reach != 0) {
      fail(issue, ModelError::kBadSampleReach, 0, source.depth);
      return std::nullopt;
    }
    if (model.format_version == format::kVersion6)
      view.reaches_[static_cast<std::size_t>(i)] = source.sample_reach;
    view.levels_[static_cast<std::size_t>(i)] =
        LevelView{source.depth,
                  {source.nodes, source.node_bytes},
                  {source.leaves, source.leaf_count},
                  with_normals ? std::span<const std::uint8_t>{source.normals, source.leaf_count}
                               : std::span<const std::uint8_t>{}};
  }
  if (!validateLevels(view, issue, nullptr, 0)) return std::nullopt;
  view.indexSubtrees();
  if (issue != nullptr) *issue = {};
  return view;
}

void ModelView::indexSubtrees() {
#if !defined(OCTOPOINT_BARE_METAL)
  std::size_t total = 0;
  for (int i = 0; i < level_count_; ++i)
    total += skipIndexEntries(levels_[static_cast<std::size_t>(i)]);
  if (total == 0) return;
  auto ends = std::make_shared<std::vector<SubtreeEnd>>(total);
  std::span<SubtreeEnd> free = *ends;
  for (int i = 0; i < level_count_; ++i) {
    LevelView& level = levels_[static_cast<std::size_t>(i)];
    level.skip = buildSkipIndex(level, free);
    free = free.subspan(level.skip.ends.size());
  }
  skip_ends_ = std::move(ends);
#endif
}

Rgb ModelView::paletteColour(int index) const {
  const std::uint8_t* entry = palette_rgb_ + 3 * static_cast<std::size_t>(index);
  return {entry[0], entry[1], entry[2]};
}

NormalQ14 ModelView::normal(int index) const {
  const auto at = 3 * static_cast<std::size_t>(index);
  if (normal_values_ != nullptr)
    return {normal_values_[at], normal_values_[at + 1], normal_values_[at + 2]};
  const std::uint8_t* entry = normal_bytes_ + 2 * at;
  return {readI16(entry), readI16(entry + 2), readI16(entry + 4)};
}

std::int32_t ModelView::sampleReachOfDepth(int depth) const {
  for (int i = 0; i < level_count_; ++i) {
    if (levels_[static_cast<std::size_t>(i)].depth == depth) return sampleReach(i);
  }
  return format::kOneSampleReachQ4;
}

const LevelView* ModelView::levelOfDepth(int depth) const {
  for (int i = 0; i < level_count_; ++i) {
    if (levels_[static_cast<std::size_t>(i)].depth == depth)
      return &levels_[static_cast<std::size_t>(i)];
  }
  return nullptr;
}

}  // namespace octopoint
