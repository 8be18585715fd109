#include "renderer/render.h"

#include <array>

namespace octopoint {
namespace {

constexpr std::array kVariants = {
    VariantInfo{Variant::kFixedBaseline, "fixed_baseline",
                "Algorithm 1: integer recursion down to each leaf"},
};

}  // namespace

std::span<const VariantInfo> allVariants() { return kVariants; }

std::optional<Variant> variantFromName(std::string_view name) {
  for (const VariantInfo& info : kVariants) {
    if (info.name == name) return info.variant;
  }
  return std::nullopt;
}

bool renderLevel(Variant variant, const LevelView& level, const FrameSetup& setup,
                 Framebuffer& frame, const std::atomic<bool>* abort) {
  switch (variant) {
    case Variant::kFixedBaseline: return renderFixedBaseline(level, setup, frame, abort);
  }
  return false;
}

}  // namespace octopoint
