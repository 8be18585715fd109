#pragma once
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
// below it. `forEachStyledPixel` (renderer/styled_rows.h) styles rows [first_row, end_row) of a
// frame and reads rows first_row - 2 to end_row + 1 where the frame has them; a band drawn two
// rows taller at each inner edge therefore styles exactly as the whole frame does.

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

#include "fixedpoint/angle.h"
#include "renderer/camera.h"
#include "renderer/framebuffer.h"
#include "renderer/model.h"

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
  std::uint32_t slack(std::uint32_t normal_a, std::uint32_t normal_b) const {
    return std::min(slack_[normal_a], slack_[normal_b]);
  }

 private:
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
