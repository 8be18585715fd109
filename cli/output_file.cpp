// Whole-or-nothing output (cli/output_file.h). A single file goes to a temporary beside it and is
// renamed over it. A set is written into a staging folder inside the output directory (same file
// system, so the renames are atomic); only when every file is written are they renamed into
// place, one by one. A file of an earlier run that a new one replaces is moved into the staging
// folder first, so that if a later rename fails every file already put in place is taken out again
// and the earlier ones are put back: the directory holds the old set or the new set, never a mix.
// Only SIGKILL (or a power cut) during those renames could leave a mix, so where Linux can swap
// two folders in one step the whole folder is swapped instead (cli/folder_swap.h).
#include "cli/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "cli/error.h"
#include "cli/file_size_signal.h"
#include "cli/folder_swap.h"
#include "cli/signals.h"
#include "cli/text.h"

namespace octopoint::cli {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& what) {
  throw Error(displayPath(path) + ": " + what);
}

void throwIfInterrupted(const fs::path& path) {
  if (const int signal_number = TerminationSignalsHeld::interrupted()) {
    fail(path,
         "interrupted by signal " + std::to_string(signal_number) + " before it was complete");
  }
}

std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISREG(mode)) return "a regular file";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Writes all of `bytes` to a new file at `path` (which must not exist).
void writeNewFile(const fs::path& path, std::string_view bytes, const fs::path& shown_as) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    fail(shown_as.parent_path().empty() ? fs::path(".") : shown_as.parent_path(),
         std::string("cannot write here: ") + std::strerror(errno));
  }
  std::size_t done = 0;
  int error = 0;
  while (done < bytes.size()) {
    const ssize_t wrote = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) {
      error = wrote < 0 ? errno : ENOSPC;
      break;
    }
    done += static_cast<std::size_t>(wrote);
  }
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    ::unlink(path.c_str());
    fail(shown_as,
         std::string("write failed (") + std::strerror(error) + "; disk full or file size limit?)");
  }
}

// One file put in place, and whether an earlier file of that name waits in `displaced`.
struct Published {
  fs::path final_path;
  fs::path displaced;
  bool had_previous = false;
};

// Renames one staged file into place, moving an earlier file of that name aside first.
Published publish(const fs::path& staged, const fs::path& final_path, const fs::path& displaced) {
  std::error_code error;
  Published done{final_path, displaced, false};
  const fs::file_status existing = fs::symlink_status(final_path, error);
  if (fs::is_regular_file(existing) || fs::is_symlink(existing)) {
    fs::rename(final_path, displaced, error);
    if (error) fail(final_path, "cannot replace the earlier file (" + error.message() + ")");
    done.had_previous = true;
  }
  fs::rename(staged, final_path, error);
  if (error) {
    std::error_code ignored;
    if (done.had_previous) fs::rename(displaced, final_path, ignored);
    fail(final_path, "cannot rename into place (" + error.message() + ")");
  }
  return done;
}

// Moves a file of the earlier set that the new set does not hold aside, with the set's displaced
// files (unpublish puts it back). Nothing there, or not a regular file or link: nothing to do.
Published takeOut(const fs::path& final_path, const fs::path& displaced) {
  std::error_code error;
  Published done{final_path, displaced, false};
  const fs::file_status existing = fs::symlink_status(final_path, error);
  if (!fs::is_regular_file(existing) && !fs::is_symlink(existing)) return done;
  fs::rename(final_path, displaced, error);
  if (error) fail(final_path, "cannot take out the earlier file (" + error.message() + ")");
  done.had_previous = true;
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

// Staging folders of writers that no longer run (killed with SIGKILL, or the machine went down).
void removeStaleStaging(const fs::path& directory) {
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    if (!leftByDeadWriter(it->path().filename().string(), kStagingPrefix)) continue;
    std::error_code ignored;
    fs::remove_all(it->path(), ignored);
  }
}

}  // namespace

void checkOutputFile(const fs::path& path) {
  if (path.empty()) throw Error("an empty output file name was given");
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) {
    if (!S_ISREG(status.st_mode)) {
      fail(path, "exists and is " + kindOf(status.st_mode) +
                     ", not a regular file: refusing to replace it");
    }
    return;
  }
  const int error = errno;
  struct stat link {};
  if (error == ENOENT && ::lstat(path.c_str(), &link) == 0) {
    fail(path, "is a dangling symbolic link: refusing to write through it");
  }
  if (error == ELOOP) fail(path, "too many levels of symbolic links (a symlink loop?)");
  if (error != ENOENT) fail(path, std::string("cannot look at it: ") + std::strerror(error));
  const fs::path parent = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  struct stat parent_status {};
  if (::stat(parent.c_str(), &parent_status) != 0 || !S_ISDIR(parent_status.st_mode)) {
    fail(path, "its directory " + displayPath(parent) + " does not exist");
  }
}

