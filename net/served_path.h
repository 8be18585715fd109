#pragma once
// Which file a request path names, for a server that must never serve anything outside its folder.
// Only plain names are served: each path segment made of letters, digits, '.', '_' and '-', not
// "." or "..", no empty segment, nothing percent-encoded left (the raw request target must be as
// plain as the decoded path, so no encoding of any of these can slip through), and the file found
// must, once every symbolic link is followed, still lie inside the served folder and be a regular
// file. A path ending in '/' names that folder's index.html.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace octopoint::net {

enum class PathVerdict {
  kFile,      // a regular file inside the folder
  kRefused,   // a name we never serve (403)
  kNotFound,  // a plain name, but no such file (404)
};

// `root` must be canonical (std::filesystem::canonical). `target` is the request target as sent
// (before percent-decoding, without the query), `path` the decoded path the HTTP library made of
// it.
PathVerdict resolveServedPath(const std::filesystem::path& root, std::string_view target,
                              std::string_view path, std::filesystem::path* file);

}  // namespace octopoint::net
