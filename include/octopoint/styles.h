#pragma once
// octopoint/styles.h: Styles applied when a frame becomes RGB: colour, shaded, lines, toon,
// outlined. The manual of the whole library is octopoint/octopoint.h.

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>

#include "octopoint/camera.h"
#include "octopoint/fixed.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"

// How a frame becomes a picture (docs/styles.md): in the scan's colours, lit from a light, or as a
// line drawing. Every style is applied after decoding, when the frame is turned into RGB
// (octopoint/styles.h), so the decoders' inner loops do not grow; all are integer only.
//
//   colour    the palette colours, as the scan was captured
//   shaded    colour (grey for a scan without colour) times a per-frame intensity per normal:
//             ambient + diffuse from the light (+ an optional headlight)
//   lines     white background, black silhouettes, grey creases
//   toon      the shaded colours in a few flat bands, with silhouettes and creases
//   outlined  the colour image with silhouettes and creases drawn over it
//
// Every style but colour needs a model with normals (octopoint-prepare --normals) and a frame that
// carries them (Framebuffer::clear(PixelPayload::kColourNormal)).

namespace octopoint {

enum class Style : std::uint8_t { kColour, kShaded, kLines, kToon, kOutlined };

struct StyleInfo {
  Style style;
  std::string_view name;  // what `octopoint-render --style` takes
  std::string_view summary;
};

std::span<const StyleInfo> allStyles();
[[nodiscard]] std::optional<Style> styleFromName(std::string_view name);
std::string_view styleName(Style style);
bool styleNeedsNormals(Style style);
// The next style in allStyles() order, wrapping around (the viewer's style key).
Style nextStyle(Style style);

// A light, fixed relative to the viewer: it comes from `azimuth` to the right of the viewing
// direction (negative: from the left) and `elevation` above it. Azimuth 0, elevation 0 is a light
// at the viewer's eye.
struct Light {
  Angle azimuth = Angle::fromDegrees(-30);
  Angle elevation = Angle::fromDegrees(35);
  bool headlight = false;  // a second, weaker light at the viewer's eye: no face is left black
};

// Where two neighbouring pixels' normals differ by more than this, a line style draws a crease.
inline constexpr int kDefaultCreaseDegrees = 60;

}  // namespace octopoint

// Relighting (docs/styles.md): once per frame, one integer intensity per normal palette entry, from
// the light and the camera's rotation; a lit pixel is then its colour times the intensity of its
// normal index, a table look-up when the frame becomes RGB. Botsch et al. (2002) shade quantized
// normals the same way.
//
// The light and the viewer are turned into the model's axes (the transposed camera rotation), and
// each entry's intensity is, in Q8 (256 = full):
//   ambient + diffuse * max(0, n . light) [+ headlight * max(0, n . viewer)]
// Lighting is two-sided: an entry facing away from the viewer (the back of a single-view scan, seen
// from behind) is lit as if it faced the viewer. Integer only: normals and directions are Q1.14,
// their dot products Q2.28.

namespace octopoint {

inline constexpr std::int32_t kFullIntensity = 256;  // Q8

// The share of each term at full strength (Q8, ambient + diffuse (+ headlight) = 256).
struct LightMix {
  std::int32_t ambient, diffuse, headlight;
};
inline constexpr LightMix kLightMix{64, 192, 0};
inline constexpr LightMix kHeadlightMix{48, 160, 48};

// A direction in Q1.14 (2^14 = 1.0).
struct DirectionQ14 {
  std::int32_t x = 0, y = 0, z = 0;
};

// The unit vector toward the light in view axes (x right, y down, z away from the viewer).
DirectionQ14 lightInView(const Light& light);

// The intensity (Q8) of a unit normal in view axes (Q1.14) under a light toward `to_light` (view
// axes, lightInView) and `mix`: an entry's ShadingTable intensity, computed for one normal (a
// blended pixel's, octopoint/smooth.h).
std::uint16_t intensityInView(const DirectionQ14& normal, const DirectionQ14& to_light,
                              const LightMix& mix);

class ShadingTable {
 public:
  // The intensities of `model`'s normal palette for a frame drawn with `model_to_view` (the
  // camera's rotation, octopoint/fixed.h). Entries past the palette are 0.
  void build(const ModelView& model, const Rotation& model_to_view, const Light& light);

