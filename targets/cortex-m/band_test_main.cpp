// The bare-metal band test (docs/device.md), run under qemu-system-arm by scripts/test-mcu:
//  1. every case of targets/cortex-m/band_cases.h (three cameras, depths 7 and 8, with and without
//  hole
//     filling, bands of 1, 7, 8 and 24 rows) drawn by fixed_fast and by fixed_delta with the
//     level-3 subtree index into two alternating band buffers, every band's checksum compared with
//     the host's golden;
//  2. the cost table: every fixed variant, bands of 8, 24 and 120 rows (two or three bands:
//     almost one walk), without an index and with the level-3 and level-4 ones, at 320x240 and
//     240x320, depth 8: instructions per frame from qemu's instruction clock (the sink's
//     checksumming excluded), each frame checked against the goldens too;
//  3. the perspective cases (band_cases.h): drawn in bands by renderPerspectiveBands with and
//     without occlusion culling, every band against the host's golden, instructions per point;
//     and the RAM of the upper tree indexes, the tiles and the walk tables;
//  4. the stack's high-water mark over all of it.
// Prints one line per measurement and exits with status 0 only if every band matched.
#include <array>
#include <cstdint>
#include <memory>

#include "mcu/golden.h"
#include "octopoint/render.h"
#include "renderer/perspective_bands.h"
#include "renderer/perspective_layers.h"
#include "targets/cortex-m/band_check.h"
#include "targets/cortex-m/semihosting.h"

using namespace octopoint;
using namespace octopoint::mcu;

