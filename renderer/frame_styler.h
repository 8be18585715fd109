#pragma once
// Turning a decoded frame into RGB in a style (renderer/style.h, docs/styles.md): the embedding
// API of relighting and line drawing.
//
//   FrameStyler styler(model);                       // once per model: tables, no frame buffers
//   styler.setOptions({Style::kToon, light});        // refused when the model has no normals
//   per frame:
//     frame.clear(styler.payload());                 // a frame that carries normals when needed
//     renderLevel(variant, level, setup, frame);
//     styler.beginFrame(setup);                      // the light in the model's axes: 255 entries
//     styler.resolve(frame, rgb);                    // width * height * 3 bytes
//
// Integer only; allocates nothing (its tables are members, about 12 KiB). resolveRows styles a
// range of rows for band rendering: it reads two rows above and below the range where the frame
// has them, so bands drawn two rows taller at each inner edge give the whole frame's pixels.

#include <cstdint>
#include <span>

#include "renderer/camera.h"
#include "renderer/edges.h"
#include "renderer/framebuffer.h"
#include "renderer/model.h"
#include "renderer/shading.h"
#include "renderer/style.h"
#include "renderer/style_passes.h"

namespace octopoint {

struct StyleOptions {
  Style style = Style::kColour;
  Light light;
  Angle crease_angle = Angle::fromDegrees(kDefaultCreaseDegrees);
  Rgb background{236, 236, 240};  // the lines style draws on white whatever this is
};

enum class StyleError : std::uint8_t {
  kNone,
  kNeedsNormals,         // the style lights or outlines creases, and the model has no normals
  kFrameWithoutNormals,  // resolve: the frame was not cleared with PixelPayload::kColourNormal
  kFrameSizeMismatch,    // resolve: the rows or the RGB buffer do not fit the frame
};
const char* describe(StyleError error);

class FrameStyler {
 public:
  // `model` must outlive the styler. Starts in the colour style.
  explicit FrameStyler(const ModelView& model);

  // Takes the options, or keeps the old ones and says why not.
  StyleError setOptions(const StyleOptions& options);
  const StyleOptions& options() const { return options_; }
  // What frames for this style must carry (Framebuffer::clear).
  PixelPayload payload() const;

  // Per frame, before resolving: the intensities of the normals under the light for this camera,
  // and the depth step that counts as a silhouette (with each normal's slope on screen).
  void beginFrame(const FrameSetup& setup);

  StyleError resolve(const FrameView& frame, std::span<std::uint8_t> rgb) const {
    return resolveRows(frame, 0, frame.height(), rgb);
  }
  // Rows [first_row, end_row) of `frame` into `rgb` (3 bytes per pixel, first_row first).
  StyleError resolveRows(const FrameView& frame, std::int32_t first_row, std::int32_t end_row,
                         std::span<std::uint8_t> rgb) const;

 private:
  void fillColours();

  const ModelView& model_;
  StyleOptions options_;
  CreaseTable creases_;
  bool creases_built_ = false;
  ShadingTable shading_;
  SurfaceSlopes slopes_;  // the silhouettes' slack on steep surfaces, per frame
  FrameSetup setup_{};
  StylePass pass_;
};

}  // namespace octopoint
