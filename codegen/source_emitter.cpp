// The C++ sources of a prepared model: const arrays that an app compiles in, so drawing the model
// needs no file I/O. Bytes are written either as decimal initialiser lists or as string literals
// (EmitStyle; docs/embedding.md compares their compile time and memory).
#include <cstdio>
#include <sstream>
#include <string_view>
#include <string>

#include "codegen/model_writer.h"
#include "renderer/model_format.h"

namespace octopoint::prepare {
namespace {

constexpr std::size_t kLineWidth = 100;

// The arrays are written into strings reserved up front, not through a stream: a model of tens of
// megabytes would otherwise spend seconds growing and copying the stream's buffer.
void appendByteList(std::string& text, const std::vector<std::uint8_t>& bytes) {
  text.reserve(text.size() + bytes.size() * 4 + bytes.size() / kLineWidth * 6 + 8);
  text += "    ";
  std::size_t column = 0;
  for (std::uint8_t byte : bytes) {
    char item[5];
    const int size = std::snprintf(item, sizeof item, "%u,", static_cast<unsigned>(byte));
    if (column + static_cast<std::size_t>(size) > kLineWidth) {
      text += "\n    ";
      column = 0;
    }
    text.append(item, static_cast<std::size_t>(size));
    column += static_cast<std::size_t>(size);
  }
  text += "\n";
}

// One literal piece per line, each far below kMaxLiteralPiece. Printable characters stand for
// themselves; the rest are three-digit octal escapes (a fixed length, so a following digit is never
// read as part of the escape). '?' is escaped too, so no trigraph can form for older compilers.
void appendStringPieces(std::string& text, const std::vector<std::uint8_t>& bytes) {
  static_assert(kLineWidth < kMaxLiteralPiece);
  // Written through a pointer into room made beforehand: at most 4 characters per byte, and a
  // 7-character line break every kLineWidth - 4 or more characters.
  const std::size_t start = text.size();
  const std::size_t most = bytes.size() * 4;
  text.resize(start + most + (most / (kLineWidth - 4) + 2) * 7 + 8);
  char* out = text.data() + start;
  const auto put = [&out](const char* chars, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) *out++ = chars[i];
  };
  put("    \"", 5);
  std::size_t column = 0;
  for (std::uint8_t byte : bytes) {
    const bool plain = byte >= 0x20 && byte < 0x7f && byte != '"' && byte != '\\' && byte != '?';
    const std::size_t size = plain ? 1 : 4;
    if (column + size > kLineWidth) {
      put("\"\n    \"", 7);
      column = 0;
    }
    if (plain) {
      *out++ = static_cast<char>(byte);
    } else {
      const char escape[4] = {'\\', static_cast<char>('0' + (byte >> 6)),
                              static_cast<char>('0' + ((byte >> 3) & 7)),
                              static_cast<char>('0' + (byte & 7))};
      put(escape, 4);
    }
    column += size;
  }
  put("\"\n", 2);
  text.resize(static_cast<std::size_t>(out - text.data()));
}

// A string literal carries a terminating NUL, so its array is one byte longer than the data.
std::size_t storedSize(std::size_t bytes, const EmitOptions& options) {
  return options.style == EmitStyle::kStrings ? bytes + 1 : bytes;
}

void appendArray(std::string& out, const std::string& name, const std::vector<std::uint8_t>& bytes,
                 const EmitOptions& options) {
  out += "extern const ::std::uint8_t " + name + "[" +
         std::to_string(storedSize(bytes.size(), options)) + "] =";
  if (options.style == EmitStyle::kStrings) {
    out += "\n";
    appendStringPieces(out, bytes);
    out += "    ;\n";
  } else {
    out += " {\n";
    appendByteList(out, bytes);
    out += "};\n";
  }
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
  return "// Generated from " + commentSafe(model.source_description) + "\n// Do not edit: regenerate it.\n";
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
        << " bits per point of geometry) + " << level.leaves.size() << " colour bytes";
    if (!level.normals.empty()) out << " + " << level.normals.size() << " normal bytes";
    out << "\n";
  }
  out << "extern const ::octopoint::EmbeddedModel " << model.name << ";\n\n"
      << "}  // namespace octopoint::models\n";
  return out.str();
}

void appendLevelArrays(std::string& out, const PreparedModel& model, const PreparedLevel& level,
                       const EmitOptions& options) {
  appendArray(out, arrayName(model, level, "nodes"), level.nodes, options);
  out += "\n";
  appendArray(out, arrayName(model, level, "leaves"), level.leaves, options);
  if (!level.normals.empty()) {
    out += "\n";
    appendArray(out, arrayName(model, level, "normals"), level.normals, options);
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
  appendByteList(palette_list, palette_bytes);
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
        << (with_normals ? arrayName(model, level, "normals") : std::string("nullptr")) << "},\n";
  }
  const unsigned flags = (with_normals ? format::v2::kFlagNormals : 0u) |
                         (model.synthetic_colour ? format::v2::kFlagSyntheticColour : 0u);
  // Field by field as in renderer/embedded_model.h: name, format version, flags, cube edge (pm),
  // palette count and colours, normal count and palette, levels.
  out << "};\n\n}  // namespace\n\n"
      << "extern const ::octopoint::EmbeddedModel " << model.name << " = {\n"
      << "    \"" << model.name << "\", " << format::kVersion2 << ", " << flags << ", "
      << model.cube_edge_pm << "u, " << model.palette.size() << ", palette_, "
      << model.normal_palette.size() << ", " << (with_normals ? "normals_" : "nullptr") << ", "
      << model.levels.size() << ", levels_};\n\n"
      << "}  // namespace octopoint::models\n";
  return out.str();
}

std::string levelSource(const PreparedModel& model, const PreparedLevel& level, const EmitOptions& options) {
  std::string out = banner(model) + "#include <cstdint>\n\nnamespace octopoint::models {\n\n";
  appendLevelArrays(out, model, level, options);
  out += "\n}  // namespace octopoint::models\n";
  return out;
}

}  // namespace

std::vector<OutputFile> emitSources(const PreparedModel& model, const EmitOptions& options) {
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
