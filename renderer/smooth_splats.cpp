// Smooth splats (octopoint/smooth.h, docs/splats.md "Smooth splats"): passes 2 and 3 over a box
// frame. Integers only: weights Q8 per axis, their product Q12, colour sums in 32 bits.

#include <algorithm>
#include <array>

#include "octopoint/smooth.h"
#include "renderer/bit_scan.h"
#include "renderer/decode_algorithms.h"
#include "renderer/subtree_clip.h"

namespace octopoint {
namespace {

constexpr std::array kModes = {
    SplatModeInfo{SplatMode::kBox, "box", "each magnified voxel a flat rectangle of its colour"},
    SplatModeInfo{SplatMode::kSmooth, "smooth",
                  "magnified voxels blended with their neighbours, round silhouettes"},
};

// The kernel's table: the weight at a distance of i / kKernelSteps of the kernel's radius, Q8
// (256 at the centre, falling to 1 at the last step). The cubic 1 - 3t^2 + 2t^3 sums to one
// between two samples a radius apart, as the tent 1 - t does, but joins them without a crease.
constexpr int kKernelSteps = 256;
constexpr std::array<std::uint16_t, kKernelSteps> kKernel = [] {
  std::array<std::uint16_t, kKernelSteps> table{};
  constexpr std::int64_t kOne = kKernelSteps;  // t = i / kOne
  for (std::int64_t i = 0; i < kKernelSteps; ++i) {
    // 256 (1 - 3t^2 + 2t^3) = (256 kOne^3 - 768 i^2 kOne + 512 i^3) / kOne^3, rounded.
    const std::int64_t scaled = 256 * kOne * kOne * kOne - 768 * i * i * kOne + 512 * i * i * i;
    const std::int64_t weight = (scaled + kOne * kOne * kOne / 2) / (kOne * kOne * kOne);
    table[static_cast<std::size_t>(i)] =
        static_cast<std::uint16_t>(std::max<std::int64_t>(weight, 1));
  }
  return table;
}();

// The kernel's radius, in sixteenths of the voxel's edge on screen (voxelEdgeOnScreen), the
// spacing of neighbouring centres: a radius of one spacing lets every pixel between two centres
// take both. The same on both axes: a turned voxel's footprint is wider than its edge, but its
// neighbours are no farther apart.
constexpr std::int64_t kRadiusSixteenths = 16;
// Contributions whose depth key differs from the pixel's nearest by more than this many voxel
// edges belong to another surface (one behind, or one in front that does not cover the pixel).
// Measured on a dense sphere turned 30 degrees (tests/core/smooth_splats_test.cpp): 2 edges left
// holes up to 1.7 voxels inside its outline, where the surface turns away and neighbouring
// voxels within the kernel's reach lie deeper; 4 leaves none.
constexpr std::uint64_t kDepthToleranceVoxelEdges = 4;
// A pixel is covered where its summed weight (Q12: one leaf's centre is 4096) is at least this.
// On the default model at 480x360 zoom 3, 2048 and 3072 opened cracks the box frame does not
// have where the scan is sparse (a pixel few leaves reach); 1024 keeps the box frame's coverage
// inside a surface and rounds the outline of a turned one (docs/splats.md).
constexpr std::uint32_t kCoverWeight = 1024;

// A leaf's weight product wx * wy (Q16) is kept Q12, so that a contribution, colour times weight,
// is below 2^20: a pixel's sums wrap only past 4,096 full-weight contributions, where the leaves
// within a kernel's reach and the depth tolerance are a few dozen.
constexpr int kProductShift = 4;

class BlendWalk {
 public:
  BlendWalk(const LevelView& level, const FrameSetup& setup, const FrameView& frame,
            SmoothSplats::Sums* sums, const PaletteRgb& palette, std::uint16_t* column_weight,
            std::uint16_t* row_weight, const std::atomic<bool>* abort)
      : node_(level.nodes.data()),
        leaf_(level.leaves.data()),
        setup_(setup),
        words_(frame.pixels().data()),
        sums_(sums),
        palette_(palette),
        column_weight_(column_weight),
        row_weight_(row_weight),
        abort_(abort),
        radius_x_(radiusOf(setup)),
        radius_y_(radius_x_),
        inverse_x_((std::uint64_t{kKernelSteps} << 32) / static_cast<std::uint64_t>(radius_x_)),
        inverse_y_((std::uint64_t{kKernelSteps} << 32) / static_cast<std::uint64_t>(radius_y_)),
        tolerance_(static_cast<std::uint32_t>(std::min<std::uint64_t>(
            (voxelEdgeOnScreen(setup) * kDepthToleranceVoxelEdges) >> setup.depth_shift,
            FrameView::kMaxDepthKey))),
        clip_(setup, kernelReach()) {}

