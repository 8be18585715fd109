#include "tests/support/surface_cover.h"

#include <algorithm>
#include <fstream>

#include "octopoint/framebuffer.h"
#include "octopoint/render.h"
#include "octopoint/smooth.h"

namespace octopoint::testing {

std::vector<bool> levelCover(const ModelView& model, const LevelView& level, const Camera& camera,
                             std::int32_t reach, bool smooth, const std::string& ppm_path) {
  FrameSetup setup;
  if (buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup, reach) !=
      CameraError::kNone)
    return {};
  Framebuffer frame(setup);
  frame.clear();
  const PaletteRgb palette = paletteOf(model);
  SmoothSplats blender(setup);
  const bool drawn = smooth
                         ? renderSmooth(Variant::kFixedFast, level, setup, frame, blender, palette)
                         : renderLevel(Variant::kFixedFast, level, setup, frame);
  if (!drawn) return {};
  if (!ppm_path.empty()) {
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera.width * camera.height) * 3);
    const bool resolved = smooth ? blender.resolveToRgb(frame, palette, Rgb{255, 255, 255}, rgb)
                                 : resolveToRgb(frame, model, Rgb{255, 255, 255}, rgb);
    if (!resolved) return {};
    std::ofstream out(ppm_path, std::ios::binary);
    out << "P6\n" << camera.width << ' ' << camera.height << "\n255\n";
    out.write(reinterpret_cast<const char*>(rgb.data()), static_cast<std::streamsize>(rgb.size()));
  }
  std::vector<bool> covered;
  covered.reserve(frame.pixels().size());
  for (const std::uint32_t word : frame.pixels()) covered.push_back(word != Framebuffer::kEmpty);
  return covered;
}

std::vector<bool> referenceSurface(const ModelView& model, int depth, const Camera& camera) {
  const LevelView* level = model.levelOfDepth(depth);
  if (level == nullptr) return {};
  const std::vector<bool> coarse = levelCover(model, *level, camera, kOneSampleReach, false);
  if (coarse.empty()) return {};
  const int border = (std::min(camera.width, camera.height) >> depth) + 1;
  std::vector<bool> inside(coarse.size(), false);
  for (int y = border; y < camera.height - border; ++y) {
    for (int x = border; x < camera.width - border; ++x) {
      bool all = true;
      for (int dy = -border; dy <= border && all; dy += border) {
        for (int dx = -border; dx <= border && all; dx += border) {
          all = coarse[static_cast<std::size_t>((y + dy) * camera.width + x + dx)];
        }
      }
      inside[static_cast<std::size_t>(y * camera.width + x)] = all;
    }
  }
  return inside;
}

int emptyPerMille(const std::vector<bool>& reference, const std::vector<bool>& drawn) {
  if (drawn.size() != reference.size()) return 1000;
  std::size_t surface = 0, empty = 0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    if (!reference[i]) continue;
    ++surface;
    if (!drawn[i]) ++empty;
  }
  return surface == 0 ? 1000 : static_cast<int>(empty * 1000 / surface);
}

}  // namespace octopoint::testing
