#include <algorithm>
#include <cstdlib>

#include "fixedpoint/trig.h"
#include "octopoint/fixed.h"
#include "octopoint/styles.h"

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

void SurfaceSlopes::build(const ModelView& model, const FrameSetup& setup) {
  // The reach along each axis, footprint + 1 pixels, in 24-bit depth key units: a pixel of depth
  // is 2^F units of z and 2^(F - depth_shift) of the key (< 2^32 while buildFrameSetup accepted
  // the splat's reach). A kColourNormal word keeps the key's top 16 bits: >> 8 at the end.
  const auto reach = [&](std::int32_t footprint) {
    return (std::uint64_t{static_cast<std::uint32_t>(footprint) + 1} << setup.fraction_bits) >>
           setup.depth_shift;
  };
  fillSlack(model,
            rotationFromYawPitchRoll(setup.camera.yaw, setup.camera.pitch, setup.camera.roll),
            reach(setup.splat.columns), reach(setup.splat.rows),
            voxelEdgeOnScreen(setup) >> setup.depth_shift);
}

void SurfaceSlopes::buildPerspective(const ModelView& model, const Rotation& world_to_camera,
                                     std::int64_t focal_q16) {
  // A pixel across at depth z is z / f; a depth code step is 2^-11 to 2^-12 of z, so a pixel is at
  // most 2^12 / f codes: kept in 2^-8 codes until the end, as the orthographic keys' >> 8.
  const std::uint64_t pixel = perspectivePixelCodesQ8(focal_q16);
  fillSlack(model, world_to_camera, kPerspectiveSplatReach * pixel, kPerspectiveSplatReach * pixel,
            pixel);
}

void SurfaceSlopes::fillSlack(const ModelView& model, const Rotation& rotation,
                              std::uint64_t reach_x, std::uint64_t reach_y, std::uint64_t edge) {
  slack_.fill(0);
  const std::uint64_t most = kMaxSurfaceSlope * (std::max(reach_x, reach_y) + edge);
  for (int i = 0; i < model.normalCount(); ++i) {
    const NormalQ14 n = model.normal(i);
    std::array<std::uint64_t, 3> view{};  // |R n| per view axis, Q1.14 (<= 2^14 + a few)
    for (std::size_t row = 0; row < 3; ++row) {
      const std::int64_t sum = std::int64_t{rotation.m_q30[row][0]} * n.x +
                               std::int64_t{rotation.m_q30[row][1]} * n.y +
                               std::int64_t{rotation.m_q30[row][2]} * n.z;  // Q2.44, < 2^47
      view[row] = static_cast<std::uint64_t>(sum < 0 ? -sum : sum) >> 30;
    }
    // (|v_x| reach_x + |v_y| reach_y + (1 - |v_z|) edge) / |v_z|, at most `most` (also where
    // v_z is 0). The last term: voxel centres lie up to about a voxel edge off the surface (the
    // voxel's extent along the normal, and the scan's noise), which shifts their depth by that
    // over |v_z|; the jump already allows one voxel edge for it where the surface faces the
    // viewer. Numerator and most * |v_z| stay below 2^15 * 2^35.
    const std::uint64_t rise =
        view[0] * reach_x + view[1] * reach_y +
        ((std::uint64_t{1} << 14) - std::min<std::uint64_t>(view[2], 1 << 14)) * edge;
    const std::uint64_t key_units = rise >= most * view[2] ? most : rise / view[2];
    slack_[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(
        std::min<std::uint64_t>(key_units >> 8, Framebuffer::kMaxDepthKey));
  }
}

EdgeRule edgeRuleFor(const FrameSetup& setup, PixelPayload payload, const CreaseTable* creases,
                     const SurfaceSlopes* slopes) {
  // A depth step of kSilhouetteVoxelEdges voxels, or pixels where a voxel is smaller than one: the
  // voxel centres of a surface lie up to about a voxel off it, and where voxels are smaller than
  // pixels, neighbouring pixels' voxels lie up to a pixel apart. What a surface seen obliquely
  // recedes beyond that is the slopes' slack.
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
  rule.slopes = slopes;
  if (payload != PixelPayload::kColourNormal) {  // no normals to compare
    rule.creases = nullptr;
    rule.slopes = nullptr;
  }
  return rule;
}

std::uint64_t perspectivePixelCodesQ8(std::int64_t focal_q16) {
  // 2^12 / f codes with f in Q.16, in Q.8: 2^36 / f, rounded up.
  const auto focal = static_cast<std::uint64_t>(std::max<std::int64_t>(focal_q16, 1));
  return ((std::uint64_t{1} << 36) + focal - 1) / focal;
}

EdgeRule perspectiveEdgeRule(std::int64_t focal_q16, const CreaseTable* creases,
                             const SurfaceSlopes* slopes) {
  // kSilhouetteVoxelEdges pixels across at the pair's depth: detail by distance draws voxels of
  // at most a pixel, so this is the orthographic rule's "or pixels where a voxel is smaller".
  EdgeRule rule;
  rule.key_shift = 16;
  rule.jump = static_cast<std::uint32_t>(
      std::min<std::uint64_t>((kSilhouetteVoxelEdges * perspectivePixelCodesQ8(focal_q16)) >> 8,
                              Framebuffer::kMaxDepthKey));
  rule.creases = creases;
  rule.slopes = slopes;
  return rule;
}

}  // namespace octopoint