  std::uint16_t intensity(std::uint8_t normal_index) const { return intensity_[normal_index]; }
  const std::uint16_t* data() const { return intensity_.data(); }

 private:
  std::array<std::uint16_t, 256> intensity_{};
};

}  // namespace octopoint

// The line pass of the line styles (docs/styles.md): after decoding, each covered pixel is compared
// with its four neighbours, O(pixels), integer only.
// - Silhouette: a neighbour is background, or lies farther than its own surface explains: by more
//   than `jump` (kSilhouetteVoxelEdges voxel edges, or pixels where a voxel is smaller than a
//   pixel) plus the slack of the pair's surface slope (SurfaceSlopes): the object's outline and
//   the outline of whatever stands in front of something else. Only the nearer pixel of such a
//   pair is marked, so the line is one pixel wide.
// - Crease: a neighbour is no silhouette, but the normals of the two pixels differ by more than
//   the crease angle (a table of 255 x 255 bits built once per model and angle, so the test is one
//   look-up, not a dot product). Again only one pixel of the pair is marked: the nearer, or the
//   left (upper) one of a pair at equal depth; and none where the other pixel is a silhouette
//   pixel, whose line is already there (classifyPixel).
// Neighbours outside the frame are ignored: no line along the frame's edge.
//
// Bands (drawing a frame a few rows at a time): a row's result depends on the two rows above and
// below it. `forEachStyledPixel` (octopoint/styles.h) styles rows [first_row, end_row) of a
// frame and reads rows first_row - 2 to end_row + 1 where the frame has them; a band drawn two
// rows taller at each inner edge therefore styles exactly as the whole frame does.

namespace octopoint {

inline constexpr std::uint32_t kSilhouetteVoxelEdges = 4;
// The most SurfaceSlopes credits a surface with: the slack of a surface whose depth recedes by
// kMaxSurfaceSlope pixels per pixel across the screen (about 83 degrees from facing the viewer),
// kMaxSurfaceSlope times (the larger reach + a voxel edge). A surface seen more nearly edge-on
// covers few pixels, and two such surfaces one behind the other keep their outline.
inline constexpr std::uint32_t kMaxSurfaceSlope = 8;

enum class Edge : std::uint8_t { kNone, kCrease, kSilhouette };

class CreaseTable {
 public:
  // Pairs of `model`'s normal palette entries more than `angle` apart (0 to 180 degrees). An
  // entry is never a crease with itself, whatever the rounding of its dot product at angle 0: the
  // line pass then needs no test for equal indices.
  void build(const ModelView& model, Angle angle);
  bool crease(std::uint32_t a, std::uint32_t b) const {
    return (bits_[a * 8 + (b >> 5)] >> (b & 31)) & 1u;
  }

