#pragma once
// How a frame becomes a picture (docs/styles.md): in the scan's colours, lit from a light, or as a
// line drawing. Every style is applied after decoding, when the frame is turned into RGB
// (renderer/frame_styler.h), so the decoders' inner loops do not grow; all are integer only.
//
//   colour    the palette colours, as the scan was captured
//   shaded    colour (grey for a scan without colour) times a per-frame intensity per normal:
//             ambient + diffuse from the light (+ an optional headlight)
//   lines     white background, black silhouettes, grey creases
//   toon      the shaded colours in a few flat bands, with silhouettes and creases
//   outlined  the colour image with silhouettes and creases drawn over it
//
// Every style but colour needs a model with normals (octopoint-prepare --normals) and a frame that
// carries them (Framebuffer::clear(PixelPayload::kColourNormal)).

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "fixedpoint/angle.h"

namespace octopoint {

enum class Style : std::uint8_t { kColour, kShaded, kLines, kToon, kOutlined };

struct StyleInfo {
  Style style;
  std::string_view name;  // what `octopoint-render --style` takes
  std::string_view summary;
};

std::span<const StyleInfo> allStyles();
std::optional<Style> styleFromName(std::string_view name);
std::string_view styleName(Style style);
bool styleNeedsNormals(Style style);
// The next style in allStyles() order, wrapping around (the viewer's style key).
Style nextStyle(Style style);

// A light, fixed relative to the viewer: it comes from `azimuth` to the right of the viewing
// direction (negative: from the left) and `elevation` above it. Azimuth 0, elevation 0 is a light
// at the viewer's eye.
struct Light {
  Angle azimuth = Angle::fromDegrees(-30);
  Angle elevation = Angle::fromDegrees(35);
  bool headlight = false;  // a second, weaker light at the viewer's eye: no face is left black
};

// Where two neighbouring pixels' normals differ by more than this, a line style draws a crease.
inline constexpr int kDefaultCreaseDegrees = 60;

}  // namespace octopoint