  bool run() {
    visit(0, setup_.root);
    return !aborted_;
  }

 private:
  // Q(32-F).F; at least one pixel, so that a leaf always reaches the pixel it lies in.
  static std::int64_t radiusOf(const FrameSetup& setup) {
    const auto edge = static_cast<std::int64_t>(voxelEdgeOnScreen(setup));
    const std::int64_t edge_or_pixel =
        std::max<std::int64_t>(edge, std::int64_t{1} << setup.fraction_bits);
    return std::max<std::int64_t>(edge_or_pixel * kRadiusSixteenths / 16, 1);
  }

  // The pixels a leaf reaches, as a footprint for SubtreeClip: p - R .. p + R per axis.
  SplatFootprint kernelReach() const {
    SplatFootprint reach;
    reach.offset_x = static_cast<std::int32_t>(-radius_x_);
    reach.offset_y = static_cast<std::int32_t>(-radius_y_);
    reach.span_x = static_cast<std::int32_t>(2 * radius_x_);
    reach.span_y = static_cast<std::int32_t>(2 * radius_y_);
    return reach;
  }

  void visit(int level, const Vec3& centre) {
    if (level == kAbortCheckLevel && abort_ != nullptr && !aborted_) {
      aborted_ = abort_->load(std::memory_order_relaxed);
    }
    if (aborted_) return;
    if (clip_.classify(level, centre) == Clip::kOutside) {
      skipSubtree(node_, leaf_, level, setup_.depth);
      return;
    }
    unsigned mask = *node_++;
    const auto& offsets = setup_.child_offset[static_cast<std::size_t>(level)];
    if (level + 1 == setup_.depth) {
      for (; mask != 0; mask &= mask - 1) add(centre + offsets[lowestChild(mask)], *leaf_++);
      return;
    }
    for (; mask != 0; mask &= mask - 1) visit(level + 1, centre + offsets[lowestChild(mask)]);
  }

  // The columns (or rows) whose pixel centre lies within `radius` of `at` (Q(32-F).F), clipped to
  // [0, size), with each one's weight into `weight`: [begin, end).
  struct Span {
    std::int32_t begin, end;
  };
  Span weigh(std::int32_t at, std::int64_t radius, std::uint64_t inverse, std::int32_t size,
             std::uint16_t* weight) const {
    const int f = setup_.fraction_bits;
    const std::int64_t half = std::int64_t{1} << (f - 1);
    // Centre c = x 2^F + half: inside where at - radius < c < at + radius.
    const std::int64_t first = ((at - radius - half) >> f) + 1;
    const std::int64_t last = (at + radius - half - 1) >> f;
    const auto begin = static_cast<std::int32_t>(std::max<std::int64_t>(first, 0));
    const auto end = static_cast<std::int32_t>(std::min<std::int64_t>(last + 1, size));
    for (std::int32_t i = begin; i < end; ++i) {
      const std::int64_t offset = (std::int64_t{i} << f) + half - at;
      const auto distance = static_cast<std::uint64_t>(offset < 0 ? -offset : offset);  // < radius
      weight[i - begin] = kKernel[static_cast<std::size_t>((distance * inverse) >> 32)];
    }
    return {begin, end};
  }

