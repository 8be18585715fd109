// All-or-nothing output. Every file is first written into a staging directory inside the output
// directory (same file system, so the final renames are atomic); only when all are written are
// they renamed into place, one by one. A file of an earlier run that a new one replaces is moved
// into the staging directory first, so that if a later rename fails (the directory vanished, a
// name is taken by a directory, ...) every file already put in place is taken out again and the
// earlier run's files are put back: the directory holds the old set or the new set, never a mix.
#include <csignal>
#include <fstream>
#include <system_error>
#include <unistd.h>

#include "codegen/model_writer.h"
#include "codegen/prepare_error.h"

namespace octopoint::prepare {
namespace fs = std::filesystem;

namespace {

// Under a file size limit (RLIMIT_FSIZE, `ulimit -f`) a write past it raises SIGXFSZ, which kills
// the process before it can clean up. Ignored, the write fails with EFBIG instead and we report it
// like a full disk. The previous disposition comes back when the output is done.
class FileSizeSignalIgnored {
 public:
  FileSizeSignalIgnored() : previous_(std::signal(SIGXFSZ, SIG_IGN)) {}
  ~FileSizeSignalIgnored() { std::signal(SIGXFSZ, previous_); }
  FileSizeSignalIgnored(const FileSizeSignalIgnored&) = delete;
  FileSizeSignalIgnored& operator=(const FileSizeSignalIgnored&) = delete;

 private:
  void (*previous_)(int);
};

// One file put in place, and whether an earlier file of that name waits in `displaced`.
struct Published {
  fs::path final_path;
  fs::path displaced;
  bool had_previous = false;
};

void writeFile(const fs::path& path, const std::string& contents, const fs::path& final_path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw PrepareError(final_path.parent_path().string() + ": cannot write into the output directory");
  out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  out.flush();
  if (!out) throw PrepareError(final_path.string() + ": write failed (disk full or file size limit?)");
}

// Renames one staged file into place, moving an earlier regular file of that name aside first.
// A directory of that name is left alone: the rename then fails, as it should.
Published publish(const fs::path& staged, const fs::path& final_path, const fs::path& displaced) {
  std::error_code error;
  Published done{final_path, displaced, false};
  const fs::file_status existing = fs::symlink_status(final_path, error);
  if (fs::is_regular_file(existing) || fs::is_symlink(existing)) {
    fs::rename(final_path, displaced, error);
    if (error) {
      throw PrepareError(final_path.string() + ": cannot replace the earlier file (" + error.message() + ")");
    }
    done.had_previous = true;
  }
  fs::rename(staged, final_path, error);
  if (error) {
    std::error_code ignored;
    if (done.had_previous) fs::rename(displaced, final_path, ignored);
    throw PrepareError(final_path.string() + ": cannot rename into place (" + error.message() + ")");
  }
  return done;
}

// Takes the new files out again and puts the earlier ones back, newest first.
void unpublish(const std::vector<Published>& published) {
  std::error_code ignored;
  for (auto it = published.rbegin(); it != published.rend(); ++it) {
    fs::remove(it->final_path, ignored);
    if (it->had_previous) fs::rename(it->displaced, it->final_path, ignored);
  }
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

  const fs::path staging = directory / (".octopoint-prepare.tmp-" + std::to_string(::getpid()));
  const fs::path displaced = staging / "displaced";
  std::vector<Published> published;
  const FileSizeSignalIgnored file_size_signal_ignored;
  try {
    fs::remove_all(staging, error);
    if (!fs::create_directory(staging, error) || !fs::create_directory(displaced, error)) {
      throw PrepareError(directory.string() + ": cannot write into the output directory (" +
                         error.message() + ")");
    }
    for (const OutputFile& file : files) writeFile(staging / file.name, file.contents, directory / file.name);
    for (const OutputFile& file : files) {
      published.push_back(publish(staging / file.name, directory / file.name, displaced / file.name));
    }
  } catch (const PrepareError&) {
    unpublish(published);
    fs::remove_all(staging, error);
    if (!existed) fs::remove(directory, error);  // only if we made it and it is empty again
    throw;
  }
  fs::remove_all(staging, error);  // the displaced files of the earlier run
}

}  // namespace octopoint::prepare
