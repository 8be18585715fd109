#pragma once
// Smooth splats' pass 3 over a run of one row (octopoint/smooth.h, docs/splats.md "Smooth
// splats"): a covered pixel whose summed weight (Q12) is below the cover weight becomes kEmpty,
// the others' red sum becomes their weighted mean colour, packed 0x00RRGGBB, each channel
// floor((sum + floor(weight / 2)) / weight). Integers only.

#include <cstddef>
#include <cstdint>

#include "octopoint/smooth.h"

namespace octopoint {

// Pixels [0, count) of `words` and `sums`. The AVX2 steps (eight pixels at a time, where the
// CPU has it: simdDecoderAvailable) give the same words and colours as the scalar loop.
void normaliseRun(std::uint32_t* words, SmoothSplats::Sums* sums, std::size_t count,
                  std::uint32_t cover_weight, bool avx2);

// One pixel's colour, packed: what normaliseRun gives a covered pixel of weight >= 1.
std::uint32_t blendedColour(const SmoothSplats::Sums& sum);

}  // namespace octopoint
