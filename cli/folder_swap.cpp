// The whole-folder swap (cli/folder_swap.h). The sibling is made in the folder's parent, so that
// it is on the same file system (hard links and renameat2 need that); its name carries the
// writer's process id, so that a later run can tell a killed writer's sibling from a live one's.
#include "cli/folder_swap.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>  // renameat2 (glibc 2.28+), RENAME_EXCHANGE
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <system_error>

#include "cli/output_file.h"

namespace octopoint::cli {
namespace {

namespace fs = std::filesystem;

// Every entry is a regular file or a symbolic link (hard links can copy those), or a staging folder
// of a per-file writer killed earlier, which the copy leaves out (a live one's is left alone).
bool onlyFiles(const fs::path& directory) {
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; it != end; it.increment(error)) {
    if (error) return false;
    if (leftByDeadWriter(it->path().filename().string(), kStagingPrefix)) continue;
    const fs::file_status status = it->symlink_status(error);
    if (error || !(fs::is_regular_file(status) || fs::is_symlink(status))) return false;
  }
  return !error;
}

// Siblings of `name` that writers no longer running left in `parent`.
void removeStaleSiblings(const fs::path& parent, const std::string& name) {
  const std::string prefix = "." + name + std::string(kSwapInfix);
  std::error_code error;
  for (fs::directory_iterator it(parent, error), end; !error && it != end; it.increment(error)) {
    if (!leftByDeadWriter(it->path().filename().string(), prefix)) continue;
    std::error_code ignored;
    fs::remove_all(it->path(), ignored);
  }
}

// Hard-links every entry of `from` but the replaced ones and staging folders into `to`.
bool linkKept(const fs::path& from, const fs::path& to, const std::vector<std::string>& replaced) {
  std::error_code error;
  for (fs::directory_iterator it(from, error), end; it != end; it.increment(error)) {
    if (error) return false;
    const std::string name = it->path().filename().string();
    if (name.rfind(kStagingPrefix, 0) == 0) continue;
    if (std::find(replaced.begin(), replaced.end(), name) != replaced.end()) continue;
    // linkat without AT_SYMLINK_FOLLOW links a symbolic link itself, as the folder held it.
    if (::linkat(AT_FDCWD, it->path().c_str(), AT_FDCWD, (to / name).c_str(), 0) != 0) return false;
  }
  return !error;
}

}  // namespace

bool leftByDeadWriter(std::string_view name, std::string_view prefix) {
  if (!name.starts_with(prefix)) return false;
  const std::string digits(name.substr(prefix.size()));
  if (digits.empty() || digits.size() > 9 ||
      digits.find_first_not_of("0123456789") != std::string::npos)
    return false;
  const pid_t pid = static_cast<pid_t>(std::stol(digits));
  return pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH;
}

bool swapFolder(const fs::path& directory, const std::vector<std::string>& replaced,
                const std::function<void(const fs::path&)>& write_new) {
  const fs::path folder = directory.lexically_normal();
  const fs::path tidy = folder.has_filename() ? folder : folder.parent_path();  // "out/" -> "out"
  const std::string name = tidy.filename().string();
  if (name.empty() || name == "." || name == "..") return false;
  struct stat status {};
  if (::lstat(tidy.c_str(), &status) != 0 || !S_ISDIR(status.st_mode)) return false;  // a link
  // A folder we may not write into is left to the file-by-file way and its error (we could not
  // remove the old folder after the swap either).
  if (::access(tidy.c_str(), W_OK) != 0 || !onlyFiles(tidy)) return false;
  const fs::path parent = tidy.has_parent_path() ? tidy.parent_path() : fs::path(".");
  removeStaleSiblings(parent, name);
  const fs::path sibling =
      parent / ("." + name + std::string(kSwapInfix) + std::to_string(::getpid()));
  std::error_code error;
  fs::remove_all(sibling, error);
  if (::mkdir(sibling.c_str(), 0700) != 0) return false;  // a read-only parent: file by file
  if (!linkKept(tidy, sibling, replaced)) {
    fs::remove_all(sibling, error);
    return false;
  }
  try {
    write_new(sibling);
  } catch (...) {
    fs::remove_all(sibling, error);
    throw;
  }
  // The new folder keeps the old one's permissions (set once it is written: a read-only folder
  // stays read-only) and, where allowed, its owner.
  [[maybe_unused]] const int owner_kept = ::chown(sibling.c_str(), status.st_uid, status.st_gid);
  if (::chmod(sibling.c_str(), status.st_mode & 07777) != 0 ||
      ::renameat2(AT_FDCWD, sibling.c_str(), AT_FDCWD, tidy.c_str(), RENAME_EXCHANGE) != 0) {
    fs::remove_all(sibling, error);  // EINVAL, ENOSYS, EBUSY (a mount point): file by file
    return false;
  }
  fs::remove_all(sibling, error);  // now the old folder
  return true;
}

}  // namespace octopoint::cli
