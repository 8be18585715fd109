// The `.oct` binary image of a prepared model, in the layout of renderer/model_format.h.
#include <cassert>

#include "codegen/byte_output.h"
#include "codegen/model_writer.h"
#include "renderer/model_format.h"

namespace octopoint::prepare {

std::vector<std::uint8_t> serializeModel(const PreparedModel& model) {
  assert(!model.levels.empty() && model.levels.size() <= format::kMaxLevels);
  assert(!model.palette.empty() && model.palette.size() <= format::kPaletteEntries);
  std::vector<std::uint8_t> out(format::kMagic, format::kMagic + sizeof format::kMagic);
  putU16(out, format::kFormatVersion);
  out.push_back(static_cast<std::uint8_t>(model.levels.size()));
  out.push_back(0);
  putU32(out, model.cube_edge_um);
  putU16(out, static_cast<std::uint32_t>(model.palette.size()));
  putU16(out, 0);
  for (std::size_t i = 0; i < format::kPaletteEntries; ++i) {
    const Rgb8 colour = i < model.palette.size() ? model.palette[i] : Rgb8{};
    out.insert(out.end(), colour.begin(), colour.end());
  }
  assert(out.size() == format::kHeaderBytes);
  for (const PreparedLevel& level : model.levels) {
    out.push_back(static_cast<std::uint8_t>(level.depth));
    out.insert(out.end(), 3, std::uint8_t{0});
    putU32(out, static_cast<std::uint32_t>(level.nodes.size()));
    putU32(out, static_cast<std::uint32_t>(level.leaves.size()));
  }
  for (const PreparedLevel& level : model.levels) {
    out.insert(out.end(), level.nodes.begin(), level.nodes.end());
    out.insert(out.end(), level.leaves.begin(), level.leaves.end());
  }
  return out;
}

}  // namespace octopoint::prepare