 private:
  std::array<std::uint32_t, 256 * 8> bits_{};  // row a, bit b: 8 KiB
};

// How much farther than the jump a neighbour on the same surface may lie, per normal palette entry,
// for one frame (a kColourNormal frame's key units, word >> 16). A surface seen obliquely recedes
// by |n_x / n_z| pixels of depth per pixel along x and |n_y / n_z| along y (n the entry's normal in
// view axes), and two neighbouring pixels show the nearest of the voxels whose splats cover them:
// voxels whose centres lie up to a footprint plus one pixel apart along each axis, whichever way
// the two pixels neighbour each other; and each voxel centre lies up to about a voxel edge e off
// the surface, e / |n_z| in depth. So the depths of neighbours on one surface differ by up to
// (|n_x| (columns + 1) + |n_y| (rows + 1) + (1 - |n_z|) e) / |n_z| pixels beyond the jump (which
// allows for e where the surface faces the viewer): the slack. Without it, a steep surface
// drawn with splats is hatched with silhouettes wherever the steps between its rows of splats
// exceed the jump (docs/styles.md). The slack is capped (kMaxSurfaceSlope). A pair's slack is the
// smaller of its two pixels': where a steep surface stands in front of another one, their normals
// differ and the outline stays.
class SurfaceSlopes {
 public:
  // For frames of `setup` (its rotation, splat footprint and depth key scale).
  void build(const ModelView& model, const FrameSetup& setup);
  // For a perspective frame that carries normals, drawn with `world_to_camera` and focal length
  // `focal_q16` (pixels, Q.16): slack in its depth codes (perspectiveEdgeRule), for splats of
  // kPerspectiveSplatReach pixels' reach and voxels of a pixel (detail by distance).
  void buildPerspective(const ModelView& model, const Rotation& world_to_camera,
                        std::int64_t focal_q16);
  std::uint32_t slack(std::uint32_t normal_a, std::uint32_t normal_b) const {
    return std::min(slack_[normal_a], slack_[normal_b]);
  }

 private:
  // The slack of each palette normal turned by `rotation`, for reaches and a voxel edge in units
  // of 2^-8 of the frame's (word >> 16).
  void fillSlack(const ModelView& model, const Rotation& rotation, std::uint64_t reach_x,
                 std::uint64_t reach_y, std::uint64_t edge);

  std::array<std::uint32_t, 256> slack_{};  // 0 past the palette
};

// What the line pass needs of a frame: how far apart neighbouring depths may be, in the units of
// (word >> key_shift).
struct EdgeRule {
  std::uint32_t jump = 0;
  int key_shift = 8;
  const CreaseTable* creases = nullptr;   // nullptr: silhouettes only
  const SurfaceSlopes* slopes = nullptr;  // nullptr: no slack beyond the jump
};

// The rule for a frame set up by `setup` whose words carry `payload` (creases and slopes apply to
// kColourNormal frames only; `slopes` built for the same set-up).
EdgeRule edgeRuleFor(const FrameSetup& setup, PixelPayload payload, const CreaseTable* creases,
                     const SurfaceSlopes* slopes);

// A perspective frame's depth (renderer/perspective_depth.h) is camera-space z, and in a frame that
// carries normals a code whose step is 2^-11 to 2^-12 of z: a depth difference of one pixel across
// at the pair's depth (z / f) is at most 2^12 / f codes at any depth. perspectivePixelCodesQ8 is
// that in Q.8 for f = `focal_q16` (pixels, Q.16).
std::uint64_t perspectivePixelCodesQ8(std::int64_t focal_q16);
// The splats of a perspective frame drawn by distance span about a pixel, padded: neighbouring
// pixels show voxels up to this many pixels apart (the orthographic footprint + 1).
inline constexpr std::uint64_t kPerspectiveSplatReach = 2;
// The rule for a perspective frame that carries normals (PixelPayload::kColourNormal), focal
// length `focal_q16`: the jump is kSilhouetteVoxelEdges pixels across at the pair's depth.
EdgeRule perspectiveEdgeRule(std::int64_t focal_q16, const CreaseTable* creases,
                             const SurfaceSlopes* slopes);

// Whether covered pixel (x, y) of `frame` has a neighbour in the frame that is background or lies
// farther than the jump plus the pair's slope slack: a silhouette pixel.
inline bool hasSilhouetteNeighbour(const FrameView& frame, std::int32_t x, std::int32_t y,
                                   const EdgeRule& rule) {
  const std::uint32_t word = frame.pixelAt(x, y);
  const std::uint32_t farthest = (word >> rule.key_shift) + rule.jump;
  const auto outlines = [&](std::int32_t qx, std::int32_t qy) {
    const std::uint32_t q = frame.pixelAt(qx, qy);
    if (q == Framebuffer::kEmpty) return true;
    const std::uint32_t key = q >> rule.key_shift;
    if (key <= farthest) return false;
    return rule.slopes == nullptr ||
           key - farthest >
               rule.slopes->slack(Framebuffer::normalIndexOf(word), Framebuffer::normalIndexOf(q));
  };
  return (x > 0 && outlines(x - 1, y)) || (x + 1 < frame.width() && outlines(x + 1, y)) ||
         (y > 0 && outlines(x, y - 1)) || (y + 1 < frame.height() && outlines(x, y + 1));
}

// The class of pixel (x, y) of `frame`, covered: the definition of the line pass.
// - kSilhouette when hasSilhouetteNeighbour.
// - Else kCrease when a neighbour q that p draws the pair's crease for (q farther than p, or as
//   far and to its right or below) has a normal index more than the crease angle from p's, and q
//   is no silhouette pixel itself. A crease whose other pixel is a silhouette is left to the
//   silhouette: where an outline is also an edge between two faces (a box seen past its edge, the
//   outermost pixel showing the face turned away), the line is drawn once, on the outline, not a
//   second time one pixel inside it.
// Reads the pixels within two rows and columns of (x, y) where the frame has them.
inline Edge classifyPixel(const FrameView& frame, std::int32_t x, std::int32_t y,
                          const EdgeRule& rule) {
  if (hasSilhouetteNeighbour(frame, x, y, rule)) return Edge::kSilhouette;
  if (rule.creases == nullptr) return Edge::kNone;
  const std::uint32_t word = frame.pixelAt(x, y);
  const std::uint32_t depth = word >> rule.key_shift, n = Framebuffer::normalIndexOf(word);
  const auto creaseWith = [&](std::int32_t qx, std::int32_t qy, bool p_draws_ties) {
    const std::uint32_t q = frame.pixelAt(qx, qy), other = q >> rule.key_shift;
    const std::uint32_t m = Framebuffer::normalIndexOf(q);
    return (other > depth || (other == depth && p_draws_ties)) && n != m &&
           rule.creases->crease(n, m) && !hasSilhouetteNeighbour(frame, qx, qy, rule);
  };
  const bool crease = (x > 0 && creaseWith(x - 1, y, false)) ||
                      (x + 1 < frame.width() && creaseWith(x + 1, y, true)) ||
                      (y > 0 && creaseWith(x, y - 1, false)) ||
                      (y + 1 < frame.height() && creaseWith(x, y + 1, true));
  return crease ? Edge::kCrease : Edge::kNone;
}

}  // namespace octopoint

