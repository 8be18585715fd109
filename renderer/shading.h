#pragma once
// Relighting (docs/styles.md): once per frame, one integer intensity per normal palette entry, from
// the light and the camera's rotation; a lit pixel is then its colour times the intensity of its
// normal index, a table look-up when the frame becomes RGB. Botsch et al. (2002) shade quantized
// normals the same way.
//
// The light and the viewer are turned into the model's axes (the transposed camera rotation), and
// each entry's intensity is, in Q8 (256 = full):
//   ambient + diffuse * max(0, n . light) [+ headlight * max(0, n . viewer)]
// Lighting is two-sided: an entry facing away from the viewer (the back of a single-view scan, seen
// from behind) is lit as if it faced the viewer. Integer only: normals and directions are Q1.14,
// their dot products Q2.28.

#include <array>
#include <cstdint>

#include "fixedpoint/rotation.h"
#include "renderer/model.h"
#include "renderer/style.h"

namespace octopoint {

inline constexpr std::int32_t kFullIntensity = 256;  // Q8

// The share of each term at full strength (Q8, ambient + diffuse (+ headlight) = 256).
struct LightMix {
  std::int32_t ambient, diffuse, headlight;
};
inline constexpr LightMix kLightMix{64, 192, 0};
inline constexpr LightMix kHeadlightMix{48, 160, 48};

// A direction in Q1.14 (2^14 = 1.0).
struct DirectionQ14 {
  std::int32_t x = 0, y = 0, z = 0;
};

// The unit vector toward the light in view axes (x right, y down, z away from the viewer).
DirectionQ14 lightInView(const Light& light);

class ShadingTable {
 public:
  // The intensities of `model`'s normal palette for a frame drawn with `model_to_view` (the
  // camera's rotation, fixedpoint/rotation.h). Entries past the palette are 0.
  void build(const ModelView& model, const Rotation& model_to_view, const Light& light);

  std::uint16_t intensity(std::uint8_t normal_index) const { return intensity_[normal_index]; }
  const std::uint16_t* data() const { return intensity_.data(); }

 private:
  std::array<std::uint16_t, 256> intensity_{};
};

}  // namespace octopoint
