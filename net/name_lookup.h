#pragma once
// Looking a host name up within a deadline. getaddrinfo blocks for as long as the system's
// resolver waits (resolv.conf's timeout x attempts x name servers: 10 s and more for a server that
// does not answer), so the connect deadline did not bound it. Here a numeric address is converted
// at once; a name is looked up by glibc's getaddrinfo_a on its own thread and waited for until the
// deadline or an abort, then abandoned: cancelled, or left to finish and freed by a later lookup.

#include <netdb.h>

#include <chrono>
#include <memory>
#include <string>

namespace octopoint::net {

struct FreeAddresses {
  void operator()(addrinfo* list) const { ::freeaddrinfo(list); }
};
using Addresses = std::unique_ptr<addrinfo, FreeAddresses>;

// The TCP addresses of `host` at `port`, found before `deadline`, into `found`; "" when found,
// else why ("cannot resolve HOST: no answer in time", "... : Name or service not known"), or
// "aborted" once `abort_fd` is readable (the connection's eventfd).
[[nodiscard]] std::string lookUp(const std::string& host, int port,
                                 std::chrono::steady_clock::time_point deadline, int abort_fd,
                                 Addresses& found);

}  // namespace octopoint::net