// The loop of the line styles (lines, toon, outlined): every pixel of some rows of a frame, with
// its class from the line pass (octopoint/styles.h), painted into RGB888. Internal to the style
// passes (octopoint/styles.h).
//
// What it costs is what the frame holds: rows and columns outside the frame's drawn rectangle
// (FrameView::drawnRect, where every pixel is background) are filled with the background colour
// without being looked at; inside it, the frame's inner pixels go through a loop without bounds
// tests and without branches on the normals (paintInnerRun), the frame's first and last rows and
// columns through classifyPixel. Every pixel gets exactly the class classifyPixel defines
// (tests/core/edges_fast_path_test.cpp compares them).

namespace octopoint {

inline void storeRgb(std::uint8_t* out, std::uint32_t rgb) {
  out[0] = static_cast<std::uint8_t>(rgb >> 16);
  out[1] = static_cast<std::uint8_t>(rgb >> 8);
  out[2] = static_cast<std::uint8_t>(rgb);
}

// `count` pixels of RGB888 colour `rgb` (0xRRGGBB) from `out` on: four pixels (12 bytes) a step,
// copied from a pattern, so a run of background costs under one store per pixel.
inline void fillRgb(std::uint8_t* out, std::int32_t count, std::uint32_t rgb) {
  std::uint8_t pattern[12];
  for (int i = 0; i < 12; i += 3) storeRgb(pattern + i, rgb);
  std::int32_t i = 0;
  for (; i + 4 <= count; i += 4, out += 12) std::memcpy(out, pattern, 12);
  for (; i < count; ++i, out += 3) storeRgb(out, rgb);
}

namespace styled_rows_detail {

// paint(word, edge, at) where `paint` takes the pixel's index in the frame (y width + x: a blended
// frame's own colour and normal, octopoint/smooth.h), paint(word, edge) where it does not.
template <typename Paint>
inline std::uint32_t paintPixel(Paint& paint, std::uint32_t word, Edge edge, std::size_t at) {
  if constexpr (std::is_invocable_v<Paint&, std::uint32_t, Edge, std::size_t>) {
    return paint(word, edge, at);
  } else {
    return paint(word, edge);
  }
}

// Whether normals n and the one of `neighbour`'s word are a crease pair (0 or 1); 0 for a
// neighbour of the same index (CreaseTable::build) and, without a table, always.
template <bool kCreases>
inline std::uint32_t creaseBit(const CreaseTable* creases, std::uint32_t n,
                               std::uint32_t neighbour) {
  if constexpr (kCreases) {
    return creases->crease(n, Framebuffer::normalIndexOf(neighbour)) ? 1u : 0u;
  } else {
    return 0u;
  }
}

// Pixels [x, x_end) of inner row y of a kColourNormal frame (1 <= x, x_end <= width - 1, rows
// above and below present), painted. What classifyPixel decides,
// with the words compared whole:
// - A neighbour's key (word >> 16) exceeds depth + jump exactly when its word exceeds
//   (depth + jump) << 16 | 0xFFFF. Where depth + jump reaches 0xFFFF no key exceeds it, and the
//   limit is 0xFFFFFEFF, the largest real word (normal indices stop at 254), which only kEmpty
//   exceeds. So one comparison of the largest of the four neighbour words finds both a
//   background neighbour and one farther than the jump; a neighbour farther than the jump but
//   no background (a few percent of the covered pixels, on steep surfaces) goes through
//   classifyPixel, which asks whether the pair's surface slope explains it (SurfaceSlopes).
// - p draws the crease it shares with q when q is farther (left, above: key > depth, i.e. word >
//   word | 0xFFFF) or as far (right, below: word >= word & 0xFFFF0000). Where the left, upper
//   and lower neighbours have p's normal index (most pixels where splats cover several), only
//   the right pair can be a crease (CreaseTable: none with itself); otherwise the look-ups and
//   side tests go without branches. A pair's look-up is symmetric: the one with the right
//   neighbour is kept for the next pixel's left pair. A pixel these find a crease for (under 1%
//   of the covered pixels) goes through classifyPixel, which also asks whether the pair's other
//   pixel is a silhouette.
template <bool kCreases, typename Paint>
void paintInnerRun(const FrameView& frame, std::int32_t y, std::int32_t x, std::int32_t x_end,
                   const EdgeRule& rule, std::uint32_t background, std::uint8_t* out,
                   Paint& paint) {
  const std::ptrdiff_t stride = frame.width();
  const std::uint32_t* const row = frame.pixels().data() + y * stride;
  const CreaseTable* creases = rule.creases;
  const std::uint32_t* const above = row - stride;
  const std::uint32_t* const below = row + stride;
  constexpr std::uint32_t kLargestWord = 0xFFFF'FEFFu, kNormalBits = 0xFF00u;
  // creaseBit of pixel x - 1 with pixel x (read only when both are covered)
  std::uint32_t left_pair =
      creaseBit<kCreases>(creases, Framebuffer::normalIndexOf(row[x - 1]), row[x]);
  for (; x < x_end; ++x) {
    const std::uint32_t word = row[x];
    std::uint8_t* const pixel_out = out + static_cast<std::ptrdiff_t>(x) * 3;
    if (word == Framebuffer::kEmpty) {
      // A run of background; the pixel after it, if covered, is a silhouette: left_pair unread.
      std::int32_t end = x + 1;
      while (end < x_end && row[end] == Framebuffer::kEmpty) ++end;
      fillRgb(pixel_out, end - x, background);
      x = end - 1;
      continue;
    }
    const std::uint32_t l = row[x - 1], r = row[x + 1], a = above[x], b = below[x];
    const std::uint32_t farthest = (word >> 16) + rule.jump;
    const std::uint32_t limit = farthest < 0xFFFFu ? farthest << 16 | 0xFFFFu : kLargestWord;
    const std::uint32_t n = Framebuffer::normalIndexOf(word);
    const std::uint32_t right_pair = creaseBit<kCreases>(creases, n, r);
    const std::uint32_t largest = std::max(std::max(l, r), std::max(a, b));
    Edge edge = Edge::kSilhouette;
    if (largest <= limit) {
      edge = Edge::kNone;
      if (kCreases && (((l ^ word) | (a ^ word) | (b ^ word)) & kNormalBits) != 0) {
        const std::uint32_t farther = word | 0xFFFFu, as_far = word & 0xFFFF'0000u;
        const std::uint32_t crease =
            (left_pair & static_cast<std::uint32_t>(l > farther)) |
            (right_pair & static_cast<std::uint32_t>(r >= as_far)) |
            (creaseBit<kCreases>(creases, n, a) & static_cast<std::uint32_t>(a > farther)) |
            (creaseBit<kCreases>(creases, n, b) & static_cast<std::uint32_t>(b >= as_far));
        if (crease != 0) edge = classifyPixel(frame, x, y, rule);
      } else if (right_pair != 0 && r >= (word & 0xFFFF'0000u)) {
        edge = classifyPixel(frame, x, y, rule);
      }
    } else if (rule.slopes != nullptr && largest != Framebuffer::kEmpty) {
      edge = classifyPixel(frame, x, y, rule);  // farther than the jump: is it the slope's?
    }
    left_pair = right_pair;
    storeRgb(pixel_out, paintPixel(paint, word, edge, static_cast<std::size_t>(y * stride + x)));
  }
}

}  // namespace styled_rows_detail

// Calls paint(word, edge) (or paint(word, edge, at), at = y width + x) for every covered pixel
// of rows [first_row, end_row) of `frame` and
// stores the RGB888 it returns (packed 0xRRGGBB) into `rgb`, row first_row first; background pixels
// (word Framebuffer::kEmpty) get paint(kEmpty, Edge::kNone), asked once. `paint` must be a
// function of its arguments only.
template <typename Paint>
void forEachStyledPixel(const FrameView& frame, std::int32_t first_row, std::int32_t end_row,
                        const EdgeRule& rule, std::span<std::uint8_t> rgb, Paint paint) {
  const std::int32_t width = frame.width();
  const std::uint32_t* pixels = frame.pixels().data();
  const std::uint32_t background =
      styled_rows_detail::paintPixel(paint, Framebuffer::kEmpty, Edge::kNone, 0);
  const PixelRect& drawn = frame.drawnRect();
  const std::int32_t x_begin = std::max<std::int32_t>(drawn.x_begin, 0);
  const std::int32_t x_end = std::min<std::int32_t>(drawn.x_end, width);
  // The whole-word comparisons hold for kColourNormal words only (key in the top 16 bits).
  const bool words_compare = rule.key_shift == 16 && frame.payload() == PixelPayload::kColourNormal;
  for (std::int32_t y = first_row; y < end_row; ++y) {
    std::uint8_t* const out = rgb.data() + static_cast<std::ptrdiff_t>(y - first_row) * width * 3;
    if (y < drawn.y_begin || y >= drawn.y_end || x_begin >= x_end) {
      fillRgb(out, width, background);
      continue;
    }
    fillRgb(out, x_begin, background);
    fillRgb(out + static_cast<std::ptrdiff_t>(x_end) * 3, width - x_end, background);
    const std::uint32_t* row = pixels + static_cast<std::ptrdiff_t>(y) * width;
    const std::uint32_t* above = y > 0 ? row - width : nullptr;
    const std::uint32_t* below = y + 1 < frame.height() ? row + width : nullptr;
    const auto onePixel = [&](std::int32_t x) {
      const std::uint32_t word = row[x];
      storeRgb(out + static_cast<std::ptrdiff_t>(x) * 3,
               word == Framebuffer::kEmpty
                   ? background
                   : styled_rows_detail::paintPixel(
                         paint, word, classifyPixel(frame, x, y, rule),
                         static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                             static_cast<std::size_t>(x)));
    };
    std::int32_t x = x_begin;
    if (above == nullptr || below == nullptr || !words_compare) {
      for (; x < x_end; ++x) onePixel(x);
      continue;
    }
    if (x == 0) onePixel(x++);
    const std::int32_t inner_end = std::min<std::int32_t>(x_end, width - 1);
    if (x < inner_end) {
      if (rule.creases != nullptr) {
        styled_rows_detail::paintInnerRun<true>(frame, y, x, inner_end, rule, background, out,
                                                paint);
      } else {
        styled_rows_detail::paintInnerRun<false>(frame, y, x, inner_end, rule, background, out,
                                                 paint);
      }
      x = inner_end;
    }
    if (x < x_end) onePixel(x);  // the frame's last column
  }
}

}  // namespace octopoint

// The per-style passes that turn rows of a frame into RGB888 (one file each: style_colour.cpp,
// style_shaded.cpp, style_lines.cpp, style_toon.cpp, style_outlined.cpp). FrameStyler
// (octopoint/styles.h) builds their StylePass once per frame and calls one of them; they
// read only the frame and the pass, write only `rgb`, and allocate nothing. Internal: users go
// through FrameStyler.

namespace octopoint {

// A blended frame's own colour and normal per pixel (octopoint/smooth.h, SmoothSplats::pixelBlend),
// which the styles take instead of the palettes' for every covered pixel; null: the palettes'.
struct PixelBlend {
  const std::uint32_t* colour = nullptr;  // pixel `at`'s 0xRRGGBB at colour[at * colour_stride]
  std::size_t colour_stride = 1;
  const DirectionQ14* normal = nullptr;  // pixel `at`'s unit normal in view axes (Q1.14)
};

struct StylePass {
  std::array<std::uint32_t, 256>
      colour{};  // palette index -> 0xRRGGBB (the base colour of lit styles)
  const std::uint16_t* intensity = nullptr;  // normal index -> Q8 intensity (ShadingTable)
  EdgeRule rule;                             // the line pass (octopoint/styles.h)
  std::uint32_t background = 0;              // 0xRRGGBB
  PixelBlend blend;                          // a blended frame's colours and normals, or none
  DirectionQ14 to_light;                     // view axes (intensityInView), for blend.normal
  LightMix mix = kLightMix;

