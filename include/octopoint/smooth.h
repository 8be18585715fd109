#pragma once
// octopoint/smooth.h: Smooth close-ups, blended splats in integer arithmetic (docs/splats.md,
// "Smooth splats"). The manual of the whole library is octopoint/octopoint.h.
//
// Magnified, a box splat (octopoint/camera.h) is a flat square of one palette colour. A smooth
// frame reconstructs a surface instead, as EWA surface splatting does (Zwicker et al. 2001) but in
// integers: every leaf adds weight * colour to the pixels within its kernel's reach, the weight
// falling off from the leaf's centre by a separable integer table, and each pixel divides by the
// weights it received. Three passes, each independent of the order leaves arrive in:
//   1. the box frame (renderLevel by fixed_fast or fixed_simd): each pixel's nearest depth;
//   2. every leaf within the kernel's reach of a pixel and within the depth tolerance of that
//      pixel's nearest depth adds its weighted colour and its weight (integer sums commute);
//   3. per pixel, covered where the summed weight passes a threshold (round silhouettes, not the
//      voxels' staircase), its colour the weighted mean.
// Where a voxel's edge is at most one pixel (voxelEdgeOnScreen: depth auto's voxels, even where a
// turned one's footprint is 2 x 1 or 2 x 2) nothing is blended: the frame and its colours are the
// box frame's, bit for bit.

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "octopoint/camera.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "octopoint/render.h"
#include "octopoint/styles.h"

namespace octopoint {

// How a magnified leaf is drawn: `box` (the default) fills its footprint with its colour, `smooth`
// blends it with its neighbours.
enum class SplatMode : std::uint8_t { kBox, kSmooth };

struct SplatModeInfo {
  SplatMode mode;
  std::string_view name;  // what users pass to `octopoint-render --splats`
  std::string_view summary;
};

std::span<const SplatModeInfo> allSplatModes();
[[nodiscard]] std::optional<SplatMode> splatModeFromName(std::string_view name);
std::string_view splatModeName(SplatMode mode);

// A model's 256 palette colours (entries past its palette are black).
using PaletteRgb = std::array<Rgb, 256>;
PaletteRgb paletteOf(const ModelView& model);

// The blending buffers for frames of one size: kBytesPerPixel a pixel besides the frame's own 4
// (kBytesPerPixelWithNormals where normals are blended), allocated once, at construction, or
// the caller's (Memory); blending never allocates.
class SmoothSplats {
 public:
  // Red, green, blue and weight sums, 32 bits each.
  static constexpr std::size_t kBytesPerPixel = 16;
  // And x, y, z sums of the normals, 32 bits each.
  static constexpr std::size_t kBytesPerPixelWithNormals = 28;

  struct Sums {
    std::uint32_t r, g, b, weight;
  };

  // Memory the caller gives instead (a device without a heap: docs/device.md): `sums` of at least
  // width * height entries, `column_weights` of at least width and `row_weights` of at least
  // height. Colour frames only (no normals are blended); smaller spans make buffers that refuse
  // every frame. The object then never allocates.
  struct Memory {
    std::span<Sums> sums;
    std::span<std::uint16_t> column_weights;
    std::span<std::uint16_t> row_weights;
  };

  // For frames of width x height pixels, each 1..kMaxViewportSide (or as wide and fewer rows: the
  // bands of a band renderer, octopoint/bands.h); any other size makes buffers that refuse every
  // frame.
  SmoothSplats(std::int32_t width, std::int32_t height);
  SmoothSplats(std::int32_t width, std::int32_t height, const Memory& memory);
  // Not copied (the sums are large, and a copy's spans would name the original's memory); moved
  // whole, its vectors' memory with it.
  SmoothSplats(const SmoothSplats&) = delete;
  SmoothSplats& operator=(const SmoothSplats&) = delete;
  SmoothSplats(SmoothSplats&&) = default;
  SmoothSplats& operator=(SmoothSplats&&) = default;
  explicit SmoothSplats(const FrameSetup& setup) : SmoothSplats(setup.width, setup.height) {}
  // The same, and where `model` has normals, buffers that also blend them: a frame cleared with
  // PixelPayload::kColourNormal (for the styles, octopoint/styles.h) of one of `model`'s levels
  // gets a blended unit normal per covered pixel (pixelBlend), weighted as its colour is.
  SmoothSplats(std::int32_t width, std::int32_t height, const ModelView& model);

