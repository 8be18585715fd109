#include "tools/model_info.h"

#include <cstdio>

#include "cli/text.h"
#include "tools/scan_eye.h"

namespace octopoint {
namespace {

std::string line(const char* format, auto... values) {
  char text[256];
  std::snprintf(text, sizeof text, format, values...);
  return text;
}

// How wide a level's splats are drawn, in footprints (stored in sixteenths, Q4: whole ones in what
// the preparer writes), the same words for every kind of model.
std::string reachText(std::int32_t reach) {
  return line("sample reach %d.%02d footprints", reach / 16, reach % 16 * 100 / 16);
}

// The metric size and the placement: the lines every kind of model shares.
std::string cubeLines(std::uint64_t edge_pm, const CubePlacement& placement, int version) {
  std::string out;
  if (edge_pm > 0) {
    out += line("cube edge %.6g m\n", static_cast<double>(edge_pm) * 1e-12);
  } else {
    out += "cube edge not recorded in metres\n";
  }
  const std::optional<ScanCube> cube = scanCube(placement);
  if (!cube) {
    out += line(
        "cube placement not recorded (format version %d has none: prepare the scan again for "
        "--eye)\n",
        version);
    return out;
  }
  // The lowest corner and the edge in scan units, in the frame --crop takes.
  out += "cube " + scanPointText(cube->corner) + " " + cli::realText(cube->edge) + "\n";
  out += cube->y_up ? "scan axes y-up (the model is the scan turned 180 degrees about x)\n"
                    : "scan axes y-down (the model's axes are the scan's)\n";
  return out;
}

std::string viewInfo(const ModelView& model) {
  std::string out = line("format version %d\n", model.formatVersion());
  out += line("palette %d colours%s\n", model.paletteCount(),
              model.colourIsSynthetic() ? " (a depth shade: the scan had no colour)" : "");
  out += model.hasNormals() ? line("normals %d directions\n", model.normalCount())
                            : std::string("normals none\n");
  for (int i = 0; i < model.levelCount(); ++i) {
    const LevelView& level = model.level(i);
    out += line("depth %d: %zu leaves, %zu node bytes, ", level.depth, level.leaves.size(),
                level.nodes.size()) +
           reachText(model.sampleReach(i)) + "\n";
  }
  return out + cubeLines(model.cubeEdgePicometres(), model.cubePlacement(), model.formatVersion());
}

std::string chunkedInfo(const ProgressiveModel& model) {
  const ChunkedHead& head = model.head();
  std::string out = line("format version %d (chunked), %llu bytes, head %llu bytes\n",
                         head.format_version, static_cast<unsigned long long>(head.file_bytes),
                         static_cast<unsigned long long>(head.head_bytes));
  out += line("palette %d colours%s\n", head.palette_count,
              (head.flags & chunked::kFlagSyntheticColour) != 0
                  ? " (a depth shade: the scan had no colour)"
                  : "");
  out += line("depth %d (base): %zu leaves, ", head.levels[0].depth, head.base_leaves.size()) +
         reachText(head.levels[0].sample_reach) + "\n";
  for (int level = 1; level < model.levelCount(); ++level) {
    unsigned long long leaves = 0;
    for (std::uint32_t i = 0; i < model.chunkCount(level); ++i)
      leaves += model.record(level, i).points;
    out += line("depth %d: %llu leaves in %u chunks, ", model.levelDepth(level), leaves,
                model.chunkCount(level)) +
           reachText(head.levels[static_cast<std::size_t>(level)].sample_reach) + "\n";
  }
  return out + cubeLines(head.cube_edge_pm, head.cube, head.format_version);
}

}  // namespace

std::string modelInfo(const LoadedModel& loaded) {
  std::string out = (loaded.file_bytes.empty() ? "model " : "file ") + loaded.label + "\n";
  return out + (loaded.chunked ? chunkedInfo(*loaded.chunked) : viewInfo(*loaded.view));
}

}  // namespace octopoint
