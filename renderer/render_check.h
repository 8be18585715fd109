#pragma once
// What every drawing entry point checks before it touches a framebuffer, in release builds too:
// the decoders trust their arguments (no bounds check for a subtree the set-up says is on screen),
// so a framebuffer of another size, a level of another depth or a set-up buildFrameSetup would not
// have made must be refused, not drawn. All checks are O(1): at most format::kMaxDepth x 8 offsets.
//
// What cannot be checked in O(1) is a LevelView's stream itself: take levels from a ModelView
// (ModelView::fromBytes / fromEmbedded validate them), never build one by hand from untrusted bytes.

#include <cstdint>

#include "renderer/camera.h"
#include "renderer/framebuffer.h"
#include "renderer/model.h"

namespace octopoint {

enum class RenderError : std::uint8_t {
  kNone,
  kBadSetup,           // not a set-up buildFrameSetup makes: depth, fraction bits or size out of range,
                       // or offsets and splat that could overflow 32 bits
  kFrameSizeMismatch,  // the framebuffer's width or height differs from the set-up's
  kDepthMismatch,      // the level's depth differs from the set-up's
  kImplausibleLevel,   // no nodes or leaves, or node bytes and leaf count no tree of its depth has
  kLevelWithoutNormals,  // the frame was cleared to carry normals (PixelPayload::kColourNormal) and
                         // the level has none
};

// A short, stable English description, for one-line messages.
const char* describe(RenderError error);

// Whether `setup` is safe to draw: sizes, depth and fraction bits in range, and no position a
// decoder computes (root plus one offset per level, plus the splat's pixel range) can wrap 32
// bits, as buildFrameSetup proves for what it makes. Band set-ups (a smaller height, a shifted
// root, a subtree's depth) and a splat reset to SplatFootprint{} pass.
RenderError checkFrameSetup(const FrameSetup& setup);

// checkFrameSetup, then whether `level` and `frame` fit it. renderLevel and every variant's
// function return false without drawing when this is not kNone.
RenderError checkRender(const LevelView& level, const FrameSetup& setup, const FrameView& frame);

}  // namespace octopoint
