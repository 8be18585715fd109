#include "tests/support/chunked_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cassert>
#include <cstdio>

#include "codegen/level_voxels.h"
#include "codegen/octree_encoder.h"

namespace octopoint::testing {
namespace {

// The index of the chunk of `level` whose region is `region`, or -1.
long chunkOfRegion(const ProgressiveModel& model, int level, std::uint32_t region) {
  const std::uint32_t count = model.chunkCount(level);
  std::uint32_t low = 0, high = count;
  while (low < high) {
    const std::uint32_t mid = (low + high) / 2;
    if (model.record(level, mid).region < region)
      low = mid + 1;
    else
      high = mid;
  }
  return low < count && model.record(level, low).region == region ? static_cast<long>(low) : -1;
}

bool held(const ProgressiveModel& model, int level, std::uint32_t region) {
  const long index = chunkOfRegion(model, level, region);
  return index >= 0 &&
         model.chunkState(level, static_cast<std::uint32_t>(index)) == ChunkState::kHeld;
}

}  // namespace

const prepare::PreparedLevel* finestLevelAtMost(const std::vector<prepare::PreparedLevel>& levels,
                                                int depth) {
  const auto level =
      std::find_if(levels.rbegin(), levels.rend(),
                   [&](const prepare::PreparedLevel& l) { return l.depth <= depth; });
  return level == levels.rend() ? nullptr : &*level;
}

Framebuffer referenceFrame(const ProgressiveModel& model,
                           const std::vector<prepare::PreparedLevel>& levels, const Camera& camera,
                           Variant variant) {
  const int wanted = *model.wantedDepth(camera);
  int drawn = 0;
  while (drawn + 1 < model.levelCount() && model.levelDepth(drawn + 1) <= wanted) ++drawn;
  FrameSetup finest;
  EXPECT_EQ(buildFrameSetup(camera, model.levelDepth(drawn), kDefaultFractionBits, &finest),
            CameraError::kNone);
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  for (int j = 0; j <= drawn; ++j) {
    const prepare::LevelVoxels voxels = prepare::decodeLevel(levels[static_cast<std::size_t>(j)]);
    const int depth = voxels.depth;
    prepare::LevelVoxels chosen;
    chosen.depth = depth;
    for (std::size_t i = 0; i < voxels.keys.size(); ++i) {
      const std::uint64_t key = voxels.keys[i];
      if (j > 0) {
        const int region_level = model.head().levels[static_cast<std::size_t>(j)].region_level;
        if (!held(model, j, static_cast<std::uint32_t>(key >> (3 * (depth - region_level)))))
          continue;
      }
      if (j < drawn) {
        if (!model.hasRecordTable(j + 1)) {
          // Nothing finer is known: the level is drawn whole where held.
        } else {
          const int finer_region_level =
              model.head().levels[static_cast<std::size_t>(j + 1)].region_level;
          if (held(model, j + 1,
                   static_cast<std::uint32_t>(key >> (3 * (depth - finer_region_level)))))
            continue;
        }
      }
      chosen.keys.push_back(key);
      chosen.colours.push_back(voxels.colours[i]);
    }
    if (chosen.keys.empty()) continue;
    const prepare::PreparedLevel stream = prepare::encodeLevel(chosen);
    FrameSetup setup;
    EXPECT_EQ(buildFrameSetup(camera, depth, kDefaultFractionBits, &setup), CameraError::kNone);
    setup.depth_bias = finest.depth_bias;
    setup.depth_shift = finest.depth_shift;
    EXPECT_TRUE(renderLevel(variant, LevelView{depth, stream.nodes, stream.leaves}, setup, frame));
  }
  return frame;
}

std::vector<prepare::PreparedLevel> levelStreams(std::span<const std::uint8_t> image,
                                                 const prepare::PreparedModel& prepared) {
  ChunkedIssue issue;
  const std::optional<ChunkedHead> head = parseChunkedHead(image, &issue);
  assert(head);
  std::vector<prepare::PreparedLevel> levels;
  levels.push_back({head->levels[0].depth, head->base_nodes, head->base_leaves});
  for (int j = 1; j < head->level_count; ++j) {
    const auto it = std::find_if(
        prepared.levels.begin(), prepared.levels.end(), [&](const prepare::PreparedLevel& l) {
          return l.depth == head->levels[static_cast<std::size_t>(j)].depth;
        });
    assert(it != prepared.levels.end());
    levels.push_back(*it);
  }
  return levels;
}

std::vector<FetchItem> allChunkItems(const ProgressiveModel& model) {
  std::vector<FetchItem> items;
  for (int level = 1; level < model.levelCount(); ++level) {
    for (std::uint32_t i = 0; i < model.chunkCount(level); ++i)
      items.push_back(model.chunkItem(level, i));
  }
  return items;
}

void feed(ProgressiveModel& model, std::span<const std::uint8_t> image, const FetchItem& item) {
  const ChunkedIssue issue = model.accept(
      item,
      image.subspan(static_cast<std::size_t>(item.offset), static_cast<std::size_t>(item.bytes)));
  EXPECT_EQ(issue.error, ChunkedError::kNone) << describe(issue.error) << " at " << issue.offset;
}

void feedTables(ProgressiveModel& model, std::span<const std::uint8_t> image) {
  for (int level = 1; level < model.levelCount(); ++level)
    feed(model, image, model.recordTableItem(level));
}

bool sameFrame(const Framebuffer& a, const Framebuffer& b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  std::size_t differ = 0, first = 0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    if (a.pixels()[i] == b.pixels()[i]) continue;
    if (differ++ == 0) first = i;
  }
  if (differ > 0) {
    const auto width = static_cast<std::size_t>(a.width());
    std::printf("%zu pixels differ, the first at (%zu, %zu): %08x instead of %08x\n", differ,
                first % width, first / width, a.pixels()[first], b.pixels()[first]);
  }
  return differ == 0;
}

Camera makeCamera(int yaw, int pitch, double zoom, int width, int height, int pan_x, int pan_y) {
  Camera camera;
  camera.yaw = Angle::fromDegrees(yaw);
  camera.pitch = Angle::fromDegrees(pitch);
  camera.zoom = Q16::fromRaw(static_cast<std::int32_t>(zoom * Q16::kOneRaw));
  camera.width = width;
  camera.height = height;
  camera.pan_x_px = pan_x;
  camera.pan_y_px = pan_y;
  return camera;
}

}  // namespace octopoint::testing