  void add(const Vec3& p, std::uint8_t colour_index) {
    const Span columns = weigh(p.x, radius_x_, inverse_x_, setup_.width, column_weight_);
    if (columns.begin >= columns.end) return;
    const Span rows = weigh(p.y, radius_y_, inverse_y_, setup_.height, row_weight_);
    const std::uint32_t key = setup_.depthKey(p.z);
    const Rgb colour = palette_[colour_index];
    const std::uint32_t twice_tolerance = 2 * tolerance_;
    const auto width = static_cast<std::size_t>(setup_.width);
    for (std::int32_t y = rows.begin; y < rows.end; ++y) {
      const std::uint32_t row_weight = row_weight_[y - rows.begin];
      const std::size_t row = static_cast<std::size_t>(y) * width;
      for (std::int32_t x = columns.begin; x < columns.end; ++x) {
        const std::uint32_t word = words_[row + static_cast<std::size_t>(x)];
        // Within the tolerance of the pixel's nearest depth, either side (unsigned: one compare).
        if (word == FrameView::kEmpty ||
            key - FrameView::depthKeyOf(word) + tolerance_ > twice_tolerance) {
          continue;
        }
        const std::uint32_t weight =
            (row_weight * column_weight_[x - columns.begin]) >> kProductShift;  // Q12
        SmoothSplats::Sums& sum = sums_[row + static_cast<std::size_t>(x)];
        sum.r += weight * colour.r;
        sum.g += weight * colour.g;
        sum.b += weight * colour.b;
        sum.weight += weight;
      }
    }
  }