namespace {

constexpr std::int32_t kTallRows = 120;  // two bands of a 240-row frame: about one walk
constexpr std::size_t kHistoryWords =
    static_cast<std::size_t>(kMaxWidth + 2 * kHoleFillPadColumns) * kHoleFillHistoryRows;
constexpr std::size_t kBufferWords =
    static_cast<std::size_t>(kMaxBandRows + 2 * kHoleFillReachRows) * kMaxWidth;
// One arena: either two band buffers of up to 24 + 4 rows, or one band of 120 rows, or what a
// perspective frame needs (its two band buffers, the upper tree indexes, the occlusion tiles):
// the Cortex-M4's 192 KB hold one of them at a time.
constexpr std::size_t kArenaWords = static_cast<std::size_t>(kTallRows) * kMaxWidth;
static_assert(2 * kBufferWords <= kArenaWords);
constexpr std::size_t kPerspectiveBandWords = static_cast<std::size_t>(kMaxBandRows) * kMaxWidth;
constexpr std::size_t kPerspectiveIndexEntries = 7000;  // the levels' upper tree nodes
constexpr int kPerspectiveTileShift = 3;                // 8 x 8 tiles
constexpr std::size_t kPerspectiveTiles =
    static_cast<std::size_t>(kMaxWidth >> kPerspectiveTileShift) *
    ((kMaxBandRows + 7) >> kPerspectiveTileShift);
struct PerspectiveStorage {
  std::uint32_t bands[2][kPerspectiveBandWords];
  UpperTreeNode nodes[kPerspectiveIndexEntries];
  OcclusionTile tiles[kPerspectiveTiles];
};
union Arena {
  constexpr Arena() : words{} {}
  std::uint32_t words[kArenaWords];
  PerspectiveStorage perspective;
};
static_assert(sizeof(PerspectiveStorage) <= sizeof(std::uint32_t) * kArenaWords);
alignas(8) Arena arena_storage;
std::uint32_t* const arena = arena_storage.words;
std::uint32_t history[kHistoryWords];
// The index the device uses (level 3: 116 nodes of the default model, 464 bytes) and a deeper one
// (level 4: 398 nodes, 1,592 bytes) for the cost table; by depth 7, 8.
constexpr int kIndexLevel = 3;
constexpr int kDeeperIndexLevel = 4;
std::array<SubtreeSize, 120> index_storage[2];
std::array<SubtreeSize, 400> deeper_index_storage[2];
BandIndex indexes[2];
BandIndex deeper_indexes[2];
Rgb565Palette palette;

struct VariantName {
  Variant variant;
  const char* name;
};
constexpr VariantName kVariants[] = {
    {Variant::kFixedBaseline, "fixed_baseline"}, {Variant::kFixedLeafCall, "fixed_leafcall"},
    {Variant::kFixedUnrolled, "fixed_unrolled"}, {Variant::kFixedSetBits, "fixed_setbits"},
    {Variant::kFixedClipped, "fixed_clipped"},   {Variant::kFixedFast, "fixed_fast"},
    {Variant::kFixedDelta, "fixed_delta"},
};
// The variants that draw every case: fixed_fast (footprint splats where a voxel covers more than a
// pixel) and fixed_delta (one pixel per leaf; on ARMv6-M its leaf loop is Thumb-1 assembly,
// renderer/delta_leaves.h).
constexpr VariantName kCaseVariants[] = {{Variant::kFixedFast, "fixed_fast"},
                                         {Variant::kFixedDelta, "fixed_delta"}};

// Draws case `number` (band rows overridden by `rows` when > 0); returns whether every band
// matched its golden, and the instructions spent in renderBands.
bool drawCase(int number, Variant variant, int index_level, std::int32_t rows, bool two_buffers,
              std::uint64_t* instructions) {
  const BandCase& c = kCases[static_cast<std::size_t>(number)];
  const Camera& camera = kCameras[c.camera];
  const ModelView& model = defaultModel();
  const LevelView& level = *model.levelOfDepth(c.depth);
  FrameSetup setup;
  if (buildFrameSetup(camera, c.depth, kDefaultFractionBits, &setup) != CameraError::kNone)
    return false;
  const BandConfig config{variant, rows > 0 ? rows : c.band_rows, c.fill, kBackground};
  const std::size_t words = bandBufferWords(camera.width, config);
  BandBuffers buffers{std::span(arena, words), {}, std::span(history)};
  if (two_buffers) buffers.second = std::span(arena + words, words);
  GoldenSink golden(number, variant, camera.width);
  const BandIndex no_index;
  const std::uint64_t start = instructionsNow();
  const BandIndex& index = index_level == kIndexLevel         ? indexes[c.depth - 7]
                           : index_level == kDeeperIndexLevel ? deeper_indexes[c.depth - 7]
                                                              : no_index;
  const BandError error = renderBands(level, setup, config, index, palette, buffers, golden.sink());
  *instructions = instructionsNow() - start - golden.flushInstructions();
  if (error != BandError::kNone) {
    print("renderBands: ");
    print(describe(error));
    print("\n");
    return false;
  }
  return golden.passed();
}

// The perspective cases (band_cases.h), each with and without occlusion culling: every band
// against the host's golden, the instructions of the frame (its set-up, the view and the walk
// tables, included; the sink's checksumming excluded) per point one walk of the whole frame
// hands over (the host's count) and per point the bands handed over.
int drawPerspectiveCases() {
  const ModelView& model = defaultModel();
  // The arena's band words are done with: it holds the perspective storage from here on.
  PerspectiveStorage& storage = *std::construct_at(&arena_storage.perspective);
  // The upper tree index of each level, built once (set-up, not per frame).
  std::array<UpperTreeIndex, format::kMaxLevels> level_indexes{};
  std::size_t used = 0;
  for (int i = 0; i < model.levelCount() && model.level(i).depth <= kMaxRenderDepth; ++i) {
    const std::size_t entries = upperTreeEntries(model.level(i));
    if (used + entries > kPerspectiveIndexEntries) {
      print("the upper tree indexes do not fit their storage\n");
      return 1;
    }
    level_indexes[static_cast<std::size_t>(i)] =
        buildUpperTreeIndex(model.level(i), std::span(storage.nodes + used, entries));
    report("perspective upper tree index of depth",
           static_cast<std::uint64_t>(model.level(i).depth));
    report("  bytes", entries * sizeof(UpperTreeNode));
    used += entries;
  }
  report("perspective upper tree indexes, all levels, bytes", used * sizeof(UpperTreeNode));
  report("perspective occlusion tiles bytes (24-row band, 320 wide)",
         occlusionTileCount(320, 24, kPerspectiveTileShift) * sizeof(OcclusionTile));
  report("perspective walk tables bytes per level", sizeof(PerspectiveWalkTables));
  // One per level of the default model (depths 6, 7 and 8), not format::kMaxLevels: with five
  // affine thresholds a table is 704 bytes larger, and the M0+'s RAM holds the arena beside them.
  constexpr std::size_t kTableLevels = 3;
  static std::array<PerspectiveWalkTables, kTableLevels> tables;
  if (static_cast<std::size_t>(model.levelCount()) > kTableLevels) {
    print("the walk tables do not fit their storage\n");
    return 1;
  }
  int failures = 0;
#ifdef OCTOPOINT_MCU_PROFILE
  constexpr int kCasesDrawn = 1;
  constexpr std::array<bool, 1> kCullings{false};
#else
  constexpr int kCasesDrawn = kPerspectiveCaseCount;
  constexpr std::array<bool, 2> kCullings{false, true};
#endif
  for (int i = 0; i < kCasesDrawn; ++i) {
    const PerspectiveCase& c = kPerspectiveCases[static_cast<std::size_t>(i)];
    for (const bool cull : kCullings) {
      GoldenSink golden(kGoldenPerspectiveBands + kGoldenPerspectiveFirst[i], c.band_rows,
                        c.camera.width, c.camera.height);
      PerspectiveDrawStats stats;
      const std::uint64_t start = instructionsNow();
      PerspectiveView view;
      bool drawn =
          buildPerspectiveView(c.camera, kDefaultFractionBits, &view) == PerspectiveError::kNone;
      const PerspectiveLayers layers = perspectiveLayers(model, view, 0, level_indexes, tables);
      const std::uint64_t set_up = instructionsNow() - start;
      PerspectiveBandFrame frame{layers.layers(), &layers.detail, &view, {}, kPerspectiveTileShift};
      if (cull) frame.tiles = std::span(storage.tiles);
      const std::size_t words =
          static_cast<std::size_t>(c.camera.width) * static_cast<std::size_t>(c.band_rows);
      const BandBuffers buffers{
          std::span(storage.bands[0], words), std::span(storage.bands[1], words), {}};
      drawn = drawn && layers.count > 0 &&
              renderPerspectiveBands(frame, c.band_rows, palette, buffers, golden.sink(), &stats) ==
                  BandError::kNone;
      const std::uint64_t instructions = instructionsNow() - start - golden.flushInstructions();
      const bool passed = drawn && golden.passed();
      failures += passed ? 0 : 1;
      const std::uint64_t points = kGoldenPerspectivePoints[i];
      print(passed ? "pass" : "FAIL");
      print(" perspective case ");
      printUnsigned(static_cast<std::uint64_t>(i));
      print(" rows ");
      printUnsigned(static_cast<std::uint64_t>(c.band_rows));
      print(cull ? " culled" : " unculled");
      print(" instructions ");
      printUnsigned(instructions);
      print(" set-up ");
      printUnsigned(set_up);
      print(" points (one walk) ");
      printUnsigned(points);
      print(" per point ");
      printUnsigned(points == 0 ? 0 : longDivide(instructions + points / 2, points).quotient);
      print(" points (bands) ");
      printUnsigned(stats.leaves);
      print(" hidden subtrees ");
      printUnsigned(stats.hidden_subtrees);
      print("\n");
    }
  }
  return failures;
}

int caseNumber(int camera, int depth, bool fill, std::int32_t rows) {
  for (int i = 0; i < kCaseCount; ++i) {
    const BandCase& c = kCases[static_cast<std::size_t>(i)];
    if (c.camera == camera && c.depth == depth && c.fill == fill && c.band_rows == rows) return i;
  }
  return -1;
}

}  // namespace

