#include <algorithm>

#include "fixedpoint/trig.h"
#include "octopoint/styles.h"

namespace octopoint {
namespace {

// Q1.30 x Q1.30 -> Q1.30, rounded.
std::int32_t mulQ30(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>((std::int64_t{a} * b + (std::int64_t{1} << 29)) >> 30);
}

// R^T v: a view-axes direction (Q1.30) in the model's axes (Q1.14). R is orthonormal to within
// a few units in the last place, so the result is a unit vector to within rounding.
DirectionQ14 toModel(const Rotation& r, const std::array<std::int32_t, 3>& v_q30) {
  std::array<std::int32_t, 3> out{};
  for (std::size_t col = 0; col < 3; ++col) {
    std::int64_t sum = 0;  // Q2.60: three terms below 2^60 each
    for (std::size_t row = 0; row < 3; ++row) sum += std::int64_t{r.m_q30[row][col]} * v_q30[row];
    out[col] = static_cast<std::int32_t>((sum + (std::int64_t{1} << 45)) >> 46);  // Q1.14
  }
  return {out[0], out[1], out[2]};
}

std::int32_t dotQ28(const NormalQ14& n, const DirectionQ14& d) {
  return n.x * d.x + n.y * d.y + n.z * d.z;  // |.| <= 2^28 (1 + a few ulp): fits 32 bits
}

// A Q2.28 cosine (clamped at 0) times a Q8 weight, in Q8.
std::int32_t weighted(std::int32_t cosine_q28, std::int32_t weight_q8) {
  return ((std::max<std::int32_t>(cosine_q28, 0) >> 14) * weight_q8) >>
         14;  // Q1.14 x Q8 = Q9.22 -> Q8
}

// A normal's intensity (Q8) from its cosines (Q2.28) with the viewer and the light: two-sided,
// a normal facing away lit as if it faced the viewer.
std::uint16_t intensityOf(std::int32_t facing, std::int32_t lit, const LightMix& mix) {
  const std::int32_t diffuse = facing >= 0 ? lit : -lit;
  const std::int32_t value = mix.ambient + weighted(diffuse, mix.diffuse) +
                             weighted(facing >= 0 ? facing : -facing, mix.headlight);
  return static_cast<std::uint16_t>(std::min(value, kFullIntensity));
}

}  // namespace

DirectionQ14 lightInView(const Light& light) {
  const std::int32_t cos_elevation = cosQ30(light.elevation);
  const std::array<std::int32_t, 3> toward_light = {mulQ30(sinQ30(light.azimuth), cos_elevation),
                                                    -sinQ30(light.elevation),
                                                    -mulQ30(cosQ30(light.azimuth), cos_elevation)};
  const auto q14 = [](std::int32_t v) { return (v + (1 << 15)) >> 16; };
  return {q14(toward_light[0]), q14(toward_light[1]), q14(toward_light[2])};
}

std::uint16_t intensityInView(const DirectionQ14& normal, const DirectionQ14& to_light,
                              const LightMix& mix) {
  // As ShadingTable::build, whose to_viewer is (0, 0, -1) in view axes: facing = -z (Q2.28).
  const std::int32_t facing = -normal.z * (1 << 14);
  const std::int32_t lit = normal.x * to_light.x + normal.y * to_light.y + normal.z * to_light.z;
  return intensityOf(facing, lit, mix);
}

void ShadingTable::build(const ModelView& model, const Rotation& model_to_view,
                         const Light& light) {
  const DirectionQ14 light_view = lightInView(light);
  const std::array<std::int32_t, 3> light_q30 = {light_view.x << 16, light_view.y << 16,
                                                 light_view.z << 16};
  const DirectionQ14 to_light = toModel(model_to_view, light_q30);
  const DirectionQ14 to_viewer = toModel(model_to_view, {0, 0, -(1 << 30)});
  const LightMix mix = light.headlight ? kHeadlightMix : kLightMix;
  intensity_.fill(0);
  for (int i = 0; i < model.normalCount(); ++i) {
    const NormalQ14 n = model.normal(i);
    intensity_[static_cast<std::size_t>(i)] =
        intensityOf(dotQ28(n, to_viewer), dotQ28(n, to_light), mix);
  }
}

}  // namespace octopoint
