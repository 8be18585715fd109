#pragma once
// How fixed_delta plots the leaves of a leaf parent that lies on screen with few registers: a
// Cortex-M0+ (Thumb-1) has eight low registers, and the plain per-leaf computation (x, y and z of
// each child, x >> F and y >> F, y * width + x, the depth key) keeps more values alive than that.
//
// Pixel index from per-child deltas and packed sub-pixel carries. Split the parent's centre and
// each child's offset into whole pixels and a fraction of F bits: c.x = X * 2^F + fx, and
// d.x = Dx * 2^F + gx with Dx = d.x >> F (floor) and 0 <= gx < 2^F. Then the child's column is
// (c.x + d.x) >> F = X + Dx + carry_x, where carry_x = (fx + gx) >> F is 0 or 1; the same for rows.
// So its pixel index is base + delta_k + carry_x + carry_y * width, with base = Y * width + X per
// parent and delta_k = Dy * width + Dx per child k, prepared once per frame. With F <= 15 both
// fractions fit one register: fx in bits 32 - F .. 31, fy in bits 16 - F .. 15. One addition of the
// child's packed fractions then gives carry_x as the carry out of bit 31 and carry_y in bit 16.
//
// Depth key without a shift by a variable: ((z + bias) >> s) << 8 is the top 24 bits of
// (z + bias) << (8 - s) (s <= 8; the sum stays below 2^(24 + s), FrameSetup), and that is linear:
// the parent's (c.z + bias) << (8 - s) plus the child's d.z << (8 - s), mod 2^32.
//
// Exact: the same floors and the same key as every other fixed decoder (tests compare whole frames
// bit for bit). Needs F <= 15 and s <= 8 (deltaLeavesApply); otherwise the decoder plots plainly.

#include <array>
#include <cstdint>

#include "octopoint/camera.h"
#include "renderer/bit_scan.h"

// The leaf loop in Thumb-1 assembly on ARMv6-M (a Cortex-M0+), unless a build says 0 to measure
// or test the C++ loop there.
#ifndef OCTOPOINT_THUMB1_LEAF_LOOP
#if defined(__ARM_ARCH_6M__)
#define OCTOPOINT_THUMB1_LEAF_LOOP 1
#else
#define OCTOPOINT_THUMB1_LEAF_LOOP 0
#endif
#endif

