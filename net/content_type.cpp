#include "net/content_type.h"

#include <array>
#include <cctype>
#include <string_view>

namespace octopoint::net {
namespace {

struct Known {
  std::string_view extension;  // lower case, with the dot
  std::string_view type;
};

// What the page (web/) and its documentation consist of; the models stay octet streams.
constexpr std::array<Known, 8> kKnown{{
    {".html", "text/html; charset=utf-8"},
    {".js", "text/javascript; charset=utf-8"},
    {".css", "text/css; charset=utf-8"},
    {".wasm", "application/wasm"},
    {".json", "application/json"},
    {".png", "image/png"},
    {".svg", "image/svg+xml"},
    {".txt", "text/plain; charset=utf-8"},
}};

bool endsWithIgnoringCase(std::string_view name, std::string_view lower_suffix) {
  if (name.size() < lower_suffix.size()) return false;
  const std::string_view tail = name.substr(name.size() - lower_suffix.size());
  for (std::size_t i = 0; i < tail.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(tail[i])) != lower_suffix[i]) return false;
  }
  return true;
}

}  // namespace

std::string_view contentTypeFor(std::string_view name) {
  for (const Known& known : kKnown) {
    if (endsWithIgnoringCase(name, known.extension)) return known.type;
  }
  return "application/octet-stream";
}

bool isPage(std::string_view name) { return contentTypeFor(name).starts_with("text/html"); }

}  // namespace octopoint::net
