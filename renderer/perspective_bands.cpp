#include "renderer/perspective_bands.h"

#include <algorithm>
#include <limits>

#include "renderer/band_turns.h"

namespace octopoint {

namespace {

// The slope y / z (Q.30) of the eye's ray through the frame's row boundary `row` (pixels):
// (row * 2^F - centre_y) / f, f in Q.16. One rounded division; `outward` moves it one unit up
// (-1) or down (+1), so that the rounding only widens the band. None where it does not fit.
std::int64_t rowSlope(const PerspectiveView& view, std::int32_t row, int outward) {
  const int f = view.fraction_bits;
  const std::int64_t offset = (std::int64_t{row} << f) - view.centre_y;  // Q(32-F).F, < 2^38
  const std::optional<std::int64_t> slope = divShiftRound(offset, view.focal_q16, 46 - f);
  if (!slope)
    return outward < 0 ? std::numeric_limits<std::int64_t>::min() / 2
                       : std::numeric_limits<std::int64_t>::max() / 2;
  return *slope + outward;
}

}  // namespace

PerspectiveBand perspectiveBand(const PerspectiveView& view, std::int32_t y0, std::int32_t rows) {
  return {rowSlope(view, y0 - kPerspectiveBandMargin, -1),
          rowSlope(view, y0 + rows + kPerspectiveBandMargin, +1)};
}

BandError renderPerspectiveBands(const PerspectiveBandFrame& frame, std::int32_t band_rows,
                                 const Rgb565Palette& palette, const BandBuffers& buffers,
                                 const BandSink& sink, PerspectiveDrawStats* stats) {
  if (band_rows < 1) return BandError::kBadBandRows;
  if (sink.flush == nullptr) return BandError::kNoSink;
  if (frame.view == nullptr || frame.layers.empty() ||
      (frame.layers.size() > 1 &&
       (frame.detail == nullptr || frame.detail->count != static_cast<int>(frame.layers.size())))) {
    return BandError::kRefused;
  }
  const PerspectiveView& whole = *frame.view;
  const std::int32_t width = whole.camera.width, height = whole.camera.height;
  band_rows = std::min(band_rows, height);
  const std::size_t words = static_cast<std::size_t>(width) * static_cast<std::size_t>(band_rows);
  if (buffers.first.size() < words || (!buffers.second.empty() && buffers.second.size() < words))
    return BandError::kBufferTooSmall;
  const bool cull = !frame.tiles.empty();
  if (cull && (frame.tile_shift < 1 || frame.tile_shift > 6 ||
               frame.tiles.size() < occlusionTileCount(width, band_rows, frame.tile_shift))) {
    return BandError::kRefused;
  }
  // The last band's centre lies lowest: if it fits 32 bits, every band's does.
  if (whole.centre_y - (std::int64_t{height - 1} << whole.fraction_bits) <
      std::numeric_limits<std::int32_t>::min()) {
    return BandError::kRefused;
  }

  int band_number = 0;
  for (std::int32_t y0 = 0; y0 < height; y0 += band_rows, ++band_number) {
    const std::int32_t rows = std::min(band_rows, height - y0);
    const std::span<std::uint32_t> buffer = bandBufferFor(buffers, band_number, sink);
    FrameView band_frame(buffer.data(), width, rows);
    band_frame.clear();
    // The band's rows are the frame's moved up by y0: every position moves by exactly y0 << F.
    PerspectiveView view = whole;
    view.centre_y -= std::int64_t{y0} << whole.fraction_bits;
    view.camera.height = rows;
    const PerspectiveBand band = perspectiveBand(whole, y0, rows);
    std::optional<OcclusionTiles> occlusion;
    if (cull) {
      occlusion.emplace(band_frame, frame.tiles, frame.tile_shift);
      occlusion->reset();
    }
    drawPerspectiveLayers(frame.layers, frame.detail, view, band_frame,
                          occlusion ? &*occlusion : nullptr, stats, &band);
    const std::size_t pixels = static_cast<std::size_t>(rows) * static_cast<std::size_t>(width);
    const std::span<std::uint8_t> rgb565 = bytesOf(buffer).first(pixels * 2);
    packedToRgb565(buffer.data(), pixels, palette, rgb565.data());
    sink.flush(sink.user, y0, rows, rgb565);
  }
  return BandError::kNone;
}

}  // namespace octopoint
