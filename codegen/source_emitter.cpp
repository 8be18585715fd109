// The C++ sources of a prepared model: const arrays that an app compiles in, so drawing the model
// needs no file I/O. Bytes are written either as decimal initialiser lists or as string literals
// (EmitStyle; docs/embedding.md compares their compile time and memory).
#include <bit>
#include <cstdio>
#include <sstream>
#include <string>
#include <string_view>

#include "codegen/byte_text.h"
#include "codegen/huge_pages.h"
#include "codegen/model_writer.h"
#include "codegen/parallel.h"
#include "octopoint/model.h"

namespace octopoint::prepare {
namespace {

// A byte array's definition: its declaration, its bytes as text, and the closing.
struct ArrayText {
  std::string head;
  ByteText bytes;
  std::string_view tail;

  std::size_t size() const { return head.size() + bytes.size() + tail.size(); }
  void appendTo(std::string& out, unsigned threads) const {
    out += head;
    bytes.appendTo(out, threads);
    out += tail;
  }
};

// A string literal carries a terminating NUL, so its array is one byte longer than the data.
std::size_t storedSize(std::size_t bytes, const EmitOptions& options) {
  return options.style == EmitStyle::kStrings ? bytes + 1 : bytes;
}

ArrayText arrayText(const std::string& name, const std::vector<std::uint8_t>& bytes,
                    const EmitOptions& options) {
  const bool strings = options.style == EmitStyle::kStrings;
  return {"extern const ::std::uint8_t " + name + "[" +
              std::to_string(storedSize(bytes.size(), options)) + "] =" + (strings ? "\n" : " {\n"),
          ByteText(bytes, options.style), strings ? "    ;\n" : "};\n"};
}

// Every identifier the generator adds ends in '_', which no model name may (codegen/model_name.h):
// no model's arrays can clash with another model's name, nor this model's helpers with its own.
std::string arrayName(const PreparedModel& model, const PreparedLevel& level, const char* part) {
  return model.name + "_depth" + std::to_string(level.depth) + "_" + part + "_";
}

// Text from outside (file names, the command line) in a comment: kept as it is when it is plainly
// printable, otherwise %XX per byte. A newline would end the comment and turn the rest into code;
// a backslash at a line's end would splice the next line into the comment; '?' and a few others
// are kept out so that nothing in the comment can mean anything to a compiler.
std::string commentSafe(const std::string& text) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (const char c : text) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       std::string_view(" _-.,:/=+@").find(c) != std::string_view::npos;
    if (plain) {
      out += c;
    } else {
      const auto byte = static_cast<unsigned char>(c);
      out += '%';
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    }
  }
  return out;
}

std::string banner(const PreparedModel& model) {
  return "// Generated from " + commentSafe(model.source_description) +
         "\n// Do not edit: regenerate it.\n";
}

std::string header(const PreparedModel& model) {
  std::ostringstream out;
  out << banner(model) << "#pragma once\n\n#include \"octopoint/model.h\"\n\n"
      << "namespace octopoint::models {\n\n";
  for (const PreparedLevel& level : model.levels) {
    const double bits_per_point =
        8.0 * static_cast<double>(level.nodes.size()) / static_cast<double>(level.leaves.size());
    out << "// depth " << level.depth << ": " << level.leaves.size() << " voxels, "
        << level.nodes.size() << " node bytes (" << static_cast<int>(bits_per_point * 100) / 100.0
        << " bits per point of geometry) + " << level.leaves.size() << " colour bytes";
    if (!level.normals.empty()) out << " + " << level.normals.size() << " normal bytes";
    out << "\n";
  }
  out << "extern const ::octopoint::EmbeddedModel " << model.name << ";\n\n"
      << "}  // namespace octopoint::models\n";
  return out.str();
}

// The level's arrays (nodes, leaves, normals), one blank line apart, written into room reserved
// once for them and `more` characters after them.
void appendLevelArrays(std::string& out, const PreparedModel& model, const PreparedLevel& level,
                       const EmitOptions& options, std::size_t more = 0) {
  std::vector<ArrayText> arrays;
  arrays.push_back(arrayText(arrayName(model, level, "nodes"), level.nodes, options));
  arrays.push_back(arrayText(arrayName(model, level, "leaves"), level.leaves, options));
  if (!level.normals.empty()) {
    arrays.push_back(arrayText(arrayName(model, level, "normals"), level.normals, options));
  }
  std::size_t size = out.size() + more;
  for (const ArrayText& array : arrays) size += array.size() + 1;
  reserveOnHugePages(out, size);
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    if (i > 0) out += "\n";
    arrays[i].appendTo(out, options.threads);
  }
}

// The normal palette: Q1.14 components as signed decimal numbers, three per entry.
void appendNormalPalette(std::ostringstream& out, const PreparedModel& model) {
  out << "\nconst ::std::int16_t normals_[" << 3 * model.normal_palette.size() << "] = {\n    ";
  std::size_t column = 0;
  for (const auto& normal : model.normal_palette) {
    for (std::int16_t component : normal) {
      const std::string item = std::to_string(component) + ",";
      if (column + item.size() > kLineWidth) {
        out << "\n    ";
        column = 0;
      }
      out << item;
      column += item.size();
    }
  }
  out << "\n};\n";
}