namespace octopoint {

// 16 * the lowest set bit of a child mask: the byte offset of its DeltaStep.
inline constexpr std::array<std::uint8_t, 256> kLowestSetBitTimes16 = [] {
  std::array<std::uint8_t, 256> table{};
  for (std::size_t mask = 1; mask < 256; ++mask)
    table[mask] = static_cast<std::uint8_t>(16 * kLowestSetBit[mask]);
  return table;
}();

// A node's centre in packed form: its fractions, pixel index and depth as described above.
struct PackedCentre {
  std::uint32_t fraction;  // fx << (32 - F) | fy << (16 - F)
  std::int32_t index;      // Y * width + X
  std::uint32_t depth;     // (z + bias) << (8 - s), mod 2^32
};

// Child k of a node of one tree level, prepared for a frame (16 bytes: the table is indexed by
// k * 16).
struct DeltaStep {
  std::uint32_t fraction;  // gx << (32 - F) | gy << (16 - F)
  std::int32_t index;      // Dy * width + Dx
  std::uint32_t depth;     // d.z << (8 - s), mod 2^32
  std::uint32_t padding;
};
static_assert(sizeof(DeltaStep) == 16);

// What fixed_delta prepares per frame and frame buffer: the steps to the children of leaf parents
// (the leaves) and to the children of their parents (the leaf parents), 128 bytes apart.
struct DeltaLeaves {
  std::array<DeltaStep, 8> leaf_step;
  std::array<DeltaStep, 8> parent_step;  // only for depth >= 2
  std::uint32_t* pixel;
  std::int32_t width;
  int fraction_bits;
  int depth_up;  // 8 - depth_shift
  std::uint32_t depth_bias;
};

// Whether a set-up's leaves can be plotted this way.
inline bool deltaLeavesApply(const FrameSetup& setup) {
  return setup.fraction_bits <= 15 && setup.depth_shift <= 8 && setup.depth >= 1;
}

// Prepares the tables for the leaves of `setup` written into `pixel`, a frame `width` pixels wide
// (the steps only where deltaLeavesApply).
inline DeltaLeaves prepareDeltaLeaves(const FrameSetup& setup, std::uint32_t* pixel,
                                      std::int32_t width) {
  DeltaLeaves leaves{};
  const int f = setup.fraction_bits;
  leaves.pixel = pixel;
  leaves.width = width;
  leaves.fraction_bits = f;
  leaves.depth_bias = setup.depth_bias;
  if (!deltaLeavesApply(setup)) return leaves;  // only the plain plot reads these
  leaves.depth_up = 8 - setup.depth_shift;
  const std::uint32_t fraction_mask = (std::uint32_t{1} << f) - 1;
  const auto prepare = [&](const std::array<Vec3, 8>& offsets, std::array<DeltaStep, 8>& steps) {
    for (std::size_t k = 0; k < 8; ++k) {
      const Vec3& d = offsets[k];
      steps[k].fraction = (static_cast<std::uint32_t>(d.x) & fraction_mask) << (32 - f) |
                          (static_cast<std::uint32_t>(d.y) & fraction_mask) << (16 - f);
      steps[k].index = (d.y >> f) * width + (d.x >> f);
      steps[k].depth = static_cast<std::uint32_t>(d.z) << leaves.depth_up;
    }
  };
  prepare(setup.child_offset[static_cast<std::size_t>(setup.depth - 1)], leaves.leaf_step);
  if (setup.depth >= 2)
    prepare(setup.child_offset[static_cast<std::size_t>(setup.depth - 2)], leaves.parent_step);
  return leaves;
}

// A centre `c` (Q(32-F).F) in packed form: shifts and a multiply, once per grandparent.
inline PackedCentre packCentre(const DeltaLeaves& leaves, const Vec3& c) {
  const int f = leaves.fraction_bits;
  const auto cx = static_cast<std::uint32_t>(c.x), cy = static_cast<std::uint32_t>(c.y);
  return {cx << (32 - f) | (cy << (32 - f)) >> 16, (c.y >> f) * leaves.width + (c.x >> f),
          (static_cast<std::uint32_t>(c.z) + leaves.depth_bias) << leaves.depth_up};
}

// The packed centre of the child `step` leads to: packCentre of the child's centre, by additions.
// The fractions' sum keeps its field bits; its row carry (bit 16) moves into the index.
inline PackedCentre packedChild(const DeltaLeaves& leaves, const PackedCentre& parent,
                                const DeltaStep& step) {
  PackedCentre child;
  const bool carry_x = __builtin_add_overflow(parent.fraction, step.fraction, &child.fraction);
  child.index = parent.index + step.index + static_cast<std::int32_t>(carry_x);
  if ((child.fraction & 0x1'0000u) != 0) {
    child.index += leaves.width;
    child.fraction -= 0x1'0000u;
  }
  child.depth = parent.depth + step.depth;
  return child;
}

// clang-format off
#if OCTOPOINT_THUMB1_LEAF_LOOP
// The leaf loop in Thumb-1 (shared by both routines below): the children of one leaf parent, mask
// in %[mask] (non-zero), packed fractions in %[q], pixel index in %[base], depth in %[depth_high];
// %[step], %[sum] and %[at] are scratch. 25 instructions a leaf where GCC 12 makes 40 of the C++:
// what stays the same for every leaf (table, steps, width, pixels, the parent's depth) lives in
// high registers, which Thumb-1 can add but not load through, and everything a leaf computes in
// low ones. Same arithmetic as plotDeltaLeaves's C++, step for step.
#define OCTOPOINT_DELTA_LEAF_LOOP                                                         \
  "2:\n\t"                                                                                \
  "mov   %[step], %[lowest]\n\t"          /* the child: k = lowest set bit of the mask, */ \
  "ldrb  %[step], [%[step], %[mask]]\n\t" /*   read as k * 16 (a DeltaStep's size) */      \
  "add   %[step], %[steps]\n\t"           /* step = &leaf_step[k] */                       \
  "ldr   %[sum], [%[step], #0]\n\t"                                                        \
  "adds  %[sum], %[sum], %[q]\n\t"        /* fractions: carry_x out of bit 31 into C, */   \
  "ldr   %[at], [%[step], #4]\n\t"                                                         \
  "adcs  %[at], %[base]\n\t"              /*   index = base + delta_k + carry_x */         \
  "lsls  %[sum], %[sum], #15\n\t"         /*   carry_y (bit 16) into N */                  \
  "bpl   3f\n\t"                                                                           \
  "add   %[at], %[width]\n\t"             /*   index += width */                           \
  "3:\n\t"                                                                                \
  "lsls  %[at], %[at], #2\n\t"                                                             \
  "add   %[at], %[pixel]\n\t"             /* at = &pixel[index] */                         \
  "ldr   %[sum], [%[step], #8]\n\t"                                                        \
  "add   %[sum], %[depth_high]\n\t"       /* (parent depth + depth_k) mod 2^32: */         \
  "lsrs  %[sum], %[sum], #8\n\t"          /*   its top 24 bits are the key */              \
  "lsls  %[sum], %[sum], #8\n\t"                                                           \
  "ldrb  %[step], [%[leaf]]\n\t"                                                           \
  "adds  %[leaf], #1\n\t"                                                                  \
  "orrs  %[sum], %[step]\n\t"             /* word = key << 8 | palette index */            \
  "ldr   %[step], [%[at]]\n\t"                                                             \
  "cmp   %[sum], %[step]\n\t"             /* nearer (smaller word) wins */                 \
  "bhs   4f\n\t"                                                                           \
  "str   %[sum], [%[at]]\n\t"                                                              \
  "4:\n\t"                                                                                 \
  "subs  %[step], %[mask], #1\n\t"                                                         \
  "ands  %[mask], %[step]\n\t"            /* next set bit */                               \
  "bne   2b\n\t"
#endif
// clang-format on

// Plots the children of an on-screen leaf parent whose packed centre is `parent`: `mask` its child
// mask (non-zero), `leaf` its first palette index. Returns the next palette index.
[[gnu::always_inline]] inline const std::uint8_t* plotDeltaLeaves(const DeltaLeaves& leaves,
                                                                  unsigned mask,
                                                                  const std::uint8_t* leaf,
                                                                  const PackedCentre& parent) {
#if OCTOPOINT_THUMB1_LEAF_LOOP
  std::uint32_t q = parent.fraction;
  std::int32_t base = parent.index;
  std::uint32_t step_at, sum, at;
  asm volatile(".syntax unified\n\t"  // GCC hands inline assembly to Thumb-1 in divided syntax
               OCTOPOINT_DELTA_LEAF_LOOP
               : [mask] "+l"(mask), [leaf] "+l"(leaf), [step] "=&l"(step_at), [sum] "=&l"(sum),
                 [at] "=&l"(at)
               : [q] "l"(q), [base] "l"(base), [lowest] "h"(kLowestSetBitTimes16.data()),
                 [steps] "h"(leaves.leaf_step.data()), [width] "h"(leaves.width),
                 [pixel] "h"(leaves.pixel), [depth_high] "h"(parent.depth)
               : "cc", "memory");
  return leaf;
#else
  std::uint32_t* const pixel = leaves.pixel;
  do {
    const DeltaStep& step = leaves.leaf_step[lowestChild(mask)];
    std::uint32_t sum;
    const bool carry_x = __builtin_add_overflow(parent.fraction, step.fraction, &sum);
    std::int32_t index = parent.index + step.index + static_cast<std::int32_t>(carry_x);
    if ((sum & 0x1'0000u) != 0) index += leaves.width;
    const std::uint32_t word = ((parent.depth + step.depth) >> 8 << 8) | *leaf++;
    std::uint32_t& at = pixel[index];
    if (word < at) at = word;
    mask &= mask - 1;
  } while (mask != 0);
  return leaf;
#endif
}

// Plots every leaf below an on-screen node whose children are leaf parents: `grandparent` its
// packed centre, `mask` its child mask (non-zero); `node` and `leaf` are the stream cursors at its
// first child's mask and first leaf, advanced past them. The leaf parents' centres come by
// additions too (packedChild), so a leaf parent costs no shift or multiply either.
[[gnu::always_inline]] inline void plotDeltaGrandchildren(const DeltaLeaves& leaves, unsigned mask,
                                                          const std::uint8_t*& node,
                                                          const std::uint8_t*& leaf,
                                                          const PackedCentre& grandparent) {
#if OCTOPOINT_THUMB1_LEAF_LOOP
  // In Thumb-1 around the leaf loop: what the loop over the leaf parents keeps (its mask, the node
  // cursor, the grandparent's packed centre) waits in a 24-byte frame of the assembly's own below
  // the stack pointer while a leaf parent's leaves are plotted. packedChild, step for step.
  std::uint32_t q = grandparent.fraction, z = grandparent.depth, sum, depth_high;
  std::int32_t base = grandparent.index;
  const std::uint8_t* at = node;
  // clang-format off
  asm volatile(
      ".syntax unified\n\t"
      "sub   sp, #24\n\t"
      "str   %[mask], [sp, #0]\n\t"  // the grandparent's remaining children
      "str   %[at], [sp, #4]\n\t"    // node cursor
      "str   %[q], [sp, #8]\n\t"     // the grandparent's packed centre
      "str   %[base], [sp, #12]\n\t"
      "str   %[step], [sp, #16]\n\t"
      "1:\n\t"  // next leaf parent: k = lowest set bit
      "ldr   %[mask], [sp, #0]\n\t"
      "mov   %[step], %[lowest]\n\t"
      "ldrb  %[step], [%[step], %[mask]]\n\t"
      "add   %[step], %[steps]\n\t"
      "adds  %[step], #128\n\t"  // step = &parent_step[k]
      "subs  %[sum], %[mask], #1\n\t"
      "ands  %[mask], %[sum]\n\t"
      "str   %[mask], [sp, #0]\n\t"
      "ldr   %[sum], [%[step], #0]\n\t"
      "ldr   %[q], [sp, #8]\n\t"
      "adds  %[q], %[sum]\n\t"  // the leaf parent's fractions, carry_x into C
      "ldr   %[base], [%[step], #4]\n\t"
      "ldr   %[sum], [sp, #12]\n\t"
      "adcs  %[base], %[sum]\n\t"    // its index: grandparent's + delta_k + carry_x
      "lsls  %[sum], %[q], #15\n\t"  // carry_y (bit 16) into N
      "bpl   5f\n\t"
      "add   %[base], %[width]\n\t"  // index += width, and bit 16 cleared
      "movs  %[sum], #1\n\t"
      "lsls  %[sum], %[sum], #16\n\t"
      "subs  %[q], %[q], %[sum]\n\t"
      "5:\n\t"
      "ldr   %[sum], [%[step], #8]\n\t"
      "ldr   %[step], [sp, #16]\n\t"
      "add   %[sum], %[step]\n\t"
      "mov   %[depth_high], %[sum]\n\t"  // its depth
      "ldr   %[at], [sp, #4]\n\t"
      "ldrb  %[mask], [%[at]]\n\t"  // its child mask
      "adds  %[at], #1\n\t"
      "str   %[at], [sp, #4]\n\t"
      OCTOPOINT_DELTA_LEAF_LOOP
      "ldr   %[mask], [sp, #0]\n\t"
      "cmp   %[mask], #0\n\t"
      "bne   1b\n\t"
      "ldr   %[at], [sp, #4]\n\t"
      "add   sp, #24\n\t"
      : [mask] "+l"(mask), [leaf] "+l"(leaf), [at] "+l"(at), [q] "+l"(q), [base] "+l"(base),
        [step] "+l"(z), [sum] "=&l"(sum), [depth_high] "=&h"(depth_high)
      : [lowest] "h"(kLowestSetBitTimes16.data()), [steps] "h"(leaves.leaf_step.data()),
        [width] "h"(leaves.width), [pixel] "h"(leaves.pixel)
      : "cc", "memory");
  // clang-format on
  node = at;
#else
  do {
    const PackedCentre parent =
        packedChild(leaves, grandparent, leaves.parent_step[lowestChild(mask)]);
    const unsigned below = *node++;
    leaf = plotDeltaLeaves(leaves, below, leaf, parent);
    mask &= mask - 1;
  } while (mask != 0);
#endif
}

}  // namespace octopoint
