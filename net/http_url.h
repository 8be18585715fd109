#pragma once
// An http:// URL as the client takes it: http://HOST[:PORT]/PATH. No https, no user info.

#include <optional>
#include <string>
#include <string_view>

namespace octopoint::net {

struct HttpUrl {
  std::string host;  // a name, an IPv4 address, or an IPv6 address without its brackets
  int port = 80;
  std::string path;  // starts with '/'
  std::string text() const;
};

// nullopt, with `error` saying why in a few words, when `text` is not such a URL.
std::optional<HttpUrl> parseHttpUrl(std::string_view text, std::string* error);

}  // namespace octopoint::net
