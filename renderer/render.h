#pragma once
// Drawing a model level into a framebuffer, by named variant (docs/splats.md). All fixed variants
// draw bit-identical frames while a voxel projects to at most one pixel; beyond that fixed_fast and
// fixed_simd draw footprint splats (identical to each other), the paper's variants one pixel per
// leaf.

#include <atomic>
#include <optional>
#include <span>
#include <string_view>

#include "renderer/abort_flag.h"
#include "renderer/camera.h"
#include "renderer/framebuffer.h"
#include "renderer/model.h"

namespace octopoint {

enum class Variant {
  kFixedBaseline,  // Algorithm 1: recursion down to the leaf, the leaf sets the pixel
  kFixedLeafCall,  // Algorithm 2: the leaf parent sets its children's pixels
  kFixedUnrolled,  // Algorithm 2 with the 8-way child loop unrolled
  kFixedSetBits,   // Algorithm 2 visiting only the set bits of each mask
  kFixedClipped,   // set bits + hierarchical clipping: no bounds checks for subtrees on screen
  kFixedFast,      // clipped, state in registers, no call per leaf parent: the fastest portable one
  kFixedDelta,     // fast's walk, leaves from per-child pixel-index deltas: the fastest with few registers (Cortex-M0+)
  kFixedSimd,      // clipped walk, three levels per call, eight children at once in AVX2 lanes, batched min plot
  kFloatBaseline,  // floating point reference of Algorithm 1
  kFloatLeafCall,  // floating point reference of Algorithm 2
  kFloatUnrolled,  // floating point reference of Algorithm 2, unrolled
};

struct VariantInfo {
  Variant variant;
  std::string_view name;  // the name users pass to `octopoint-render --variant`
  std::string_view summary;
};

// The variants this machine runs: fixed_simd only where the CPU has AVX2 (simdDecoderAvailable).
std::span<const VariantInfo> allVariants();
std::optional<Variant> variantFromName(std::string_view name);
// The default variant wherever a frame is drawn: the fastest this CPU runs, fixed_simd where it
// has AVX2, else fixed_fast. Both draw footprint splats (FrameSetup::splat).
Variant defaultVariant();
// Whether a variant draws the set-up's footprint splats; the others set one pixel per leaf.
bool drawsSplats(Variant variant);
// Whether the variant draws frames that carry normals (PixelPayload::kColourNormal, for the lit and
// creased styles of renderer/style.h): all but fixed_delta, which draws colour frames only and
// refuses the others (nothing drawn, false).
bool drawsNormals(Variant variant);

// Draws `level` with the set-up of one frame into `frame` (which it does not clear, so several
// models can share a frame). The frame must have the set-up's width and height (make it with
// Framebuffer(setup)) and the level the set-up's depth; arguments that do not fit together are
// refused in O(1), also in release builds: false, nothing drawn (checkRender in
// renderer/render_check.h says why). When `abort` is given and becomes true while drawing, the
// decoder stops at its next poll and returns false: the frame is then incomplete and must not be
// shown. Returns true for a complete frame.
bool renderLevel(Variant variant, const LevelView& level, const FrameSetup& setup, FrameView& frame,
                 const std::atomic<bool>* abort = nullptr);

// Whether a variant uses integer arithmetic only (the float_* ones are references).
bool isFixedPoint(Variant variant);

// The variants one by one (renderLevel dispatches to them); each refuses what renderLevel refuses.
bool renderFixedBaseline(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);
bool renderFixedLeafCall(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);
bool renderFixedUnrolled(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);
bool renderFixedSetBits(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);
bool renderFixedClipped(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);
bool renderFixedFast(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);
bool renderFixedDelta(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);
bool renderFixedSimd(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);
bool simdDecoderAvailable();  // an x86-64 CPU with AVX2
bool renderFloatBaseline(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);
bool renderFloatLeafCall(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);
bool renderFloatUnrolled(const LevelView&, const FrameSetup&, FrameView&, const std::atomic<bool>* abort);

}  // namespace octopoint