  // Pixel `at`'s base colour and its intensity (Q8): the blend's where it has them.
  std::uint32_t colourAt(std::uint32_t word, std::size_t at) const {
    return blend.colour != nullptr ? blend.colour[at * blend.colour_stride]
                                   : colour[Framebuffer::colourIndexOf(word)];
  }
  std::uint32_t intensityAt(std::uint32_t word, std::size_t at) const {
    return blend.normal != nullptr ? intensityInView(blend.normal[at], to_light, mix)
                                   : intensity[Framebuffer::normalIndexOf(word)];
  }
};

// Rows [first_row, end_row) of `frame` into `rgb` (3 bytes per pixel, first_row first).
void colourRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
                std::int32_t end_row, std::span<std::uint8_t> rgb);
void shadedRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
                std::int32_t end_row, std::span<std::uint8_t> rgb);
void linesRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
               std::int32_t end_row, std::span<std::uint8_t> rgb);
void toonRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
              std::int32_t end_row, std::span<std::uint8_t> rgb);
void outlinedRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
                  std::int32_t end_row, std::span<std::uint8_t> rgb);

// 0xRRGGBB times a Q8 factor (0..256): two multiplies, red and blue side by side in one.
inline std::uint32_t scaledRgb(std::uint32_t rgb, std::uint32_t factor_q8) {
  const std::uint32_t red_blue = ((rgb & 0xFF00FFu) * factor_q8 >> 8) & 0xFF00FFu;
  const std::uint32_t green = ((rgb & 0x00FF00u) * factor_q8 >> 8) & 0x00FF00u;
  return red_blue | green;
}

}  // namespace octopoint

