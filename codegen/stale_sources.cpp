// Level sources an earlier run of the preparer left that this run does not write (model_writer.h).
#include <algorithm>
#include <fstream>
#include <system_error>

#include "codegen/model_writer.h"
#include "octopoint/model.h"

namespace octopoint::prepare {
namespace {

// How much of a file is read to recognise it: its banner (the command that made it, percent-
// encoded where needed) and the first array's declaration. A longer banner is not recognised and
// the file is left where it is, as before.
constexpr std::size_t kRecogniseBytes = 256 * 1024;

bool isLevelSourceOf(const std::filesystem::path& path, const std::string& array_name) {
  std::ifstream in(path, std::ios::binary);
  std::string text(kRecogniseBytes, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  // "extern const ::std::uint8_t NAME_depthD_nodes_[" today, "std::uint8_t NAME_depthD_nodes["
  // from the first generator: both hold this.
  return text.rfind("// Generated from ", 0) == 0 &&
         text.find("std::uint8_t " + array_name) != std::string::npos;
}

}  // namespace

std::vector<std::string> staleLevelSources(const std::filesystem::path& directory,
                                           const std::string& name,
                                           const std::vector<OutputFile>& files) {
  std::vector<std::string> stale;
  for (int depth = 1; depth <= format::kMaxDepth; ++depth) {
    const std::string level = name + "_depth" + std::to_string(depth);
    const std::string file_name = level + ".cpp";
    const auto same_name = [&](const OutputFile& file) { return file.name == file_name; };
    if (std::any_of(files.begin(), files.end(), same_name)) continue;
    std::error_code error;
    const std::filesystem::path path = directory / file_name;
    if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(path, error))) continue;
    if (isLevelSourceOf(path, level + "_nodes")) stale.push_back(file_name);
  }
  return stale;
}

}  // namespace octopoint::prepare
