#pragma once
// The per-style passes that turn rows of a frame into RGB888 (one file each: style_colour.cpp,
// style_shaded.cpp, style_lines.cpp, style_toon.cpp, style_outlined.cpp). FrameStyler
// (renderer/frame_styler.h) builds their StylePass once per frame and calls one of them; they
// read only the frame and the pass, write only `rgb`, and allocate nothing. Internal: users go
// through FrameStyler.

#include <array>
#include <cstdint>
#include <span>

#include "renderer/edges.h"
#include "renderer/framebuffer.h"
#include "renderer/styled_rows.h"

namespace octopoint {

struct StylePass {
  std::array<std::uint32_t, 256>
      colour{};  // palette index -> 0xRRGGBB (the base colour of lit styles)
  const std::uint16_t* intensity = nullptr;  // normal index -> Q8 intensity (ShadingTable)
  EdgeRule rule;                             // the line pass (renderer/edges.h)
  std::uint32_t background = 0;              // 0xRRGGBB
};

// Rows [first_row, end_row) of `frame` into `rgb` (3 bytes per pixel, first_row first).
void colourRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
                std::int32_t end_row, std::span<std::uint8_t> rgb);
void shadedRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
                std::int32_t end_row, std::span<std::uint8_t> rgb);
void linesRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
               std::int32_t end_row, std::span<std::uint8_t> rgb);
void toonRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
              std::int32_t end_row, std::span<std::uint8_t> rgb);
void outlinedRows(const StylePass& pass, const FrameView& frame, std::int32_t first_row,
                  std::int32_t end_row, std::span<std::uint8_t> rgb);

// 0xRRGGBB times a Q8 factor (0..256): two multiplies, red and blue side by side in one.
inline std::uint32_t scaledRgb(std::uint32_t rgb, std::uint32_t factor_q8) {
  const std::uint32_t red_blue = ((rgb & 0xFF00FFu) * factor_q8 >> 8) & 0xFF00FFu;
  const std::uint32_t green = ((rgb & 0x00FF00u) * factor_q8 >> 8) & 0x00FF00u;
  return red_blue | green;
}

}  // namespace octopoint
