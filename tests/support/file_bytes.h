#pragma once
// A file's bytes read whole, and bytes written to a file: for tests that damage files on purpose.

#include <filesystem>
#include <fstream>
#include <string>

namespace octopoint::testing {

inline std::string fileBytes(const std::filesystem::path& path) {
  std::string bytes(std::filesystem::file_size(path), '\0');
  std::ifstream(path, std::ios::binary)
      .read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return bytes;
}

// Writes `bytes` to `directory` / `name` and returns that path.
inline std::filesystem::path writeFileBytes(const std::filesystem::path& directory,
                                            const std::string& name, const std::string& bytes) {
  const std::filesystem::path path = directory / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

}  // namespace octopoint::testing
