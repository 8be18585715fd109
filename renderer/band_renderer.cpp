#include <algorithm>
#include <array>
#include <cstdlib>
#include <limits>

#include "octopoint/bands.h"
#include "octopoint/framebuffer.h"
#include "octopoint/render.h"
#include "renderer/band_turns.h"
#include "renderer/bit_scan.h"
#include "renderer/decode_algorithms.h"
#include "renderer/render_fixed_delta.h"
#include "renderer/subtree_clip.h"

namespace octopoint {
namespace {

// Sum over levels l >= from of the largest |offset| on each axis: how far the leaves of a node at
// tree level `from` lie from its centre (as SubtreeClip's reach), Q(32-F).F.
void reachFrom(const FrameSetup& setup, int from, std::int64_t* reach_x, std::int64_t* reach_y) {
  *reach_x = *reach_y = 0;
  for (int l = from; l < setup.depth; ++l) {
    std::int64_t widest_x = 0, widest_y = 0;
    for (const Vec3& d : setup.child_offset[static_cast<std::size_t>(l)]) {
      widest_x = std::max<std::int64_t>(widest_x, std::llabs(d.x));
      widest_y = std::max<std::int64_t>(widest_y, std::llabs(d.y));
    }
    *reach_x += widest_x;
    *reach_y += widest_y;
  }
}

// One band drawn through the index: the levels above the index level are walked here, each
// subtree at the index level that meets the band's rows is drawn by the decoder as a tree of its
// own; the others are jumped over with the index.
class IndexedBandWalk {
 public:
  // `subtree_setup` is the index-level subtrees' set-up with the window's height: its clip's reach
  // at its level 0 is the reach of an index-level node (widened by the splat, when leaves are drawn
  // as splats), its screen the window.
  // `delta`: fixed_delta prepared for this window (then `variant` is not used): each subtree is
  // then one call, without the per-call preparation renderLevel would repeat.
  IndexedBandWalk(const LevelView& level, const FrameSetup& frame, const BandIndex& index,
                  Variant variant, FrameSetup& subtree_setup, FrameView& window,
                  std::int32_t window_y0, FixedDeltaDecoder* delta)
      : level_(level),
        frame_(frame),
        index_(index),
        variant_(variant),
        subtree_(subtree_setup),
        window_(window),
        window_clip_(subtree_setup, subtree_setup.splat),
        y_shift_(std::int64_t{window_y0} << frame.fraction_bits),
        delta_(delta) {}

  // False when the index does not fit the level (built from another level of the same depth):
  // too few or too many entries, or sizes that pass the end of the stream or do not add up to it.
  // Found on the first band, which visits every index-level node, before anything is flushed. An
  // index whose sizes add up but belong to another tree is not found in O(1) per subtree: build
  // the index from the level you draw (buildBandIndex), as a level comes from a validated model.
  bool run() {
    const std::uint8_t* node = level_.nodes.data();
    std::uint32_t leaf = 0;
    visit(0, frame_.root, node, leaf);
    return fits_ && entry_ == index_.sizes.size() &&
           node == level_.nodes.data() + level_.nodes.size() && leaf == level_.leaves.size();
  }

 private:
  void visit(int l, const Vec3& centre, const std::uint8_t*& node, std::uint32_t& leaf) {
    if (!fits_) return;
    if (l == index_.level) {
      const auto node_begin = static_cast<std::size_t>(node - level_.nodes.data());
      if (entry_ == index_.sizes.size() ||
          index_.sizes[entry_].nodes > level_.nodes.size() - node_begin ||
          index_.sizes[entry_].leaves > level_.leaves.size() - leaf) {
        fits_ = false;
        return;
      }
      const SubtreeSize& size = index_.sizes[entry_++];
      // In window coordinates (bandFrameSetup proved that every shifted coordinate fits 32 bits).
      const Vec3 shifted{centre.x, static_cast<std::int32_t>(centre.y - y_shift_), centre.z};
      if (window_clip_.classify(0, shifted) != Clip::kOutside) draw(shifted, node, leaf, size);
      node += size.nodes;
      leaf += size.leaves;
      return;
    }
    if (node == level_.nodes.data() + level_.nodes.size()) {
      fits_ = false;
      return;
    }
    const auto& offsets = frame_.child_offset[static_cast<std::size_t>(l)];
    for (unsigned mask = *node++; mask != 0; mask &= mask - 1) {
      visit(l + 1, centre + offsets[lowestChild(mask)], node, leaf);
    }
  }

  void draw(const Vec3& root, const std::uint8_t* node, std::uint32_t leaf,
            const SubtreeSize& size) {
    const auto node_begin = static_cast<std::size_t>(node - level_.nodes.data());
    const LevelView subtree{subtree_.depth, level_.nodes.subspan(node_begin, size.nodes),
                            level_.leaves.subspan(leaf, size.leaves)};
    if (delta_ != nullptr) {
      delta_->draw(subtree, root);
      return;
    }
    subtree_.root = root;
    // A subtree of a validated level with the window's set-up is never refused; if it were, the
    // band would be incomplete, so the walk reports the index as not fitting.
    if (!renderLevel(variant_, subtree, subtree_, window_)) fits_ = false;
  }

