// A URL parsed by an installed octopoint::net (tests/package/main.cpp): links it and cpp-httplib.
#include <optional>
#include <string>

#include "octopoint/http.h"

bool parsesUrl() {
  std::string why;
  const std::optional<octopoint::net::HttpUrl> url =
      octopoint::net::parseHttpUrl("http://127.0.0.1:8080/model.oct", &why);
  return url && url->port == 8080 && url->path == "/model.oct";
}
