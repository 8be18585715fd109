#include "net/served_path.h"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace octopoint::net {
namespace {

constexpr std::string_view kFolderPage = "index.html";

bool plainSegment(std::string_view segment) {
  if (segment.empty() || segment == "." || segment == ".." || segment.size() > 255) return false;
  for (char c : segment) {
    const bool allowed =
        std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
    if (!allowed) return false;
  }
  return true;
}

// "/a/b.oct" with every segment plain.
bool plainPath(std::string_view path) {
  if (path.size() < 2 || path.front() != '/' || path.size() > 1024) return false;
  std::size_t at = 1;
  while (at <= path.size()) {
    const std::size_t slash = std::min(path.find('/', at), path.size());
    if (!plainSegment(path.substr(at, slash - at))) return false;
    at = slash + 1;
  }
  return true;
}

}  // namespace

PathVerdict resolveServedPath(const std::filesystem::path& root, std::string_view target,
                              std::string_view path, std::filesystem::path* file) {
  const std::string_view raw = target.substr(0, target.find('?'));
  if (raw != path) return PathVerdict::kRefused;
  // A folder's address ("/", "/web/") names its page, as on every web server; there is never a
  // listing of a folder.
  std::string named(raw);
  if (named.ends_with('/')) named += kFolderPage;
  if (!plainPath(named)) return PathVerdict::kRefused;
  std::error_code error;
  const std::filesystem::path candidate = root / std::filesystem::path(named.substr(1));
  if (!std::filesystem::exists(candidate, error)) return PathVerdict::kNotFound;
  // Follow every link, then insist on staying inside the folder: a link out is refused.
  const std::filesystem::path resolved = std::filesystem::canonical(candidate, error);
  if (error) return PathVerdict::kNotFound;
  const auto [root_end, inside] =
      std::mismatch(root.begin(), root.end(), resolved.begin(), resolved.end());
  if (root_end != root.end()) return PathVerdict::kRefused;
  if (!std::filesystem::is_regular_file(resolved, error)) return PathVerdict::kRefused;
  *file = resolved;
  return PathVerdict::kFile;
}

}  // namespace octopoint::net