  const LevelView& level_;
  const FrameSetup& frame_;
  const BandIndex& index_;
  Variant variant_;
  FrameSetup& subtree_;
  FrameView& window_;
  SubtreeClip window_clip_;
  std::int64_t y_shift_;
  FixedDeltaDecoder* delta_;
  std::size_t entry_ = 0;
  bool fits_ = true;
};

}  // namespace

CameraError bandFrameSetup(const FrameSetup& frame, std::int32_t y0, std::int32_t rows,
                           FrameSetup* band) {
  if (y0 < 0 || rows < 1 || rows > frame.height - y0) return CameraError::kBadViewport;
  std::int64_t reach_x = 0, reach_y = 0;
  reachFrom(frame, 0, &reach_x, &reach_y);
  const std::int64_t root_y =
      std::int64_t{frame.root.y} - (std::int64_t{y0} << frame.fraction_bits);
  // As buildFrameSetup: every leaf's coordinate, every partial sum and every splat row stays
  // strictly inside int32.
  const std::int64_t splat_y =
      std::max(std::llabs(frame.splat.offset_y),
               std::llabs(std::int64_t{frame.splat.offset_y} + frame.splat.span_y));
  if (std::llabs(root_y) + reach_y + splat_y >= std::numeric_limits<std::int32_t>::max())
    return CameraError::kOverflow;
  *band = frame;
  band->root.y = static_cast<std::int32_t>(root_y);
  band->height = rows;
  band->camera.height = rows;
  return CameraError::kNone;
}

bool supportsBands(Variant variant) { return isFixedPoint(variant); }

std::int32_t bandMarginRows(const BandConfig& config) {
  return config.fill ? kHoleFillReachRows : 0;
}

std::size_t bandBufferWords(std::int32_t width, const BandConfig& config) {
  return static_cast<std::size_t>(config.band_rows + 2 * bandMarginRows(config)) *
         static_cast<std::size_t>(width);
}

const char* describe(BandError error) {
  switch (error) {
    case BandError::kNone:
      return "no error";
    case BandError::kUnsupportedVariant:
      return "this variant does not draw bands (float reference)";
    case BandError::kBadBandRows:
      return "band rows must be at least 1";
    case BandError::kBufferTooSmall:
      return "band buffer or fill history too small";
    case BandError::kOverflow:
      return "band coordinates would overflow 32 bits";
    case BandError::kNoSink:
      return "no flush callback";
    case BandError::kRefused:
      return "level, frame set-up or band index do not fit each other";
  }
  return "unknown error";
}

namespace {

// What renderBands checks before it draws a band: kNone when every band can be drawn.
BandError checkBands(const LevelView& level, const FrameSetup& setup, const BandConfig& config,
                     const BandIndex& index, const BandBuffers& buffers, const BandSink& sink) {
  if (!supportsBands(config.variant)) return BandError::kUnsupportedVariant;
  if (config.band_rows < 1) return BandError::kBadBandRows;
  if (sink.flush == nullptr) return BandError::kNoSink;
  // What renderLevel checks on a whole frame, against the frame's own size, and an index level
  // the level can have: the band walks trust both (they would walk a level of another depth off
  // its end).
  const FrameView whole_frame(nullptr, setup.width, setup.height);
  if (checkRender(level, setup, whole_frame) != RenderError::kNone ||
      (index.level != 0 && !indexLevelAllowed(level.depth, index.level))) {
    return BandError::kRefused;
  }
  const std::size_t words = bandBufferWords(setup.width, config);
  if (buffers.first.size() < words || (!buffers.second.empty() && buffers.second.size() < words) ||
      (config.fill && buffers.fill_history.size() < holeFillHistoryWords(setup.width))) {
    return BandError::kBufferTooSmall;
  }
  return BandError::kNone;
}

// What a smooth band frame blends with (renderSmoothBands).
struct SmoothBands {
  SmoothSplats& splats;
  const PaletteRgb& colours;
};

// Blends band rows [y0, y0 + window.height()) of `setup`'s frame, drawn into `window`, and leaves
// them in RGB565 at `out`. Not inlined: its set-up (1.6 KB) is then on the stack only for smooth
// bands, not in every band renderer's frame on a microcontroller.
[[gnu::noinline]] bool blendBand(const LevelView& level, const FrameSetup& setup, std::int32_t y0,
                                 FrameView& window, const Rgb565Palette& palette,
                                 const SmoothBands& smooth, std::uint8_t* out) {
  FrameSetup band;
  return bandFrameSetup(setup, y0, window.height(), &band) == CameraError::kNone &&
         smooth.splats.blend(level, band, window, smooth.colours) &&
         smooth.splats.resolveToRgb565(window, palette, out);
}

// kBlended chooses at compile time, so that renderBands' code refers to nothing of smooth splats:
// a bare-metal image that draws box bands links no blend, and none of its divisions
// (mcu.no_hidden_helpers).
template <bool kBlended>
BandError drawBands(const LevelView& level, const FrameSetup& setup, const BandConfig& config,
                    const BandIndex& index, const Rgb565Palette& palette,
                    const BandBuffers& buffers, const BandSink& sink, const SmoothBands* smooth) {
  if (const BandError error = checkBands(level, setup, config, index, buffers, sink);
      error != BandError::kNone) {
    return error;
  }
  const std::int32_t width = setup.width, height = setup.height;
  const std::int32_t margin = bandMarginRows(config);
  const std::int32_t band_rows = std::min(config.band_rows, height);
  // One set-up on the stack (1.6 KB: it counts on a microcontroller): without an index, each band's
  // shifted frame set-up; with one, the index-level subtrees' set-up (the frame's vectors from the
  // index level down), whose root each subtree sets.
  FrameSetup work;
  // No band is shifted more than by the frame's last row: if that set-up fits, every band's does.
  if (bandFrameSetup(setup, height - 1, 1, &work) != CameraError::kNone)
    return BandError::kOverflow;
  if (index.level > 0) {
    work = setup;
    work.depth = setup.depth - index.level;
    for (int l = 0; l < kMaxRenderDepth; ++l) {
      const int from = l + index.level;
      work.child_offset[static_cast<std::size_t>(l)] =
          from < kMaxRenderDepth ? setup.child_offset[static_cast<std::size_t>(from)]
                                 : std::array<Vec3, 8>{};
    }
  }
  const std::uint32_t bridge_limit = config.fill ? bridgeDepthLimit(setup) : 0;

  int band_number = 0;
  for (std::int32_t y0 = 0; y0 < height; y0 += band_rows, ++band_number) {
    const std::int32_t rows = std::min(band_rows, height - y0);
    const std::span<std::uint32_t> buffer = bandBufferFor(buffers, band_number, sink);
    const std::int32_t window_y0 = std::max<std::int32_t>(0, y0 - margin);
    const std::int32_t window_rows = std::min(height, y0 + rows + margin) - window_y0;
    FrameView window(buffer.data(), width, window_rows);
    window.clear();
    if (index.level == 0) {
      // Neither can fail (the last row's set-up and the level were checked above): a refusal
      // would leave the band incomplete.
      if (bandFrameSetup(setup, window_y0, window_rows, &work) != CameraError::kNone ||
          !renderLevel(config.variant, level, work, window)) {
        return BandError::kRefused;
      }
    } else {
      work.height = window_rows;
      work.camera.height = window_rows;
      bool index_fits = false;
      if (config.variant == Variant::kFixedDelta) {
        FixedDeltaDecoder delta(work, window);
        index_fits =
            IndexedBandWalk(level, setup, index, config.variant, work, window, window_y0, &delta)
                .run();
      } else {
        index_fits =
            IndexedBandWalk(level, setup, index, config.variant, work, window, window_y0, nullptr)
                .run();
      }
      if (!index_fits) return BandError::kRefused;  // on the first band: nothing flushed yet
    }
    const std::int32_t first_row = y0 - window_y0;  // the band's own rows in the window
    if (config.fill &&
        fillHoleRows(window, first_row, first_row + rows, bridge_limit, buffers.fill_history)
            .refused) {
      return BandError::kRefused;  // cannot happen: the rows lie in the window, the history fits
    }
    const std::size_t pixels = static_cast<std::size_t>(rows) * static_cast<std::size_t>(width);
    const std::span<std::uint8_t> rgb565 = bytesOf(buffer).first(pixels * 2);
    if constexpr (kBlended) {  // no margin: the window is the band
      if (!blendBand(level, setup, y0, window, palette, *smooth, rgb565.data()))
        return BandError::kRefused;  // cannot happen: the set-ups and sizes were checked
    } else {
      packedToRgb565(buffer.data() + static_cast<std::ptrdiff_t>(first_row) * width, pixels,
                     palette, rgb565.data());
    }
    sink.flush(sink.user, y0, rows, rgb565);
  }
  return BandError::kNone;
}

}  // namespace

BandError renderBands(const LevelView& level, const FrameSetup& setup, const BandConfig& config,
                      const BandIndex& index, const Rgb565Palette& palette,
                      const BandBuffers& buffers, const BandSink& sink) {
  return drawBands<false>(level, setup, config, index, palette, buffers, sink, nullptr);
}

BandError renderSmoothBands(const LevelView& level, const FrameSetup& setup,
                            const BandConfig& config, const BandIndex& index,
                            const Rgb565Palette& palette, const PaletteRgb& colours,
                            const BandBuffers& buffers, SmoothSplats& smooth,
                            const BandSink& sink) {
  // Pass 1 needs the footprints where there are splats, as renderSmooth does.
  if (config.fill || (setup.splat.active() && !drawsSplats(config.variant)) ||
      smooth.width() != setup.width || smooth.height() < std::min(config.band_rows, setup.height)) {
    return BandError::kRefused;
  }
  const SmoothBands bands{smooth, colours};
  return drawBands<true>(level, setup, config, index, palette, buffers, sink, &bands);
}

}  // namespace octopoint
