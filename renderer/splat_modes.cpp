// Splat modes by name and a model's palette as RGB (octopoint/smooth.h).
#include <array>

#include "octopoint/smooth.h"

namespace octopoint {
namespace {

constexpr std::array kModes = {
    SplatModeInfo{SplatMode::kBox, "box", "each magnified voxel a flat rectangle of its colour"},
    SplatModeInfo{SplatMode::kSmooth, "smooth",
                  "magnified voxels blended with their neighbours, round silhouettes"},
};

}  // namespace

std::span<const SplatModeInfo> allSplatModes() { return kModes; }

std::optional<SplatMode> splatModeFromName(std::string_view name) {
  for (const SplatModeInfo& info : kModes) {
    if (info.name == name) return info.mode;
  }
  return std::nullopt;
}

std::string_view splatModeName(SplatMode mode) {
  for (const SplatModeInfo& info : kModes) {
    if (info.mode == mode) return info.name;
  }
  return {};
}

PaletteRgb paletteOf(const ModelView& model) {
  PaletteRgb palette{};
  for (int i = 0; i < model.paletteCount(); ++i)
    palette[static_cast<std::size_t>(i)] = model.paletteColour(i);
  return palette;
}

}  // namespace octopoint
