#pragma once
// The output-file rule of every tool: an output that exists must be a regular file (a device,
// FIFO, directory or socket is refused, never replaced: `-o /dev/null` as root must not destroy
// /dev/null), and what a tool writes appears whole or not at all: it is written to a temporary
// beside its place and renamed into it. A set of files (the preparer's sources and model) is
// staged in a folder inside the output directory and put in place together; a failure puts the
// earlier set back. Termination signals are held meanwhile (cli/signals.h): an interrupted write
// cleans up before the process ends.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace octopoint::cli {

// Throws cli::Error "PATH: ..." when `path` exists and is not a regular file (symbolic links are
// judged by what they point to), or when its directory does not exist or is not a directory.
void checkOutputFile(const std::filesystem::path& path);

// Throws cli::Error "PATH: ..." when `path` exists and is not a directory (a regular file, a FIFO,
// a device: named by its kind; symbolic links are judged by what they point to), is a symlink loop
// or a dangling link. A path that does not exist yet passes: writeFilesAtomically creates it.
void checkOutputDirectory(const std::filesystem::path& path);

// checkOutputFile, then writes `bytes` into a temporary beside `path` and renames it over `path`
// (through a symbolic link, onto the file it points to). Throws cli::Error and leaves no
// temporary when anything fails.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

struct OutputFile {
  std::string name;  // file name inside the output directory
  std::string contents;
};

// Creates `directory` if needed and puts every file in it, all together or none (see above).
// `obsolete` names files of an earlier set that this one replaces without writing them again (the
// preparer's level sources of depths this run leaves out): each that is there is taken out with
// the set, and put back when the set fails. Staging folders that killed runs (SIGKILL, power loss)
// left in `directory` are removed first. Throws cli::Error naming the file or directory at fault;
// the directory then holds what it held before (a directory this call created is removed again).
void writeFilesAtomically(const std::filesystem::path& directory,
                          const std::vector<OutputFile>& files,
                          const std::vector<std::string>& obsolete = {});

// The prefix of the staging folders: ".octopoint-staging-" followed by the writer's process id.
inline constexpr std::string_view kStagingPrefix = ".octopoint-staging-";

}  // namespace octopoint::cli
