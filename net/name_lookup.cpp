#include "net/name_lookup.h"

#include <poll.h>

#include <algorithm>
#include <csignal>
#include <ctime>
#include <mutex>
#include <vector>

namespace octopoint::net {
namespace {

// One getaddrinfo_a request: glibc's thread reads the strings and writes the block until the
// lookup ends, so all of it lives on the heap for as long as that takes.
struct Request {
  std::string host;
  std::string service;
  addrinfo hints{};
  gaicb block{};
};

// Lookups given up while glibc's thread still ran them; freed once they end.
std::mutex abandoned_mutex;
std::vector<Request*> abandoned;

void freeEnded() {
  const std::lock_guard lock(abandoned_mutex);
  std::erase_if(abandoned, [](Request* request) {
    const int state = ::gai_error(&request->block);
    if (state == EAI_INPROGRESS) return false;
    if (state == 0 && request->block.ar_result != nullptr) ::freeaddrinfo(request->block.ar_result);
    delete request;
    return true;
  });
}

void abandon(std::unique_ptr<Request> request) {
  if (::gai_cancel(&request->block) == EAI_CANCELED) return;  // glibc lets go of it
  if (::gai_error(&request->block) != EAI_INPROGRESS) {       // it ended meanwhile
    if (request->block.ar_result != nullptr) ::freeaddrinfo(request->block.ar_result);
    return;
  }
  const std::lock_guard lock(abandoned_mutex);
  abandoned.push_back(request.release());
}

bool isReadable(int fd) {
  pollfd entry{fd, POLLIN, 0};
  return ::poll(&entry, 1, 0) > 0;
}

}  // namespace

std::string lookUp(const std::string& host, int port,
                   std::chrono::steady_clock::time_point deadline, int abort_fd, Addresses& found) {
  auto request = std::make_unique<Request>();
  request->host = host;
  request->service = std::to_string(port);
  request->hints.ai_family = AF_UNSPEC;
  request->hints.ai_socktype = SOCK_STREAM;
  request->hints.ai_flags = AI_NUMERICSERV;
  // An address written as numbers needs no lookup (and no thread).
  addrinfo numeric = request->hints;
  numeric.ai_flags |= AI_NUMERICHOST;
  addrinfo* list = nullptr;
  if (::getaddrinfo(host.c_str(), request->service.c_str(), &numeric, &list) == 0) {
    found.reset(list);
    return {};
  }
  freeEnded();
  request->block.ar_name = request->host.c_str();
  request->block.ar_service = request->service.c_str();
  request->block.ar_request = &request->hints;
  gaicb* requests[] = {&request->block};
  sigevent none{};
  none.sigev_notify = SIGEV_NONE;
  if (const int error = ::getaddrinfo_a(GAI_NOWAIT, requests, 1, &none); error != 0)
    return "cannot resolve " + host + ": " + ::gai_strerror(error);
  for (;;) {
    if (const int state = ::gai_error(&request->block); state != EAI_INPROGRESS) {
      if (state != 0) return "cannot resolve " + host + ": " + ::gai_strerror(state);
      found.reset(request->block.ar_result);
      return {};
    }
    if (isReadable(abort_fd)) {
      abandon(std::move(request));
      return "aborted";
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      abandon(std::move(request));
      return "cannot resolve " + host + ": no answer in time";
    }
    // Short waits, so that an abort is seen within 50 ms (it comes on an eventfd, which
    // gai_suspend cannot wait on).
    const long wait_ms = std::min<long>(static_cast<long>(left.count()), 50);
    const timespec slice{0, wait_ms * 1'000'000L};
    const gaicb* waiting[] = {&request->block};
    ::gai_suspend(waiting, 1, &slice);
  }
}

}  // namespace octopoint::net