// The cube's placement as an initialiser: the binary64 bit patterns (the model format's, exact),
// then the numbers they are in a comment for the reader.
std::string cubePlacementText(const CubePlacement& cube) {
  char text[320];
  const auto number = [](std::uint64_t bits) { return std::bit_cast<double>(bits); };
  std::snprintf(text, sizeof text,
                "    // where the cube lies in the scan: its lowest corner %.17g,%.17g,%.17g\n"
                "    // and its edge %.17g, in the scan's units and axes\n"
                "    {{0x%016llxu, 0x%016llxu, 0x%016llxu}, 0x%016llxu, %u},\n",
                number(cube.corner_bits[0]), number(cube.corner_bits[1]),
                number(cube.corner_bits[2]), number(cube.edge_bits),
                static_cast<unsigned long long>(cube.corner_bits[0]),
                static_cast<unsigned long long>(cube.corner_bits[1]),
                static_cast<unsigned long long>(cube.corner_bits[2]),
                static_cast<unsigned long long>(cube.edge_bits), unsigned{cube.scan_axes});
  return text;
}

std::string descriptorSource(const PreparedModel& model, const EmitOptions& options) {
  std::ostringstream out;
  out << banner(model) << "#include \"" << model.name << ".h\"\n\n#include <cstdint>\n\n"
      << "namespace octopoint::models {\n\n";
  for (const PreparedLevel& level : model.levels) {
    if (options.single_source) {
      std::string arrays;
      appendLevelArrays(arrays, model, level, options);
      out << arrays << "\n";
      continue;
    }
    out << "extern const ::std::uint8_t " << arrayName(model, level, "nodes") << "["
        << storedSize(level.nodes.size(), options) << "];\n"
        << "extern const ::std::uint8_t " << arrayName(model, level, "leaves") << "["
        << storedSize(level.leaves.size(), options) << "];\n";
    if (!level.normals.empty()) {
      out << "extern const ::std::uint8_t " << arrayName(model, level, "normals") << "["
          << storedSize(level.normals.size(), options) << "];\n";
    }
  }
  std::vector<std::uint8_t> palette_bytes(3 * format::kPaletteEntries, 0);
  for (std::size_t i = 0; i < model.palette.size(); ++i) {
    for (std::size_t ch = 0; ch < 3; ++ch) palette_bytes[3 * i + ch] = model.palette[i][ch];
  }
  std::string palette_list;
  ByteText(palette_bytes, EmitStyle::kBytes).appendTo(palette_list, 1);
  out << "\nnamespace {\n\nconst ::std::uint8_t palette_[" << palette_bytes.size() << "] = {\n"
      << palette_list;
  out << "};\n";
  const bool with_normals = !model.normal_palette.empty();
  if (with_normals) appendNormalPalette(out, model);
  out << "\nconst ::octopoint::EmbeddedLevel levels_[" << model.levels.size() << "] = {\n";
  for (const PreparedLevel& level : model.levels) {
    out << "    {" << level.depth << ", " << arrayName(model, level, "nodes") << ", "
        << level.nodes.size() << ", " << arrayName(model, level, "leaves") << ", "
        << level.leaves.size() << ", "
        << (with_normals ? arrayName(model, level, "normals") : std::string("nullptr")) << ", "
        << static_cast<unsigned>(level.sample_reach) << "},\n";
  }
  const unsigned flags = (with_normals ? format::v2::kFlagNormals : 0u) |
                         (model.synthetic_colour ? format::v2::kFlagSyntheticColour : 0u);
  // Field by field as in octopoint/model.h: name, format version, flags, cube edge (pm),
  // palette count and colours, normal count and palette, levels, the cube's placement.
  out << "};\n\n}  // namespace\n\n"
      << "extern const ::octopoint::EmbeddedModel " << model.name << " = {\n"
      << "    \"" << model.name << "\", " << format::kVersion6 << ", " << flags << ", "
      << model.cube_edge_pm << "u, " << model.palette.size() << ", palette_, "
      << model.normal_palette.size() << ", " << (with_normals ? "normals_" : "nullptr") << ", "
      << model.levels.size() << ", levels_,\n"
      << cubePlacementText(model.cube) << "};\n\n"
      << "}  // namespace octopoint::models\n";
  return out.str();
}

std::string levelSource(const PreparedModel& model, const PreparedLevel& level,
                        const EmitOptions& options) {
  constexpr std::string_view kEnd = "\n}  // namespace octopoint::models\n";
  std::string out = banner(model) + "#include <cstdint>\n\nnamespace octopoint::models {\n\n";
  appendLevelArrays(out, model, level, options, kEnd.size());
  out += kEnd;
  return out;
}

}  // namespace

std::vector<OutputFile> emitSources(const PreparedModel& model, const EmitOptions& emit) {
  EmitOptions options = emit;
  options.threads = threadCount(emit.threads);
  std::vector<OutputFile> files = {{model.name + ".h", header(model)},
                                   {model.name + ".cpp", descriptorSource(model, options)}};
  if (options.single_source) return files;
  for (const PreparedLevel& level : model.levels) {
    files.push_back({model.name + "_depth" + std::to_string(level.depth) + ".cpp",
                     levelSource(model, level, options)});
  }
  return files;
}

}  // namespace octopoint::prepare
