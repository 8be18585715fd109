#pragma once
// Writing a prepared model out: the `.oct` binary (renderer/model_format.h) and the C++ sources an
// app compiles in (NAME.h, NAME.cpp with the palette and descriptor, NAME_depthD.cpp per level).
// Files appear all together or not at all: each is written to a temporary beside its final name
// and renamed only once every one of them has been written.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "codegen/prepared_model.h"

namespace octopoint::prepare {

struct OutputFile {
  std::string name;  // file name inside the output directory
  std::string contents;
};

std::vector<std::uint8_t> serializeModel(const PreparedModel& model);
std::vector<OutputFile> emitSources(const PreparedModel& model);

// Creates `directory` if needed and writes every file; throws PrepareError (and leaves nothing
// behind: no temporaries, no partial set of files) when any step fails.
void writeFilesAtomically(const std::filesystem::path& directory, const std::vector<OutputFile>& files);

}  // namespace octopoint::prepare
