#pragma once
// The line pass of the line styles (docs/styles.md): after decoding, each covered pixel is compared
// with its four neighbours, O(pixels), integer only.
// - Silhouette: a neighbour is background, or lies farther by more than `jump`
//   (kSilhouetteVoxelEdges voxel edges, or pixels where a voxel is smaller than a pixel): the
//   object's outline and the outline of whatever stands in front of something else. Only the
//   nearer pixel of such a pair is marked, so the line is one pixel wide.
// - Crease: a neighbour is no silhouette, but the normals of the two pixels differ by more than
//   the crease angle (a table of 255 x 255 bits built once per model and angle, so the test is one
//   look-up, not a dot product). Again only one pixel of the pair is marked: the nearer, or the
//   left (upper) one of a pair at equal depth.
// Neighbours outside the frame are ignored: no line along the frame's edge.
//
// Bands (drawing a frame a few rows at a time): a row's result depends on the rows above and
// below it. `forEachStyledPixel` (renderer/styled_rows.h) styles rows [first_row, end_row) of a
// frame and reads rows first_row - 1 and end_row where the frame has them; a band drawn one row
// taller at each inner edge therefore styles exactly as the whole frame does.

#include <array>
#include <cstdint>
#include <span>

#include "fixedpoint/angle.h"
#include "renderer/camera.h"
#include "renderer/framebuffer.h"
#include "renderer/model.h"

namespace octopoint {

inline constexpr std::uint32_t kSilhouetteVoxelEdges = 4;

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

// What the line pass needs of a frame: how far apart neighbouring depths may be, in the units of
// (word >> key_shift).
struct EdgeRule {
  std::uint32_t jump = 0;
  int key_shift = 8;
  const CreaseTable* creases = nullptr;  // nullptr: silhouettes only
};

// The rule for a frame set up by `setup` whose words carry `payload`.
EdgeRule edgeRuleFor(const FrameSetup& setup, PixelPayload payload, const CreaseTable* creases);

// Neighbour q of a covered pixel whose word is `word` and depth `depth` (word >> key_shift):
// whether q makes p a silhouette (q is background or farther by more than the jump); and, when p
// draws the pair's crease (p nearer, or as near and `p_draws_ties`: q to its right or below),
// whether their normals make one, or'ed into `crease`. Equal normal indices are never a crease: no
// look-up.
inline bool silhouetteOrCrease(std::uint32_t word, std::uint32_t depth, std::uint32_t neighbour,
                               bool p_draws_ties, const EdgeRule& rule, bool& crease) {
  if (neighbour == Framebuffer::kEmpty) return true;
  const std::uint32_t other = neighbour >> rule.key_shift;
  if (other > depth + rule.jump) return true;
  if (crease || depth > other + rule.jump || rule.creases == nullptr) return false;
  if (other > depth || (other == depth && p_draws_ties)) {
    const std::uint32_t n = Framebuffer::normalIndexOf(word),
                        m = Framebuffer::normalIndexOf(neighbour);
    crease = n != m && rule.creases->crease(n, m);
  }
  return false;
}

// The class of pixel (x, y) of `frame`, covered: the definition of the line pass. Reads the
// pixel's four neighbours where the frame has them.
inline Edge classifyPixel(const FrameView& frame, std::int32_t x, std::int32_t y,
                          const EdgeRule& rule) {
  const std::uint32_t word = frame.pixelAt(x, y);
  const std::uint32_t depth = word >> rule.key_shift;
  bool crease = false;
  if ((x > 0 && silhouetteOrCrease(word, depth, frame.pixelAt(x - 1, y), false, rule, crease)) ||
      (x + 1 < frame.width() &&
       silhouetteOrCrease(word, depth, frame.pixelAt(x + 1, y), true, rule, crease)) ||
      (y > 0 && silhouetteOrCrease(word, depth, frame.pixelAt(x, y - 1), false, rule, crease)) ||
      (y + 1 < frame.height() &&
       silhouetteOrCrease(word, depth, frame.pixelAt(x, y + 1), true, rule, crease))) {
    return Edge::kSilhouette;
  }
  return crease ? Edge::kCrease : Edge::kNone;
}

}  // namespace octopoint
