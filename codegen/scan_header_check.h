#pragma once
// Checking a scan file's header before PCL reads it: PCL 1.13's readers crash or allocate
// gigabytes on some headers (scan_loader.cpp lists what was found), so every size a header
// declares is checked against the real file length first.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace octopoint::prepare {

// Throws PrepareError with the one-line message "PATH: what (where)".
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what,
                       const std::string& where);

// a * b, or UINT64_MAX when that overflows: header sizes are untrusted.
std::uint64_t saturatingMul(std::uint64_t a, std::uint64_t b);

// File content quoted in a message: printable, short, and never a second line.
std::string printable(std::string_view text);

// Each returns the number of points the header declares, or throws PrepareError when the header is
// malformed or declares more data than the file of `file_size` bytes can hold.
std::uint64_t checkPcdHeader(const std::filesystem::path& path, std::uint64_t file_size);
std::uint64_t checkPlyHeader(const std::filesystem::path& path, std::uint64_t file_size);

// The bytes of a PLY scalar type ("float", "uchar", ...); 0 for an unknown name.
std::uint64_t plyTypeBytes(std::string_view type);

// The words of every header line up to and including the one whose first word is `last_keyword`
// ("DATA" for PCD, "end_header" for PLY), and the byte where the body starts: for the streamed
// readers (codegen/binary_scan_source.cpp), once the check above has accepted the header.
struct HeaderWords {
  std::vector<std::vector<std::string>> lines;
  std::uint64_t body_offset = 0;
};
HeaderWords readHeaderWords(const std::filesystem::path& path, std::uint64_t file_size,
                            std::string_view last_keyword);

}  // namespace octopoint::prepare
