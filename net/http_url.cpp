#include <cctype>

#include "octopoint/http.h"

namespace octopoint::net {

std::string HttpUrl::text() const {
  const bool ipv6 = host.find(':') != std::string::npos;
  return "http://" + (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port) + path;
}

std::optional<HttpUrl> parseHttpUrl(std::string_view text, std::string* error) {
  const auto fail = [&](const char* why) -> std::optional<HttpUrl> {
    if (error != nullptr) *error = why;
    return std::nullopt;
  };
  constexpr std::string_view kScheme = "http://";
  if (!text.starts_with(kScheme)) return fail("not an http:// URL");
  std::string_view rest = text.substr(kScheme.size());
  const std::size_t slash = rest.find('/');
  if (slash == std::string_view::npos)
    return fail("no path after the host (http://HOST:PORT/NAME.oct)");
  std::string_view authority = rest.substr(0, slash);
  HttpUrl url;
  url.path = std::string(rest.substr(slash));
  if (authority.find('@') != std::string_view::npos)
    return fail("user information is not supported");
  std::string_view port_text;
  if (authority.starts_with("[")) {
    const std::size_t close = authority.find(']');
    if (close == std::string_view::npos) return fail("unclosed '[' in the host");
    url.host = std::string(authority.substr(1, close - 1));
    const std::string_view after = authority.substr(close + 1);
    if (!after.empty()) {
      if (after.front() != ':') return fail("bad text after the host");
      port_text = after.substr(1);
    }
  } else {
    const std::size_t colon = authority.find(':');
    url.host = std::string(authority.substr(0, colon));
    if (colon != std::string_view::npos) port_text = authority.substr(colon + 1);
  }
  if (url.host.empty()) return fail("no host");
  if (!port_text.empty() || authority.ends_with(":")) {
    if (port_text.empty() || port_text.size() > 5) return fail("bad port");
    int port = 0;
    for (char c : port_text) {
      if (!std::isdigit(static_cast<unsigned char>(c))) return fail("bad port");
      port = port * 10 + (c - '0');
    }
    if (port < 1 || port > 65535) return fail("port outside 1..65535");
    url.port = port;
  }
  for (char c : url.path) {
    if (static_cast<unsigned char>(c) <= 0x20 || c == 0x7f)
      return fail("a space or control character in the path");
  }
  return url;
}

}  // namespace octopoint::net
