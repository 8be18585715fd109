// Smooth splats with normals (renderer/smooth_normals.h): the palette turned per frame, a blended
// normal renormalised per pixel. Integers only.
#include "renderer/smooth_normals.h"

#include <algorithm>
#include <bit>

#include "octopoint/fixed.h"
#include "renderer/integer_square_root.h"

namespace octopoint {
namespace {

std::uint32_t magnitude(std::int32_t v) {
  return v < 0 ? 0U - static_cast<std::uint32_t>(v) : static_cast<std::uint32_t>(v);
}

}  // namespace

void turnNormalsToViewer(const std::array<NormalQ14, 256>& palette, int count,
                         const Rotation& model_to_view, std::array<BlendNormal, 256>& turned) {
  turned.fill(BlendNormal{});
  constexpr int kShift = 30 + 14 - kBlendNormalBits;  // Q1.30 x Q1.14 = Q2.44 -> Q1.10
  for (int i = 0; i < count; ++i) {
    const NormalQ14& n = palette[static_cast<std::size_t>(i)];
    std::array<std::int32_t, 3> view{};
    for (std::size_t row = 0; row < 3; ++row) {
      const auto& m = model_to_view.m_q30[row];
      const std::int64_t sum = std::int64_t{m[0]} * n.x + std::int64_t{m[1]} * n.y +
                               std::int64_t{m[2]} * n.z;  // |.| < 2^46
      view[row] = static_cast<std::int32_t>((sum + (std::int64_t{1} << (kShift - 1))) >> kShift);
    }
    const std::int32_t sign = view[2] > 0 ? -1 : 1;  // view z grows away from the viewer
    turned[static_cast<std::size_t>(i)] = {static_cast<std::int16_t>(sign * view[0]),
                                           static_cast<std::int16_t>(sign * view[1]),
                                           static_cast<std::int16_t>(sign * view[2])};
  }
}

DirectionQ14 unitDirection(std::int32_t x, std::int32_t y, std::int32_t z) {
  std::uint32_t ax = magnitude(x), ay = magnitude(y), az = magnitude(z);
  const std::uint32_t largest = std::max({ax, ay, az});
  if (largest == 0) return {0, 0, -(1 << 14)};
  // The largest component into [2^14, 2^15): the squared length is then below 3 2^30.
  const int bits = std::bit_width(largest);
  if (bits > 15) {
    ax >>= bits - 15, ay >>= bits - 15, az >>= bits - 15;
  } else {
    ax <<= 15 - bits, ay <<= 15 - bits, az <<= 15 - bits;
  }
  const auto length =
      static_cast<std::uint32_t>(integerSquareRoot(ax * ax + ay * ay + az * az));  // >= 2^14
  // a 2^14 / length, rounded: a 2^14 < 2^29 (divideUnsigned: no libgcc division on a
  // Cortex-M0+, docs/device.md; the same bits).
  const auto unit = [length](std::uint32_t a, std::int32_t sign) {
    const auto q = static_cast<std::int32_t>(
        divideUnsigned((std::uint64_t{a} << 14) + length / 2, length).quotient);
    return sign < 0 ? -q : q;
  };
  return {unit(ax, x), unit(ay, y), unit(az, z)};
}

}  // namespace octopoint
