// Smooth splats' pass 3 over a run of one row (renderer/smooth_normalise.h): the weighted mean
// colour of a covered pixel, in integers; scalar (one division a pixel) and AVX2 (no division).

#include "renderer/smooth_normalise.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define OCTOPOINT_NORMALISE_AVX2 1
#endif

#include "octopoint/fixed.h"

namespace octopoint {
namespace {

// Division of any 32-bit n by one divisor d >= 1, one division for several quotients (a pixel's
// three colours): with inverse = floor((2^32 - 1) / d), q = floor(n inverse / 2^32) is floor(n /
// d) or one less (d inverse >= 2^32 - d, so n / d - n inverse / 2^32 <= n / 2^32 < 1, and
// n inverse / 2^32 < n / d), and one compare of the remainder corrects it: exactly n / d.
class Reciprocal {
 public:
  explicit Reciprocal(std::uint32_t divisor)
      : divisor_(divisor),
        // divideUnsigned: no libgcc division on a Cortex-M0+ (docs/device.md), the same bits.
        inverse_(static_cast<std::uint32_t>(divideUnsigned(0xFFFF'FFFFU, divisor).quotient)) {}
  std::uint32_t divide(std::uint32_t n) const {
    auto q = static_cast<std::uint32_t>((std::uint64_t{n} * inverse_) >> 32);
    if (n - q * divisor_ >= divisor_) ++q;
    return q;
  }

 private:
  std::uint32_t divisor_;
  std::uint32_t inverse_;
};

#ifdef OCTOPOINT_NORMALISE_AVX2
// floor(n / w) per lane for n < 256 w (w >= 1, 255 w < 2^32): the largest q in [0, 255] with
// q w <= n, found bit by bit from the top, eight multiplies and compares instead of a division
// (AVX2 has none for integers). A colour sum of weights w_i and colours c_i <= 255 is at most
// 255 w, so n = sum + floor(w / 2) < 256 w wherever the 32-bit sums do not wrap (below 4,096
// full-weight contributions a pixel, docs/splats.md): the scalar division's quotient exactly.
__attribute__((target("avx2"))) inline __m256i quotientBelow256(__m256i n, __m256i w) {
  __m256i q = _mm256_setzero_si256();
  for (int bit = 128; bit != 0; bit >>= 1) {
    const __m256i candidate = _mm256_or_si256(q, _mm256_set1_epi32(bit));
    const __m256i product = _mm256_mullo_epi32(candidate, w);
    // product <= n, unsigned: max(product, n) == n.
    const __m256i fits = _mm256_cmpeq_epi32(_mm256_max_epu32(product, n), n);
    q = _mm256_blendv_epi8(q, candidate, fits);
  }
  return q;
}

// Eight pixels from `at`, every one inside the run. A pixel's four sums are one 16-byte lane
// pair; four 32-byte loads transposed give the r, g, b and w of pixels 0 2 4 6 1 3 5 7.
__attribute__((target("avx2"))) std::size_t normaliseAvx2(std::uint32_t* words,
                                                          SmoothSplats::Sums* sums,
                                                          std::size_t count,
                                                          std::uint32_t cover_weight) {
  const __m256i empty = _mm256_set1_epi32(-1);
  const __m256i to_lanes = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);   // pixel order -> lanes
  const __m256i to_pixels = _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7);  // and back
  // Below cover_weight, unsigned: max(w, cover - 1) == cover - 1.
  const __m256i below = _mm256_set1_epi32(static_cast<int>(cover_weight - 1));
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    auto* const word_at = reinterpret_cast<__m256i*>(words + i);
    const __m256i word = _mm256_loadu_si256(word_at);
    if (_mm256_movemask_epi8(_mm256_cmpeq_epi32(word, empty)) == -1) continue;
    auto* const sum_at = reinterpret_cast<__m256i*>(sums + i);
    const __m256i s0 = _mm256_loadu_si256(sum_at), s1 = _mm256_loadu_si256(sum_at + 1);
    const __m256i s2 = _mm256_loadu_si256(sum_at + 2), s3 = _mm256_loadu_si256(sum_at + 3);
    const __m256i t0 = _mm256_unpacklo_epi32(s0, s1), t1 = _mm256_unpackhi_epi32(s0, s1);
    const __m256i t2 = _mm256_unpacklo_epi32(s2, s3), t3 = _mm256_unpackhi_epi32(s2, s3);
    const __m256i r = _mm256_unpacklo_epi64(t0, t2), g = _mm256_unpackhi_epi64(t0, t2);
    const __m256i b = _mm256_unpacklo_epi64(t1, t3), w = _mm256_unpackhi_epi64(t1, t3);
    const __m256i light = _mm256_cmpeq_epi32(_mm256_max_epu32(w, below), below);
    // A light pixel (empty word too: its sums are not read) keeps its sums; 1 avoids nothing
    // but keeps the search's products defined.
    const __m256i divisor = _mm256_max_epu32(w, _mm256_set1_epi32(1));
    const __m256i half = _mm256_srli_epi32(divisor, 1);
    const __m256i red = quotientBelow256(_mm256_add_epi32(r, half), divisor);
    const __m256i green = quotientBelow256(_mm256_add_epi32(g, half), divisor);
    const __m256i blue = quotientBelow256(_mm256_add_epi32(b, half), divisor);
    const __m256i packed = _mm256_or_si256(
        _mm256_or_si256(_mm256_slli_epi32(red, 16), _mm256_slli_epi32(green, 8)), blue);
    // Pixels whose word is kEmpty or whose weight is light keep their red sum as it was.
    const __m256i keep = _mm256_or_si256(
        light, _mm256_cmpeq_epi32(_mm256_permutevar8x32_epi32(word, to_lanes), empty));
    const __m256i red_sum = _mm256_blendv_epi8(packed, r, keep);  // lanes 0 2 4 6 1 3 5 7
    // Back into each pixel's r: pixel 2k's at lane 0 and 2k + 1's at lane 4 of s_k.
    const __m256i in_pixels = _mm256_permutevar8x32_epi32(red_sum, to_pixels);  // 0 1 2 .. 7
    const __m256i pairs[4] = {
        _mm256_permutevar8x32_epi32(in_pixels, _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1)),
        _mm256_permutevar8x32_epi32(in_pixels, _mm256_setr_epi32(2, 2, 2, 2, 3, 3, 3, 3)),
        _mm256_permutevar8x32_epi32(in_pixels, _mm256_setr_epi32(4, 4, 4, 4, 5, 5, 5, 5)),
        _mm256_permutevar8x32_epi32(in_pixels, _mm256_setr_epi32(6, 6, 6, 6, 7, 7, 7, 7))};
    _mm256_storeu_si256(sum_at, _mm256_blend_epi32(s0, pairs[0], 0x11));
    _mm256_storeu_si256(sum_at + 1, _mm256_blend_epi32(s1, pairs[1], 0x11));
    _mm256_storeu_si256(sum_at + 2, _mm256_blend_epi32(s2, pairs[2], 0x11));
    _mm256_storeu_si256(sum_at + 3, _mm256_blend_epi32(s3, pairs[3], 0x11));
    // A covered word whose weight is light becomes kEmpty (all ones).
    _mm256_storeu_si256(word_at,
                        _mm256_or_si256(word, _mm256_permutevar8x32_epi32(light, to_pixels)));
  }
  return i;
}
#endif

}  // namespace

std::uint32_t blendedColour(const SmoothSplats::Sums& sum) {
  const std::uint32_t half = sum.weight / 2;  // rounded to nearest
  const Reciprocal weight(sum.weight);
  return weight.divide(sum.r + half) << 16 | weight.divide(sum.g + half) << 8 |
         weight.divide(sum.b + half);
}

void normaliseRun(std::uint32_t* words, SmoothSplats::Sums* sums, std::size_t count,
                  std::uint32_t cover_weight, bool avx2) {
  std::size_t i = 0;
#ifdef OCTOPOINT_NORMALISE_AVX2
  if (avx2) i = normaliseAvx2(words, sums, count, cover_weight);
#else
  (void)avx2;
#endif
  for (; i < count; ++i) {
    if (words[i] == FrameView::kEmpty) continue;
    if (sums[i].weight < cover_weight) {
      words[i] = FrameView::kEmpty;
      continue;
    }
    sums[i].r = blendedColour(sums[i]);
  }
}

}  // namespace octopoint