int octopoint::mcu::programMain() {
  startInstructionClock();
  if (!calibrateInstructionClock()) {
    print(
        "the instruction clock does not count one instruction per nanosecond: is qemu run with "
        "-icount shift=0?\n");
    return 1;
  }
  const ModelView& model = defaultModel();
  palette = makeRgb565Palette(model, kBackground);
  for (int d = 0; d < 2; ++d) {
    indexes[d] = buildBandIndex(*model.levelOfDepth(7 + d), kIndexLevel, index_storage[d]);
    deeper_indexes[d] =
        buildBandIndex(*model.levelOfDepth(7 + d), kDeeperIndexLevel, deeper_index_storage[d]);
  }
  if (indexes[0].level != kIndexLevel || indexes[1].level != kIndexLevel ||
      deeper_indexes[0].level != kDeeperIndexLevel ||
      deeper_indexes[1].level != kDeeperIndexLevel) {
    print("the subtree index does not fit its storage\n");
    return 1;
  }
  int failures = 0;
  std::uint64_t instructions = 0;
#ifdef OCTOPOINT_MCU_PROFILE
  // mcu_perspective_profile: the first perspective case alone (lab/scripts/mcu-profile).
  return drawPerspectiveCases();
#endif

  for (const VariantName& v : kCaseVariants) {
    for (int i = 0; i < kCaseCount; ++i) {
      const BandCase& c = kCases[static_cast<std::size_t>(i)];
      const bool passed = drawCase(i, v.variant, kIndexLevel, 0, true, &instructions);
      failures += passed ? 0 : 1;
      print(passed ? "pass " : "FAIL ");
      print(v.name);
      print(" case camera ");
      printUnsigned(static_cast<std::uint64_t>(c.camera));
      print(" depth ");
      printUnsigned(static_cast<std::uint64_t>(c.depth));
      print(c.fill ? " fill" : " nofill");
      print(" rows ");
      printUnsigned(static_cast<std::uint64_t>(c.band_rows));
      print(" instructions ");
      printUnsigned(instructions);
      print("\n");
    }
  }

  for (const int camera : {0, 2}) {
    const std::uint64_t leaves = model.levelOfDepth(8)->leaves.size();
    for (const VariantName& v : kVariants) {
      for (const std::int32_t rows : {std::int32_t{8}, std::int32_t{24}, kTallRows}) {
        for (const int index_level : {0, kIndexLevel, kDeeperIndexLevel}) {
          // Checked against the 24-row goldens when drawn in 120-row bands (5 slices each).
          const int number = caseNumber(camera, 8, false, rows == kTallRows ? 24 : rows);
          const bool passed = drawCase(number, v.variant, index_level, rows, false, &instructions);
          failures += passed ? 0 : 1;
          print(passed ? "pass" : "FAIL");
          print(" cost ");
          print(v.name);
          print(" size ");
          printUnsigned(static_cast<std::uint64_t>(kCameras[camera].width));
          print("x");
          printUnsigned(static_cast<std::uint64_t>(kCameras[camera].height));
          print(" rows ");
          printUnsigned(static_cast<std::uint64_t>(rows));
          print(" index ");
          printUnsigned(static_cast<std::uint64_t>(index_level));
          print(" instructions ");
          printUnsigned(instructions);
          print(" leaves ");
          printUnsigned(leaves);
          print("\n");
        }
      }
    }
  }

  failures += drawPerspectiveCases();

  report("stack high-water bytes", stackHighWater());
  report("stack region bytes", stackBytes());
  report("failures", static_cast<std::uint64_t>(failures));
  return failures == 0 && stackHighWater() < stackBytes() ? 0 : 1;
}