  // Passes 2 and 3 over `frame`, which holds `level`'s box frame drawn with `setup` by a variant
  // that draws splats (drawsSplats), cleared to PixelPayload::kColour: begin, accumulate, finish.
  // Pixels whose blended weight stays below the threshold become kEmpty in `frame`; the others
  // keep their box word (depth and palette index) and get a blended colour here, read by
  // resolveToRgb or a style (pixelBlend). A frame of another size than the buffers', of normals
  // where the buffers were not made for a model with normals, or a set-up checkRender refuses for
  // `level` are refused: false, nothing changed. When `abort` becomes true, returns
  // false at the next poll (the frame is then incomplete). Returns true for a complete frame.
  [[nodiscard]] bool blend(const LevelView& level, const FrameSetup& setup, FrameView& frame,
                           const PaletteRgb& palette, const std::atomic<bool>* abort = nullptr);

  // The three steps of blend, for a frame several levels share (each drawn into it first, as
  // renderLevel allows): begin once, accumulate each level (in any order: the frame is the
  // same), finish once. Each refuses (false) what blend refuses.
  [[nodiscard]] bool begin(const FrameSetup& setup, const FrameView& frame);
  [[nodiscard]] bool accumulate(const LevelView& level, const FrameSetup& setup,
                                const FrameView& frame, const PaletteRgb& palette,
                                const std::atomic<bool>* abort = nullptr);
  [[nodiscard]] bool finish(FrameView& frame);

  // RGB888 of the last blended frame (`frame` as blend left it): blended colours, `background`
  // where empty; after a set-up without splats, the palette colours of the box frame exactly as
  // octopoint::resolveToRgb gives them. `rgb` must hold width * height * 3 bytes and `frame` be
  // the buffers' size: otherwise nothing is written and the result is false.
  [[nodiscard]] bool resolveToRgb(const FrameView& frame, const PaletteRgb& palette, Rgb background,
                                  std::span<std::uint8_t> rgb) const;
  // The same in RGB565 (octopoint/framebuffer.h, packedToRgb565: halfword i into bytes 2i and
  // 2i + 1 of `out`, which may be the frame's own words): blended colours rounded down to 5, 6 and
  // 5 bits, palette.background where empty; after a set-up without splats, packedToRgb565's.
  [[nodiscard]] bool resolveToRgb565(const FrameView& frame, const Rgb565Palette& palette,
                                     std::uint8_t* out) const;

  // The last blended frame's own colours (and, in a kColourNormal frame, normals in view axes) for
  // FrameStyler::resolve; empty (the palettes') after a set-up without splats, where the frame is
  // the box frame.
  PixelBlend pixelBlend() const;

  std::int32_t width() const { return width_; }
  std::int32_t height() const { return height_; }

 private:
  bool fits(const FrameSetup& setup, const FrameView& frame) const;

  std::int32_t width_;
  std::int32_t height_;
  bool blended_ = false;         // whether the frame blends (begin's set-up had splats)
  bool blends_normals_ = false;  // and its normals (a kColourNormal frame)
  PixelRect blended_rect_;       // where the sums are kept: the box frame's drawn rectangle
  // width * height sums (pass 3 leaves the colour packed in r) and one leaf's weights per column
  // and row within its reach (Q8, kept here so that a leaf of any size costs no allocation): in
  // the owned vectors, or in the caller's Memory.
  std::span<Sums> sums_;
  std::span<std::uint16_t> column_weight_, row_weight_;
  std::vector<Sums> owned_sums_;
  std::vector<std::uint16_t> owned_column_weight_, owned_row_weight_;
  // width * height normal sums (view axes), which pass 3 makes unit vectors (Q1.14); empty for
  // a model without normals.
  std::vector<DirectionQ14> normal_sums_;
  int normal_count_ = 0;
  std::array<NormalQ14, 256> normal_palette_{};  // the model's, Q1.14
};

// Draws `level` smoothly: renderLevel(variant, ...) into `frame` (cleared by the caller to
// PixelPayload::kColour), then smooth.blend. False when either refuses or is aborted.
[[nodiscard]] bool renderSmooth(Variant variant, const LevelView& level, const FrameSetup& setup,
                                FrameView& frame, SmoothSplats& smooth, const PaletteRgb& palette,
                                const std::atomic<bool>* abort = nullptr);

}  // namespace octopoint
