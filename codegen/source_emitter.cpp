// The C++ sources of a prepared model: const arrays that an app compiles in, so drawing the model
// needs no file I/O. Bytes are written as decimal initialiser lists (denser than hex).
#include <sstream>

#include "codegen/model_writer.h"
#include "renderer/model_format.h"

namespace octopoint::prepare {
namespace {

constexpr std::size_t kLineWidth = 100;

void appendByteList(std::ostringstream& out, const std::vector<std::uint8_t>& bytes) {
  std::size_t column = 0;
  out << "    ";
  for (std::uint8_t byte : bytes) {
    const std::string item = std::to_string(byte) + ",";
    if (column + item.size() > kLineWidth) {
      out << "\n    ";
      column = 0;
    }
    out << item;
    column += item.size();
  }
  out << "\n";
}

std::string arrayName(const PreparedModel& model, const PreparedLevel& level, const char* part) {
  return model.name + "_depth" + std::to_string(level.depth) + "_" + part;
}

std::string banner(const PreparedModel& model) {
  return "// Generated from " + model.source_description + "\n// Do not edit: regenerate it.\n";
}

std::string header(const PreparedModel& model) {
  std::ostringstream out;
  out << banner(model) << "#pragma once\n\n#include \"renderer/embedded_model.h\"\n\n"
      << "namespace octopoint::models {\n\n";
  for (const PreparedLevel& level : model.levels) {
    const double bits_per_point = 8.0 * static_cast<double>(level.nodes.size()) /
                                  static_cast<double>(level.leaves.size());
    out << "// depth " << level.depth << ": " << level.leaves.size() << " voxels, "
        << level.nodes.size() << " node bytes (" << static_cast<int>(bits_per_point * 100) / 100.0
        << " bits per point of geometry) + " << level.leaves.size() << " colour bytes\n";
  }
  out << "extern const octopoint::EmbeddedModel " << model.name << ";\n\n"
      << "}  // namespace octopoint::models\n";
  return out.str();
}

std::string descriptorSource(const PreparedModel& model) {
  std::ostringstream out;
  out << banner(model) << "#include \"" << model.name << ".h\"\n\n#include <cstdint>\n\n"
      << "namespace octopoint::models {\n\n";
  for (const PreparedLevel& level : model.levels) {
    out << "extern const std::uint8_t " << arrayName(model, level, "nodes") << "["
        << level.nodes.size() << "];\n"
        << "extern const std::uint8_t " << arrayName(model, level, "leaves") << "["
        << level.leaves.size() << "];\n";
  }
  std::vector<std::uint8_t> palette_bytes(3 * format::kPaletteEntries, 0);
  for (std::size_t i = 0; i < model.palette.size(); ++i) {
    for (std::size_t ch = 0; ch < 3; ++ch) palette_bytes[3 * i + ch] = model.palette[i][ch];
  }
  out << "\nnamespace {\n\nconst std::uint8_t kPalette[" << palette_bytes.size() << "] = {\n";
  appendByteList(out, palette_bytes);
  out << "};\n\nconst octopoint::EmbeddedLevel kLevels[" << model.levels.size() << "] = {\n";
  for (const PreparedLevel& level : model.levels) {
    out << "    {" << level.depth << ", " << arrayName(model, level, "nodes") << ", "
        << level.nodes.size() << ", " << arrayName(model, level, "leaves") << ", "
        << level.leaves.size() << "},\n";
  }
  out << "};\n\n}  // namespace\n\n"
      << "extern const octopoint::EmbeddedModel " << model.name << " = {\n"
      << "    \"" << model.name << "\", " << model.cube_edge_um << ", " << model.palette.size()
      << ", kPalette, " << model.levels.size() << ", kLevels};\n\n"
      << "}  // namespace octopoint::models\n";
  return out.str();
}

std::string levelSource(const PreparedModel& model, const PreparedLevel& level) {
  std::ostringstream out;
  out << banner(model) << "#include <cstdint>\n\nnamespace octopoint::models {\n\n"
      << "extern const std::uint8_t " << arrayName(model, level, "nodes") << "["
      << level.nodes.size() << "] = {\n";
  appendByteList(out, level.nodes);
  out << "};\n\nextern const std::uint8_t " << arrayName(model, level, "leaves") << "["
      << level.leaves.size() << "] = {\n";
  appendByteList(out, level.leaves);
  out << "};\n\n}  // namespace octopoint::models\n";
  return out.str();
}

}  // namespace

std::vector<OutputFile> emitSources(const PreparedModel& model) {
  std::vector<OutputFile> files = {{model.name + ".h", header(model)},
                                   {model.name + ".cpp", descriptorSource(model)}};
  for (const PreparedLevel& level : model.levels) {
    files.push_back({model.name + "_depth" + std::to_string(level.depth) + ".cpp",
                     levelSource(model, level)});
  }
  return files;
}

}  // namespace octopoint::prepare