  const std::uint8_t* node_;
  const std::uint8_t* leaf_;
  const FrameSetup& setup_;
  const std::uint32_t* words_;
  SmoothSplats::Sums* sums_;
  const PaletteRgb& palette_;
  std::uint16_t* column_weight_;
  std::uint16_t* row_weight_;
  const std::atomic<bool>* abort_;
  std::int64_t radius_x_, radius_y_;     // the kernel's radius, Q(32-F).F
  std::uint64_t inverse_x_, inverse_y_;  // kKernelSteps 2^32 / radius: distance to table step
  std::uint32_t tolerance_;              // depth-key units
  SubtreeClip clip_;
  bool aborted_ = false;
};

bool validSize(std::int32_t width, std::int32_t height) {
  return width >= 1 && width <= kMaxViewportSide && height >= 1 && height <= kMaxViewportSide;
}

std::size_t pixelCount(std::int32_t width, std::int32_t height) {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

std::uint32_t packRgb(std::uint32_t r, std::uint32_t g, std::uint32_t b) {
  return r << 16 | g << 8 | b;
}

}  // namespace

std::span<const SplatModeInfo> allSplatModes() { return kModes; }

std::optional<SplatMode> splatModeFromName(std::string_view name) {
  for (const SplatModeInfo& info : kModes) {
    if (info.name == name) return info.mode;
  }
  return std::nullopt;
}

std::string_view splatModeName(SplatMode mode) {
  for (const SplatModeInfo& info : kModes) {
    if (info.mode == mode) return info.name;
  }
  return {};
}

PaletteRgb paletteOf(const ModelView& model) {
  PaletteRgb palette{};
  for (int i = 0; i < model.paletteCount(); ++i)
    palette[static_cast<std::size_t>(i)] = model.paletteColour(i);
  return palette;
}

SmoothSplats::SmoothSplats(std::int32_t width, std::int32_t height)
    : width_(validSize(width, height) ? width : 0),
      height_(validSize(width, height) ? height : 0),
      sums_(pixelCount(width_, height_)),
      column_weight_(static_cast<std::size_t>(width_)),
      row_weight_(static_cast<std::size_t>(height_)) {}

bool SmoothSplats::fits(const FrameSetup& setup, const FrameView& frame) const {
  return width_ != 0 && frame.width() == width_ && frame.height() == height_ &&
         frame.payload() == PixelPayload::kColour && checkFrameSetup(setup) == RenderError::kNone &&
         setup.width == width_ && setup.height == height_;
}

bool SmoothSplats::begin(const FrameSetup& setup, const FrameView& frame) {
  if (!fits(setup, frame)) return false;
  // Magnified: a voxel's edge longer than a pixel. A turned voxel of depth auto (edge at most a
  // pixel, footprint up to 2 x 2) is drawn as the box frame draws it: its kernel would be under
  // a pixel wide, and blending it cost 4 to 8 times the box frame (docs/splats.md).
  blended_ =
      setup.splat.active() && voxelEdgeOnScreen(setup) > (std::uint64_t{1} << setup.fraction_bits);
  blended_rect_ = blended_ ? frame.drawnRect() : PixelRect{};
  if (blended_rect_.empty()) return true;
  const auto width = static_cast<std::size_t>(width_);
  for (std::int32_t y = blended_rect_.y_begin; y < blended_rect_.y_end; ++y) {
    Sums* const row = sums_.data() + static_cast<std::size_t>(y) * width;
    std::fill(row + blended_rect_.x_begin, row + blended_rect_.x_end, Sums{0, 0, 0, 0});
  }
  return true;
}

bool SmoothSplats::accumulate(const LevelView& level, const FrameSetup& setup,
                              const FrameView& frame, const PaletteRgb& palette,
                              const std::atomic<bool>* abort) {
  if (!fits(setup, frame) || checkRender(level, setup, frame) != RenderError::kNone) return false;
  if (!blended_ || blended_rect_.empty()) return true;  // nothing to blend
  return BlendWalk(level, setup, frame, sums_.data(), palette, column_weight_.data(),
                   row_weight_.data(), abort)
      .run();
}

bool SmoothSplats::finish(FrameView& frame) {
  if (width_ == 0 || frame.width() != width_ || frame.height() != height_) return false;
  if (!blended_ || blended_rect_.empty()) return true;
  // Covered pixels lie in the rectangle the box frame drew: the rest is kEmpty.
  const PixelRect& rect = blended_rect_;
  const auto width = static_cast<std::size_t>(width_);
  std::uint32_t* const words = frame.pixelsToDraw(rect);
  for (std::int32_t y = rect.y_begin; y < rect.y_end; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * width;
    for (std::int32_t x = rect.x_begin; x < rect.x_end; ++x) {
      std::uint32_t& word = words[row + static_cast<std::size_t>(x)];
      if (word == FrameView::kEmpty) continue;
      Sums& sum = sums_[row + static_cast<std::size_t>(x)];
      if (sum.weight < kCoverWeight) {
        word = FrameView::kEmpty;
        continue;
      }
      const std::uint32_t half = sum.weight / 2;  // rounded to nearest
      sum.r = packRgb((sum.r + half) / sum.weight, (sum.g + half) / sum.weight,
                      (sum.b + half) / sum.weight);
    }
  }
  return true;
}

bool SmoothSplats::blend(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                         const PaletteRgb& palette, const std::atomic<bool>* abort) {
  if (!fits(setup, frame) || checkRender(level, setup, frame) != RenderError::kNone) return false;
  return begin(setup, frame) && accumulate(level, setup, frame, palette, abort) && finish(frame);
}

bool SmoothSplats::resolveToRgb(const FrameView& frame, const PaletteRgb& palette, Rgb background,
                                std::span<std::uint8_t> rgb) const {
  if (width_ == 0 || frame.width() != width_ || frame.height() != height_ ||
      rgb.size() < pixelCount(width_, height_) * 3) {
    return false;
  }
  const std::span<const std::uint32_t> words = frame.pixels();
  std::size_t at = 0;
  for (std::int32_t y = 0; y < height_; ++y) {
    const bool blended_row = blended_ && y >= blended_rect_.y_begin && y < blended_rect_.y_end;
    for (std::int32_t x = 0; x < width_; ++x, ++at) {
      const std::uint32_t word = words[at];
      Rgb colour = background;
      if (word != FrameView::kEmpty) {
        if (blended_row && x >= blended_rect_.x_begin && x < blended_rect_.x_end) {
          const std::uint32_t packed = sums_[at].r;
          colour = {static_cast<std::uint8_t>(packed >> 16), static_cast<std::uint8_t>(packed >> 8),
                    static_cast<std::uint8_t>(packed)};
        } else {
          colour = palette[FrameView::colourIndexOf(word)];
        }
      }
      rgb[3 * at + 0] = colour.r;
      rgb[3 * at + 1] = colour.g;
      rgb[3 * at + 2] = colour.b;
    }
  }
  return true;
}

bool renderSmooth(Variant variant, const LevelView& level, const FrameSetup& setup,
                  FrameView& frame, SmoothSplats& smooth, const PaletteRgb& palette,
                  const std::atomic<bool>* abort) {
  // Pass 1 needs the footprints: a variant that sets one pixel per leaf finds no nearest depth
  // where a magnified voxel's other pixels lie.
  if (setup.splat.active() && !drawsSplats(variant)) return false;
  if (frame.payload() != PixelPayload::kColour || smooth.width() != frame.width() ||
      smooth.height() != frame.height()) {
    return false;
  }
  return renderLevel(variant, level, setup, frame, abort) &&
         smooth.blend(level, setup, frame, palette, abort);
}

}  // namespace octopoint
