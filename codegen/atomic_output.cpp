// All-or-nothing output: temporaries first, renames last, clean-up on any failure.
#include <fstream>
#include <system_error>
#include <unistd.h>

#include "codegen/model_writer.h"
#include "codegen/prepare_error.h"

namespace octopoint::prepare {
namespace fs = std::filesystem;

namespace {

void removeQuietly(const fs::path& path) {
  std::error_code ignored;
  fs::remove(path, ignored);
}

}  // namespace

void writeFilesAtomically(const fs::path& directory, const std::vector<OutputFile>& files) {
  std::error_code error;
  const bool existed = fs::exists(directory, error);
  if (!existed) {
    fs::create_directories(directory, error);
    if (error) {
      throw PrepareError(directory.string() + ": cannot create the output directory (" +
                         error.message() + ")");
    }
  } else if (!fs::is_directory(directory, error)) {
    throw PrepareError(directory.string() + ": the output path exists and is not a directory");
  }

  std::vector<fs::path> temporaries;
  auto abandon = [&](const std::string& message) {
    for (const fs::path& temporary : temporaries) removeQuietly(temporary);
    if (!existed) fs::remove(directory, error);  // only if we made it and it is still empty
    throw PrepareError(message);
  };

  const std::string suffix = ".tmp-" + std::to_string(::getpid());
  for (const OutputFile& file : files) {
    const fs::path temporary = directory / ("." + file.name + suffix);
    temporaries.push_back(temporary);
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) abandon(temporary.parent_path().string() + ": cannot write into the output directory");
    out.write(file.contents.data(), static_cast<std::streamsize>(file.contents.size()));
    out.flush();
    if (!out) abandon((directory / file.name).string() + ": write failed (disk full?)");
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    fs::rename(temporaries[i], directory / files[i].name, error);
    if (error) {
      abandon((directory / files[i].name).string() + ": cannot rename into place (" +
              error.message() + ")");
    }
  }
}

}  // namespace octopoint::prepare
