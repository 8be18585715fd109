#pragma once
// Where a decoder reads what each leaf writes besides its depth: the palette index alone, or the
// palette and normal indices of a model with normals (for a frame of PixelPayload::kColourNormal).
// Decoders are templates over the cursor, so drawing colour alone costs what it always did, and
// drawing normals too costs one more byte per leaf. Internal to the decoders.

#include <cstddef>
#include <cstdint>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"

namespace octopoint {

struct ColourLeaves {
  static constexpr PixelPayload kPayload = PixelPayload::kColour;
  const std::uint8_t* colour;

  std::uint32_t next() { return *colour++; }
  void skip(std::size_t count) { colour += count; }
};

struct ColourNormalLeaves {
  static constexpr PixelPayload kPayload = PixelPayload::kColourNormal;
  const std::uint8_t* colour;
  const std::uint8_t* normal;

  // Palette index | normal index << 8: the low 16 bits of the pixel word (Framebuffer::packLeaf).
  std::uint32_t next() { return std::uint32_t{*colour++} | std::uint32_t{*normal++} << 8; }
  void skip(std::size_t count) {
    colour += count;
    normal += count;
  }
};

// Calls `draw(cursor)` with the cursor `frame`'s payload asks for and returns what it returns; or
// returns false, drawing nothing, when the frame wants normals that `level` does not have.
template <typename Draw>
bool withLeafCursor(const LevelView& level, const FrameView& frame, Draw draw) {
  if (frame.payload() == PixelPayload::kColour) return draw(ColourLeaves{level.leaves.data()});
  if (level.normals.size() != level.leaves.size()) return false;
  return draw(ColourNormalLeaves{level.leaves.data(), level.normals.data()});
}

}  // namespace octopoint
