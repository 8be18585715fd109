#include "octopoint/camera.h"

namespace octopoint {
namespace {

struct AxisFootprint {
  std::int32_t pixels;
  std::int32_t offset;
  std::int32_t span;
  std::int32_t extent;
};

// One axis: W = 2 * half; no splat along it when W <= one pixel (see the header).
AxisFootprint axisFootprint(std::int64_t half, int depth, int fraction_bits) {
  const std::int64_t one_pixel = std::int64_t{1} << fraction_bits;
  const std::int64_t extent = 2 * half;
  if (extent <= one_pixel) return {1, 0, 0, static_cast<std::int32_t>(extent)};
  const std::int64_t padded = extent + 2 * (depth + 1);                   // P
  const std::int64_t pixels = (padded + one_pixel - 1) >> fraction_bits;  // ceil(P)
  return {static_cast<std::int32_t>(pixels), static_cast<std::int32_t>(one_pixel / 2 - padded / 2),
          static_cast<std::int32_t>(padded - one_pixel), static_cast<std::int32_t>(extent)};
}

}  // namespace

SplatFootprint splatFootprint(std::int64_t half_x, std::int64_t half_y, int depth,
                              int fraction_bits) {
  const AxisFootprint x = axisFootprint(half_x, depth, fraction_bits);
  const AxisFootprint y = axisFootprint(half_y, depth, fraction_bits);
  SplatFootprint footprint;
  footprint.extent_x = x.extent;
  footprint.extent_y = y.extent;
  if (x.pixels == 1 && y.pixels == 1) return footprint;  // one pixel per leaf: today's decoders
  footprint.columns = x.pixels;
  footprint.rows = y.pixels;
  footprint.offset_x = x.offset;
  footprint.offset_y = y.offset;
  footprint.span_x = x.span;
  footprint.span_y = y.span;
  return footprint;
}

}  // namespace octopoint