void checkOutputDirectory(const fs::path& path) {
  if (path.empty()) throw Error("an empty output directory name was given");
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) {
    if (!S_ISDIR(status.st_mode))
      fail(path, "exists and is not a directory: it is " + kindOf(status.st_mode));
    return;
  }
  const int error = errno;
  struct stat link {};
  if (error == ENOENT && ::lstat(path.c_str(), &link) == 0) {
    fail(path, "is a dangling symbolic link: refusing to write through it");
  }
  if (error == ELOOP) fail(path, "too many levels of symbolic links (a symlink loop?)");
  if (error == ENOTDIR) fail(path, "a part of the path is not a directory");
  if (error != ENOENT) fail(path, std::string("cannot look at it: ") + std::strerror(error));
}

void writeFileAtomically(const fs::path& path, std::string_view bytes) {
  checkOutputFile(path);
  std::error_code error;
  // Through a symbolic link: replace the file it points to, not the link.
  const bool is_link = fs::is_symlink(fs::symlink_status(path, error));
  error.clear();  // set when nothing is there yet, which is fine
  const fs::path target = is_link ? fs::canonical(path, error) : path;
  if (error) fail(path, "cannot follow the symbolic link (" + error.message() + ")");
  std::string temporary_name = ".";  // appended: GCC 12 warns falsely (-Wrestrict) on "." + string
  temporary_name += target.filename().string();
  temporary_name += ".tmp-";
  temporary_name += std::to_string(::getpid());
  const fs::path temporary = target.parent_path() / temporary_name;
  const TerminationSignalsHeld signals_held;
  const FileSizeSignalIgnored file_size_signal_ignored;
  fs::remove(temporary, error);  // a leftover of a killed run with our process id
  writeNewFile(temporary, bytes, path);
  if (TerminationSignalsHeld::interrupted()) {
    fs::remove(temporary, error);
    throwIfInterrupted(path);
  }
  fs::rename(temporary, target, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    fail(path, "cannot rename into place (" + error.message() + ")");
  }
}

void writeFilesAtomically(const fs::path& directory, const std::vector<OutputFile>& files,
                          const std::vector<std::string>& obsolete) {
  checkOutputDirectory(directory);
  std::error_code error;
  const bool existed = fs::exists(directory, error);
  if (!existed) {
    fs::create_directories(directory, error);
    if (error) fail(directory, "cannot create the output directory (" + error.message() + ")");
  }
  const TerminationSignalsHeld signals_held;
  const FileSizeSignalIgnored file_size_signal_ignored;
  if (existed) {  // the folder is there, so a failed check leaves nothing to clean up
    for (const OutputFile& file : files) checkOutputFile(directory / file.name);
    std::vector<std::string> replaced = obsolete;
    for (const OutputFile& file : files) replaced.push_back(file.name);
    const auto write_new = [&](const fs::path& folder) {
      for (const OutputFile& file : files) {
        writeNewFile(folder / file.name, file.contents, directory / file.name);
        throwIfInterrupted(directory / file.name);
      }
    };
    if (swapFolder(directory, replaced, write_new)) return;
  }
  const fs::path staging = directory / (std::string(kStagingPrefix) + std::to_string(::getpid()));
  const fs::path displaced = staging / "displaced";
  std::vector<Published> published;
  try {
    for (const OutputFile& file : files) checkOutputFile(directory / file.name);
    removeStaleStaging(directory);
    fs::remove_all(staging, error);
    if (!fs::create_directory(staging, error) || !fs::create_directory(displaced, error)) {
      fail(directory, "cannot write into the output directory (" + error.message() + ")");
    }
    for (const OutputFile& file : files) {
      writeNewFile(staging / file.name, file.contents, directory / file.name);
      throwIfInterrupted(directory / file.name);
    }
    for (const OutputFile& file : files) {
      published.push_back(
          publish(staging / file.name, directory / file.name, displaced / file.name));
    }
    for (const std::string& name : obsolete) {
      const Published taken = takeOut(directory / name, displaced / name);
      if (taken.had_previous) published.push_back(taken);  // else nothing to put back on failure
    }
  } catch (...) {  // also bad_alloc: nothing may stay behind
    unpublish(published);
    fs::remove_all(staging, error);
    if (!existed) fs::remove(directory, error);  // only if we made it and it is empty again
    throw;
  }
  fs::remove_all(staging, error);  // the displaced files of the earlier run
}

}  // namespace octopoint::cli
