#pragma once
// Puts a new set of files into an output folder in one step, so that even SIGKILL (which no
// signal handler sees) at any moment leaves the old set or the new one, never a mix: a sibling
// folder is made beside it holding hard links to every entry the new set keeps and the new files
// themselves, and Linux's renameat2(RENAME_EXCHANGE) swaps the two folders atomically; the old
// one is then removed. Where the exchange cannot be made (another kernel or file system, a folder
// holding subfolders, hard links refused, the folder being a symbolic link or a mount point)
// nothing has changed and the caller falls back to renaming file by file (cli/output_file.cpp).

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace octopoint::cli {

// Swaps `directory` (which exists) for a copy of it without the entries named in `replaced`, into
// which `write_new` writes the new files (it is given the copy's path and throws on failure).
// Returns false, with `directory` untouched and nothing left behind, when the whole-folder
// exchange is not possible here. When `write_new` throws, the copy is removed and the exception
// goes on, the folder untouched. Sibling folders that killed runs left are removed first.
bool swapFolder(const std::filesystem::path& directory, const std::vector<std::string>& replaced,
                const std::function<void(const std::filesystem::path&)>& write_new);

// True when `name` is `prefix` followed by the process id of a process that no longer runs: what a
// writer killed with SIGKILL (or a power cut) left behind.
bool leftByDeadWriter(std::string_view name, std::string_view prefix);

// The infix of the sibling folders: "." + folder name + ".octopoint-swap-" + the writer's pid.
inline constexpr std::string_view kSwapInfix = ".octopoint-swap-";

}  // namespace octopoint::cli
