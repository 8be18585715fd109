// The `.oct` binary image of a prepared model, in the layout of octopoint/model.h (version 6).
#include <cassert>

#include "codegen/byte_output.h"
#include "codegen/huge_pages.h"
#include "codegen/model_writer.h"
#include "octopoint/model.h"

namespace octopoint::prepare {

std::vector<std::uint8_t> serializeModel(const PreparedModel& model) {
  assert(!model.levels.empty() && model.levels.size() <= format::kMaxLevels);
  assert(!model.palette.empty() && model.palette.size() <= format::kPaletteEntries);
  assert(model.normal_palette.size() <= format::kMaxNormals);
  const bool with_normals = !model.normal_palette.empty();
  std::size_t size = format::v2::kNormalPaletteOffset + 6 * model.normal_palette.size() +
                     format::kCubePlacementBytes;
  for (const PreparedLevel& level : model.levels) {
    size += 12 + level.nodes.size() + level.leaves.size() + level.normals.size();
  }
  std::vector<std::uint8_t> out(format::kMagic, format::kMagic + sizeof format::kMagic);
  out.reserve(size);  // megabytes for a large model: no copy as it grows, on huge pages
  adviseHugePages(out.data() + out.size(), size - out.size());
  putU16(out, format::kVersion6);
  out.push_back(static_cast<std::uint8_t>(model.levels.size()));
  out.push_back(
      static_cast<std::uint8_t>((with_normals ? format::v2::kFlagNormals : 0) |
                                (model.synthetic_colour ? format::v2::kFlagSyntheticColour : 0)));
  putU64(out, model.cube_edge_pm);
  putU16(out, static_cast<std::uint32_t>(model.palette.size()));
  putU16(out, static_cast<std::uint32_t>(model.normal_palette.size()));
  for (std::size_t i = 0; i < format::kPaletteEntries; ++i) {
    const Rgb8 colour = i < model.palette.size() ? model.palette[i] : Rgb8{};
    out.insert(out.end(), colour.begin(), colour.end());
  }
  assert(out.size() == format::v2::kNormalPaletteOffset);
  for (const auto& normal : model.normal_palette) {
    for (std::int16_t component : normal) putU16(out, static_cast<std::uint16_t>(component));
  }
  putCubePlacement(out, model.cube);
  for (const PreparedLevel& level : model.levels) {
    assert(level.normals.size() == (with_normals ? level.leaves.size() : 0));
    assert(level.sample_reach >= format::kOneSampleReachQ4 &&
           level.sample_reach <= format::kMaxSampleReachQ4);
    out.push_back(static_cast<std::uint8_t>(level.depth));
    out.push_back(level.sample_reach);
    out.insert(out.end(), 2, std::uint8_t{0});
    putU32(out, static_cast<std::uint32_t>(level.nodes.size()));
    putU32(out, static_cast<std::uint32_t>(level.leaves.size()));
  }
  for (const PreparedLevel& level : model.levels) {
    out.insert(out.end(), level.nodes.begin(), level.nodes.end());
    out.insert(out.end(), level.leaves.begin(), level.leaves.end());
    out.insert(out.end(), level.normals.begin(), level.normals.end());
  }
  assert(out.size() == size);
  return out;
}

}  // namespace octopoint::prepare
