#include "octopoint/render.h"

#include <array>
#include <vector>

namespace octopoint {
namespace {

constexpr std::array kVariants = {
    VariantInfo{Variant::kFixedBaseline, "fixed_baseline",
                "Algorithm 1: integer recursion down to each leaf"},
    VariantInfo{Variant::kFixedLeafCall, "fixed_leafcall",
                "Algorithm 2: leaf parents set their children's pixels"},
    VariantInfo{Variant::kFixedUnrolled, "fixed_unrolled",
                "Algorithm 2 with the 8-way child loop unrolled"},
    VariantInfo{Variant::kFixedSetBits, "fixed_setbits",
                "Algorithm 2 visiting only the set bits of each mask"},
    VariantInfo{Variant::kFixedClipped, "fixed_clipped",
                "set bits + hierarchical clipping (no bounds checks for subtrees on screen)"},
    VariantInfo{Variant::kFixedFast, "fixed_fast",
                "clipped, state in registers, no call per leaf parent: the fastest portable one"},
    VariantInfo{
        Variant::kFixedDelta, "fixed_delta",
        "fast's walk, each leaf's pixel from per-child index deltas and packed sub-pixel carries: "
        "the fastest on few registers (Cortex-M0+)"},
    VariantInfo{Variant::kFixedSimd, "fixed_simd",
                "clipped walk, three levels per call, eight children at once in AVX2 lanes, "
                "branch-free batched plot (x86-64)"},
    VariantInfo{Variant::kFloatBaseline, "float_baseline",
                "Algorithm 1 in floating point (reference)"},
    VariantInfo{Variant::kFloatLeafCall, "float_leafcall",
                "Algorithm 2 in floating point (reference)"},
    VariantInfo{Variant::kFloatUnrolled, "float_unrolled",
                "Algorithm 2 unrolled, floating point (reference)"},
};

}  // namespace

std::span<const VariantInfo> allVariants() {
  static const std::vector<VariantInfo> available = [] {
    std::vector<VariantInfo> list;
    for (const VariantInfo& info : kVariants) {
      if (info.variant != Variant::kFixedSimd || simdDecoderAvailable()) list.push_back(info);
    }
    return list;
  }();
  return available;
}

std::optional<Variant> variantFromName(std::string_view name) {
  for (const VariantInfo& info : allVariants()) {
    if (info.name == name) return info.variant;
  }
  return std::nullopt;
}

Variant defaultVariant() {
  return simdDecoderAvailable() ? Variant::kFixedSimd : Variant::kFixedFast;
}

bool drawsSplats(Variant variant) {
  return variant == Variant::kFixedFast || variant == Variant::kFixedSimd;
}

bool drawsNormals(Variant variant) { return variant != Variant::kFixedDelta; }

bool renderLevel(Variant variant, const LevelView& level, const FrameSetup& setup, FrameView& frame,
                 const std::atomic<bool>* abort) {
  if (checkRender(level, setup, frame) != RenderError::kNone)
    return false;  // refused, nothing drawn
  switch (variant) {
#ifndef OCTOPOINT_FIXED_FAST_ONLY
    case Variant::kFixedBaseline:
      return renderFixedBaseline(level, setup, frame, abort);
    case Variant::kFixedLeafCall:
      return renderFixedLeafCall(level, setup, frame, abort);
    case Variant::kFixedUnrolled:
      return renderFixedUnrolled(level, setup, frame, abort);
    case Variant::kFixedSetBits:
      return renderFixedSetBits(level, setup, frame, abort);
    case Variant::kFixedClipped:
      return renderFixedClipped(level, setup, frame, abort);
    case Variant::kFixedFast:
      return renderFixedFast(level, setup, frame, abort);
    case Variant::kFixedDelta:
      return renderFixedDelta(level, setup, frame, abort);
    case Variant::kFixedSimd:
      return renderFixedSimd(level, setup, frame, abort);
#else  // the web page (web/CMakeLists.txt) draws fixed_fast only: the other decoders are left out
    case Variant::kFixedFast:
    case Variant::kFixedSimd:  // fixed_fast's frame where there is no AVX2, as in a browser
      return renderFixedFast(level, setup, frame, abort);
    case Variant::kFixedBaseline:
    case Variant::kFixedLeafCall:
    case Variant::kFixedUnrolled:
    case Variant::kFixedSetBits:
    case Variant::kFixedClipped:
    case Variant::kFixedDelta:
      return false;
#endif
#ifndef OCTOPOINT_INTEGER_ONLY
    case Variant::kFloatBaseline:
      return renderFloatBaseline(level, setup, frame, abort);
    case Variant::kFloatLeafCall:
      return renderFloatLeafCall(level, setup, frame, abort);
    case Variant::kFloatUnrolled:
      return renderFloatUnrolled(level, setup, frame, abort);
#else  // bare metal (docs/device.md): the float references are not built
    case Variant::kFloatBaseline:
    case Variant::kFloatLeafCall:
    case Variant::kFloatUnrolled:
      return false;
#endif
  }
  return false;
}

bool isFixedPoint(Variant variant) {
  switch (variant) {
    case Variant::kFloatBaseline:
    case Variant::kFloatLeafCall:
    case Variant::kFloatUnrolled:
      return false;
    default:
      return true;
  }
}

}  // namespace octopoint