// Turning a decoded frame into RGB in a style (octopoint/styles.h, docs/styles.md): the embedding
// API of relighting and line drawing.
//
//   FrameStyler styler(model);                       // once per model: tables, no frame buffers
//   styler.setOptions({Style::kToon, light});        // refused when the model has no normals
//   per frame:
//     frame.clear(styler.payload());                 // a frame that carries normals when needed
//     renderLevel(variant, level, setup, frame);
//     styler.beginFrame(setup);                      // the light in the model's axes: 255 entries
//     styler.resolve(frame, rgb);                    // width * height * 3 bytes
//
// Integer only; allocates nothing (its tables are members, about 12 KiB). resolveRows styles a
// range of rows for band rendering: it reads two rows above and below the range where the frame
// has them, so bands drawn two rows taller at each inner edge give the whole frame's pixels.

namespace octopoint {

struct StyleOptions {
  Style style = Style::kColour;
  Light light;
  Angle crease_angle = Angle::fromDegrees(kDefaultCreaseDegrees);
  Rgb background{236, 236, 240};  // the lines style draws on white whatever this is
};

enum class StyleError : std::uint8_t {
  kNone,
  kNeedsNormals,         // the style lights or outlines creases, and the model has no normals
  kFrameWithoutNormals,  // resolve: the frame was not cleared with PixelPayload::kColourNormal
  kFrameSizeMismatch,    // resolve: the rows or the RGB buffer do not fit the frame
};
const char* describe(StyleError error);

class FrameStyler {
 public:
  // `model` must outlive the styler. Starts in the colour style.
  explicit FrameStyler(const ModelView& model);

