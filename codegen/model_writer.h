#pragma once
// Writing a prepared model out: the `.oct` binary (octopoint/model.h) and the C++ sources an
// app compiles in (NAME.h, NAME.cpp with the palette and descriptor, NAME_depthD.cpp per level).
// The files are put in place all together or not at all by cli::writeFilesAtomically
// (cli/output_file.h).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/output_file.h"
#include "codegen/prepared_model.h"

namespace octopoint::prepare {

using OutputFile = cli::OutputFile;

// How the generated sources spell the bytes (docs/embedding.md has the compile-time figures).
enum class EmitStyle {
  kBytes,    // brace-initialised decimal bytes: {12,0,255,...}
  kStrings,  // string literals of octal escapes and plain characters, in pieces of at most
             // kMaxLiteralPiece characters (MSVC refuses longer pieces before concatenation)
};
inline constexpr std::size_t kMaxLiteralPiece = 16380;

struct EmitOptions {
  // Strings compile about 10x faster in a quarter of the memory (docs/embedding.md).
  EmitStyle style = EmitStyle::kStrings;
  // Everything in NAME.h + NAME.cpp, instead of one NAME_depthD.cpp per level as well: file names
  // that do not depend on the depths, for build rules that must name their outputs in advance.
  bool single_source = false;
  // Threads spelling the bytes (0: every core); the text is the same for any number.
  unsigned threads = 0;
};

std::vector<std::uint8_t> serializeModel(const PreparedModel& model);
std::vector<OutputFile> emitSources(const PreparedModel& model, const EmitOptions& options = {});

// The level sources NAME_depthD.cpp of model `name` that an earlier run left in `directory` and
// `files` does not hold: what a rerun with fewer depths, or with --single-source (whose NAME.cpp
// defines the same arrays: both compiled in would not link), must take out so that the directory
// holds exactly this run's set (cli::writeFilesAtomically's `obsolete`). Only a regular file that
// reads as the preparer's level source of that model and depth counts (its banner, then the
// array NAME_depthD_nodes): never a file of one's own, nor another model's (a model named
// NAME_depthD writes a NAME_depthD.cpp too).
std::vector<std::string> staleLevelSources(const std::filesystem::path& directory,
                                           const std::string& name,
                                           const std::vector<OutputFile>& files);

}  // namespace octopoint::prepare
