#include "renderer/edges.h"

#include <algorithm>
#include <cstdlib>

#include "fixedpoint/trig.h"

namespace octopoint {

void CreaseTable::build(const ModelView& model, Angle angle) {
  bits_.fill(0);
  // Normals a and b differ by more than the angle when |a . b| < cos(angle), in Q2.28: as lines,
  // not directions, since a normal the preparer could not orient (where the surface turns away
  // from the sensor) may point either way, and lighting is two-sided anyway. An angle over 90
  // degrees is taken as its supplement.
  const std::int32_t limit = std::abs(cosQ30(angle) >> 2);
  for (int a = 0; a < model.normalCount(); ++a) {
    const NormalQ14 n = model.normal(a);
    for (int b = 0; b < model.normalCount(); ++b) {
      const NormalQ14 m = model.normal(b);
      const std::int32_t dot = std::abs(n.x * m.x + n.y * m.y + n.z * m.z);
      if (dot < limit && a != b)
        bits_[static_cast<std::size_t>(a) * 8 + (static_cast<std::size_t>(b) >> 5)] |= 1u
                                                                                       << (b & 31);
    }
  }
}

EdgeRule edgeRuleFor(const FrameSetup& setup, PixelPayload payload, const CreaseTable* creases) {
  // A depth step of kSilhouetteVoxelEdges voxels, or pixels where a voxel is smaller than one: a
  // surface seen obliquely recedes by up to a few voxels per pixel, and where voxels are smaller
  // than pixels, by up to a few pixels per pixel; neither is an outline.
  const std::uint64_t one_pixel = std::uint64_t{1} << setup.fraction_bits;
  const std::uint64_t step = std::max(voxelEdgeOnScreen(setup), one_pixel) * kSilhouetteVoxelEdges;
  const std::uint64_t key_units =
      std::min<std::uint64_t>(step >> setup.depth_shift, Framebuffer::kMaxDepthKey);
  EdgeRule rule;
  rule.creases = creases;
  // The words of a kColourNormal frame keep the key's top 16 bits (Framebuffer::packColourNormal).
  rule.key_shift = payload == PixelPayload::kColourNormal ? 16 : 8;
  rule.jump = static_cast<std::uint32_t>(payload == PixelPayload::kColourNormal ? key_units >> 8
                                                                                : key_units);
  if (payload != PixelPayload::kColourNormal) rule.creases = nullptr;  // no normals to compare
  return rule;
}

}  // namespace octopoint
