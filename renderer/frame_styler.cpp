#include <algorithm>

#include "octopoint/fixed.h"
#include "octopoint/styles.h"

namespace octopoint {
namespace {

// The base colour of a lit pixel whose scan had no colour: a light grey (Q8 shading keeps detail
// at both ends).
constexpr std::uint32_t kSurfaceGrey = 0xD2D2D2;
constexpr std::uint32_t kPaper = 0xFFFFFF;

std::uint32_t packed(Rgb c) { return std::uint32_t{c.r} << 16 | std::uint32_t{c.g} << 8 | c.b; }

}  // namespace

const char* describe(StyleError error) {
  switch (error) {
    case StyleError::kNone:
      return "no error";
    case StyleError::kNeedsNormals:
      return "the model has no normals: prepare it with octopoint-prepare --normals";
    case StyleError::kFrameWithoutNormals:
      return "the frame carries no normals: clear it with PixelPayload::kColourNormal";
    case StyleError::kFrameSizeMismatch:
      return "rows or RGB buffer do not fit the frame";
  }
  return "unknown error";
}

FrameStyler::FrameStyler(const ModelView& model) : model_(model) { fillColours(); }

StyleError FrameStyler::setOptions(const StyleOptions& options) {
  if (styleNeedsNormals(options.style) && !model_.hasNormals()) return StyleError::kNeedsNormals;
  if (model_.hasNormals() &&
      (!creases_built_ || !(options.crease_angle == options_.crease_angle))) {
    creases_.build(model_, options.crease_angle);
    creases_built_ = true;
  }
  options_ = options;
  fillColours();
  return StyleError::kNone;
}

PixelPayload FrameStyler::payload() const {
  return styleNeedsNormals(options_.style) ? PixelPayload::kColourNormal : PixelPayload::kColour;
}

void FrameStyler::fillColours() {
  // Lit styles draw a scan without colour as a grey surface, not in its made-up depth shade.
  const bool grey = model_.colourIsSynthetic() &&
                    (options_.style == Style::kShaded || options_.style == Style::kToon);
  pass_.colour.fill(0);
  for (int i = 0; i < model_.paletteCount(); ++i) {
    pass_.colour[static_cast<std::size_t>(i)] =
        grey ? kSurfaceGrey : packed(model_.paletteColour(i));
  }
  pass_.background = options_.style == Style::kLines ? kPaper : packed(options_.background);
  pass_.intensity = shading_.data();
  pass_.to_light = lightInView(options_.light);
  pass_.mix = options_.light.headlight ? kHeadlightMix : kLightMix;
}

bool FrameStyler::lit() const {
  return model_.hasNormals() &&
         (options_.style == Style::kShaded || options_.style == Style::kToon);
}

bool FrameStyler::outlines() const {
  return model_.hasNormals() &&
         (options_.style == Style::kLines || options_.style == Style::kToon ||
          options_.style == Style::kOutlined);
}

void FrameStyler::beginFrame(const FrameSetup& setup) {
  setup_ = setup;
  perspective_focal_q16_ = 0;
  const Camera& camera = setup.camera;
  if (lit()) {
    shading_.build(model_, rotationFromYawPitchRoll(camera.yaw, camera.pitch, camera.roll),
                   options_.light);
  }
  if (outlines()) slopes_.build(model_, setup);
}

void FrameStyler::beginPerspectiveFrame(const Rotation& world_to_camera, std::int64_t focal_q16) {
  perspective_focal_q16_ = std::max<std::int64_t>(focal_q16, 1);
  if (lit()) shading_.build(model_, world_to_camera, options_.light);
  if (outlines()) slopes_.buildPerspective(model_, world_to_camera, perspective_focal_q16_);
}

StyleError FrameStyler::resolveRows(const FrameView& frame, std::int32_t first_row,
                                    std::int32_t end_row, std::span<std::uint8_t> rgb,
                                    const PixelBlend& blend) const {
  if (first_row < 0 || end_row > frame.height() || first_row > end_row ||
      rgb.size() < static_cast<std::size_t>(end_row - first_row) *
                       static_cast<std::size_t>(frame.width()) * 3) {
    return StyleError::kFrameSizeMismatch;
  }
  StylePass pass = pass_;
  // A scan without colour is lit in one grey (fillColours), blended or not.
  const bool grey = model_.colourIsSynthetic() && lit();
  pass.blend = {grey ? nullptr : blend.colour, blend.colour_stride, lit() ? blend.normal : nullptr};
  if (options_.style == Style::kColour) {
    colourRows(pass, frame, first_row, end_row, rgb);
    return StyleError::kNone;
  }
  if (frame.payload() != PixelPayload::kColourNormal) return StyleError::kFrameWithoutNormals;
  pass.rule = perspective_focal_q16_ != 0
                  ? perspectiveEdgeRule(perspective_focal_q16_, &creases_, &slopes_)
                  : edgeRuleFor(setup_, frame.payload(), &creases_, &slopes_);
  switch (options_.style) {
    case Style::kShaded:
      shadedRows(pass, frame, first_row, end_row, rgb);
      break;
    case Style::kLines:
      linesRows(pass, frame, first_row, end_row, rgb);
      break;
    case Style::kToon:
      toonRows(pass, frame, first_row, end_row, rgb);
      break;
    case Style::kOutlined:
      outlinedRows(pass, frame, first_row, end_row, rgb);
      break;
    case Style::kColour:
      break;
  }
  return StyleError::kNone;
}

}  // namespace octopoint
