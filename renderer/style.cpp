#include <array>

#include "octopoint/styles.h"

namespace octopoint {
namespace {

constexpr std::array kStyles = {
    StyleInfo{Style::kColour, "colour", "the scan's colours"},
    StyleInfo{Style::kShaded, "shaded",
              "lit from --light: colour (grey without) x ambient + diffuse"},
    StyleInfo{Style::kLines, "lines", "line drawing: black silhouettes, grey creases on white"},
    StyleInfo{Style::kToon, "toon", "flat shading bands with silhouettes and creases"},
    StyleInfo{Style::kOutlined, "outlined",
              "the colours with silhouettes and creases drawn over them"},
};

}  // namespace

std::span<const StyleInfo> allStyles() { return kStyles; }

std::optional<Style> styleFromName(std::string_view name) {
  for (const StyleInfo& info : kStyles) {
    if (info.name == name) return info.style;
  }
  return std::nullopt;
}

std::string_view styleName(Style style) {
  for (const StyleInfo& info : kStyles) {
    if (info.style == style) return info.name;
  }
  return "?";
}

bool styleNeedsNormals(Style style) { return style != Style::kColour; }

Style nextStyle(Style style) {
  for (std::size_t i = 0; i < kStyles.size(); ++i) {
    if (kStyles[i].style == style) return kStyles[(i + 1) % kStyles.size()].style;
  }
  return Style::kColour;
}

}  // namespace octopoint