  // Takes the options, or keeps the old ones and says why not.
  [[nodiscard]] StyleError setOptions(const StyleOptions& options);
  const StyleOptions& options() const { return options_; }
  // What frames for this style must carry (Framebuffer::clear).
  PixelPayload payload() const;

  // Per frame, before resolving: the intensities of the normals under the light for this camera,
  // and the depth step that counts as a silhouette (with each normal's slope on screen).
  void beginFrame(const FrameSetup& setup);
  // The same for a perspective frame (drawn by PerspectiveRenderer into a frame cleared with
  // payload()): the model turned by `world_to_camera` (Q1.30), focal length `focal_q16`.
  void beginPerspectiveFrame(const Rotation& world_to_camera, std::int64_t focal_q16);

  [[nodiscard]] StyleError resolve(const FrameView& frame, std::span<std::uint8_t> rgb,
                                   const PixelBlend& blend = {}) const {
    return resolveRows(frame, 0, frame.height(), rgb, blend);
  }
  // Rows [first_row, end_row) of `frame` into `rgb` (3 bytes per pixel, first_row first). A frame
  // blended by smooth splats (octopoint/smooth.h) passes its pixelBlend(): its colours (in the
  // styles that show colours, except a scan without colour lit in grey) and its normals (in the
  // lit styles) replace the palettes'; lines and creases follow the frame's words as ever.
  [[nodiscard]] StyleError resolveRows(const FrameView& frame, std::int32_t first_row,
                                       std::int32_t end_row, std::span<std::uint8_t> rgb,
                                       const PixelBlend& blend = {}) const;

 private:
  void fillColours();
  bool lit() const;       // the style lights the normals (a shading table per frame)
  bool outlines() const;  // the style draws silhouettes and creases (slopes per frame)

  const ModelView& model_;
  StyleOptions options_;
  CreaseTable creases_;
  bool creases_built_ = false;
  ShadingTable shading_;
  SurfaceSlopes slopes_;  // the silhouettes' slack on steep surfaces, per frame
  FrameSetup setup_{};
  std::int64_t perspective_focal_q16_ = 0;  // beginPerspectiveFrame's; 0: an orthographic frame
  StylePass pass_;
};

}  // namespace octopoint
