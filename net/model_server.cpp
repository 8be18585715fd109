#include "net/model_server.h"

#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fstream>
#include <vector>

#include "net/byte_range.h"
#include "net/content_type.h"
#include "net/served_path.h"

namespace octopoint::net {
namespace {

using Clock = std::chrono::steady_clock;

// Waits that end early when the server stops.
class StopSignal {
 public:
  void stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    cv_.notify_all();
  }
  bool stopped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return stopped_;
  }
  // False when stopped before `until`.
  bool sleepUntil(Clock::time_point until) {
    std::unique_lock<std::mutex> lock(mutex_);
    return !cv_.wait_until(lock, until, [&] { return stopped_; });
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  bool stopped_ = false;
};

// One connection's socket as cpp-httplib's Stream, with the limits cpp-httplib 0.11 does not have:
// a request (line and headers; GET has no body) may take at most kMaxRequestBytes and must arrive
// within ServerOptions::request_seconds of its first byte; a write waits at most
// ServerOptions::write_timeout_seconds for room.
// Reads are buffered for the connection's whole life, so pipelined requests are not lost.
class GuardedStream : public httplib::Stream {
 public:
  GuardedStream(int sock, const ServerOptions& options)
      : sock_(sock),
        request_seconds_(options.request_seconds),
        write_seconds_(options.write_timeout_seconds) {}

  // Waits up to `seconds` for the next request's first byte; false when none comes.
  bool awaitRequest(int seconds) {
    if (buffered_ == 0 && !poll(POLLIN, Clock::now() + std::chrono::seconds(seconds))) return false;
    request_bytes_ = 0;
    request_deadline_ = Clock::now() + std::chrono::seconds(request_seconds_);
    return true;
  }

  bool is_readable() const override { return buffered_ > 0 || pollNow(POLLIN); }
  bool is_writable() const override {
    return poll(POLLOUT, Clock::now() + std::chrono::seconds(write_seconds_));
  }

  // Whether a read failed: too large, too slow, or the peer went away. The connection is then
  // closed after the response cut-off requests get (if any), whatever keep-alive says.
  bool broken() const { return broken_; }

  ssize_t read(char* ptr, size_t size) override {
    if (request_bytes_ >= kMaxRequestBytes) return fail();  // the request is too large: drop it
    if (buffered_ == 0) {
      if (!poll(POLLIN, request_deadline_)) return fail();  // too slow
      const ssize_t got = ::recv(sock_, buffer_, sizeof buffer_, 0);
      if (got <= 0) return fail();
      buffered_ = static_cast<std::size_t>(got);
      at_ = 0;
    }
    const std::size_t n = std::min({size, buffered_, kMaxRequestBytes - request_bytes_});
    std::memcpy(ptr, buffer_ + at_, n);
    at_ += n;
    buffered_ -= n;
    request_bytes_ += n;
    return static_cast<ssize_t>(n);
  }

  ssize_t write(const char* ptr, size_t size) override {
    if (!is_writable()) return -1;
    return ::send(sock_, ptr, size, MSG_NOSIGNAL);
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    address(false, ip, port);
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override { address(true, ip, port); }
  socket_t socket() const override { return sock_; }

 private:
  ssize_t fail() {
    broken_ = true;
    return -1;
  }
  bool poll(short events, Clock::time_point deadline) const {
    for (;;) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return false;
      pollfd entry{sock_, events, 0};
      const int ready = ::poll(&entry, 1, static_cast<int>(std::min<long long>(left, 1000)));
      if (ready > 0) return (entry.revents & (events | POLLHUP | POLLERR)) != 0;
      if (ready < 0 && errno != EINTR) return false;
    }
  }
  bool pollNow(short events) const {
    pollfd entry{sock_, events, 0};
    return ::poll(&entry, 1, 0) > 0;
  }
  void address(bool local, std::string& ip, int& port) const {
    sockaddr_storage storage{};
    socklen_t length = sizeof storage;
    const int result = local ? ::getsockname(sock_, reinterpret_cast<sockaddr*>(&storage), &length)
                             : ::getpeername(sock_, reinterpret_cast<sockaddr*>(&storage), &length);
    char text[64] = {};
    port = -1;
    if (result == 0 && storage.ss_family == AF_INET) {
      const auto* v4 = reinterpret_cast<const sockaddr_in*>(&storage);
      ::inet_ntop(AF_INET, &v4->sin_addr, text, sizeof text);
      port = ntohs(v4->sin_port);
    } else if (result == 0 && storage.ss_family == AF_INET6) {
      const auto* v6 = reinterpret_cast<const sockaddr_in6*>(&storage);
      ::inet_ntop(AF_INET6, &v6->sin6_addr, text, sizeof text);
      port = ntohs(v6->sin6_port);
    }
    ip = text;
  }

  int sock_;
  int request_seconds_;
  int write_seconds_;
  char buffer_[4096];
  std::size_t at_ = 0, buffered_ = 0;
  std::size_t request_bytes_ = 0;
  Clock::time_point request_deadline_{};
  bool broken_ = false;
};

// Tells process_and_close_socket, run inline by the pool, to turn the connection away.
thread_local bool t_refuse_connection = false;

constexpr int kRequestsPerConnection = 1000;

// cpp-httplib's connection queue, bounded: a fixed set of worker threads, one connection each, and
// no waiting line; a connection that finds every worker busy is answered 503 at once.
class ConnectionPool : public httplib::TaskQueue {
 public:
  explicit ConnectionPool(int workers) {
    for (int i = 0; i < workers; ++i) threads_.emplace_back([this] { work(); });
  }
  void enqueue(std::function<void()> job) override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!shutting_down_ && waiting_ + busy_ < threads_.size()) {
        jobs_.push_back(std::move(job));
        ++waiting_;
        cv_.notify_one();
        return;
      }
    }
    t_refuse_connection = true;
    job();
    t_refuse_connection = false;
  }
  void shutdown() override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      shutting_down_ = true;
    }
    cv_.notify_all();
    for (std::thread& thread : threads_) thread.join();
  }

 private:
  void work() {
    for (;;) {
      std::function<void()> job;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        cv_.wait(lock, [&] { return shutting_down_ || !jobs_.empty(); });
        if (jobs_.empty()) return;
        job = std::move(jobs_.front());
        jobs_.pop_front();
        --waiting_;
        ++busy_;
      }
      job();
      std::lock_guard<std::mutex> lock(mutex_);
      --busy_;
    }
  }

  std::vector<std::thread> threads_;
  std::deque<std::function<void()>> jobs_;
  std::size_t waiting_ = 0, busy_ = 0;
  bool shutting_down_ = false;
  std::mutex mutex_;
  std::condition_variable cv_;
};

}  // namespace

class ModelServer::Impl : public httplib::Server {
 public:
  explicit Impl(ServerOptions options) : options_(std::move(options)) {
    new_task_queue = [this] { return new ConnectionPool(options_.max_connections); };
    Get(".*", [this](const httplib::Request& request, httplib::Response& response) {
      serve(request, response);
    });
  }

  ServerOptions options_;
  std::filesystem::path root_;
  int port_ = 0;
  StopSignal stop_;
  std::atomic<std::uint64_t> served_{0}, refused_{0};

 protected:
  bool process_and_close_socket(socket_t sock) override {
    if (t_refuse_connection) {
      refused_.fetch_add(1);
      static constexpr char kBusy[] =
          "HTTP/1.1 503 Service Unavailable\r\nContent-Length: 0\r\nConnection: close\r\n\r\n";
      ::send(sock, kBusy, sizeof kBusy - 1, MSG_NOSIGNAL | MSG_DONTWAIT);
    } else {
      GuardedStream stream(sock, options_);
      for (int request = 0; request < kRequestsPerConnection && !stop_.stopped(); ++request) {
        if (!stream.awaitRequest(options_.keep_alive_seconds)) break;
        bool connection_closed = false;
        const bool written = process_request(stream, false, connection_closed, nullptr);
        if (!written || connection_closed || stream.broken()) break;
      }
    }
    ::shutdown(sock, SHUT_RDWR);
    ::close(sock);
    return true;
  }

 private:
  void serve(const httplib::Request& request, httplib::Response& response) {
    served_.fetch_add(1);
    std::filesystem::path file;
    switch (resolveServedPath(root_, request.target, request.path, &file)) {
      case PathVerdict::kRefused:
        response.status = 403;
        return;
      case PathVerdict::kNotFound:
        response.status = 404;
        return;
      case PathVerdict::kFile:
        break;
    }
    std::error_code error;
    const std::uint64_t size = std::filesystem::file_size(file, error);
    if (error) {
      response.status = 404;
      return;
    }
    ByteRange range;
    const RangeVerdict verdict =
        parseRange(request.get_header_value("Range"), request.has_header("Range"), size, &range);
    response.set_header("Accept-Ranges", "bytes");
    // The browser must not guess another type than the one sent (a model is never a page).
    response.set_header("X-Content-Type-Options", "nosniff");
    const std::string name = file.filename().string();
    if (isPage(name)) response.set_header("Content-Security-Policy", std::string(kPagePolicy));
    if (verdict == RangeVerdict::kUnsatisfiable) {
      response.status = 416;
      response.set_header("Content-Range", "bytes */" + std::to_string(size));
      return;
    }
    if (options_.latency_ms > 0 &&
        !stop_.sleepUntil(Clock::now() + std::chrono::milliseconds(options_.latency_ms))) {
      response.status = 503;
      return;
    }
    const std::uint64_t length = size == 0 ? 0 : range.size();
    response.status = verdict == RangeVerdict::kPartial ? 206 : 200;
    if (verdict == RangeVerdict::kPartial) {
      response.set_header("Content-Range", "bytes " + std::to_string(range.first) + "-" +
                                               std::to_string(range.last) + "/" +
                                               std::to_string(size));
    }
    response.set_header("Content-Length", std::to_string(length));
    if (length == 0) return;
    auto in = std::make_shared<std::ifstream>(file, std::ios::binary);
    // Written in slices, each when the link's rate allows it (Q0: bytes and seconds): slice n
    // leaves no earlier than start + bytes sent / rate.
    const Clock::time_point start = Clock::now();
    const std::uint64_t rate = options_.rate_bytes_per_second;
    const std::uint64_t slice =
        rate == 0 ? 64 * 1024 : std::clamp<std::uint64_t>(rate / 50, 1, 64 * 1024);
    response.set_content_provider(
        std::string(contentTypeFor(name)),
        [this, in, range, length, rate, slice, start](std::size_t sent, httplib::DataSink& sink) {
          if (sent >= length) {
            sink.done();
            return true;
          }
          if (rate > 0) {
            const auto due = start + std::chrono::microseconds(sent * 1'000'000 / rate);
            if (!stop_.sleepUntil(due)) return false;
          }
          std::vector<char> buffer(static_cast<std::size_t>(std::min(slice, length - sent)));
          in->seekg(static_cast<std::streamoff>(range.first + sent));
          in->read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
          if (!*in) return false;  // the file changed under us: end the connection
          return sink.write(buffer.data(), buffer.size());
        });
  }
};

ModelServer::ModelServer(ServerOptions options)
    : impl_(std::make_unique<Impl>(std::move(options))) {}
ModelServer::~ModelServer() { stop(); }

bool ModelServer::bind(std::string* error) {
  std::error_code fs_error;
  impl_->root_ = std::filesystem::canonical(impl_->options_.root, fs_error);
  if (fs_error || !std::filesystem::is_directory(impl_->root_)) {
    *error = impl_->options_.root.string() + ": not a folder";
    return false;
  }
  impl_->set_read_timeout(impl_->options_.request_seconds);
  impl_->set_write_timeout(impl_->options_.write_timeout_seconds);
  impl_->set_payload_max_length(0);
  // A response is its headers, then its body in slices: with Nagle's algorithm a slice waits for
  // the client's (delayed, up to 40 ms) acknowledgement of the headers, which on a fast link costs
  // more than the transfer (a 4 KB range took 70-100 ms at 1 MB/s + 20 ms instead of 24 ms).
  impl_->set_tcp_nodelay(true);
  impl_->set_keep_alive_max_count(kRequestsPerConnection);  // what the Keep-Alive header announces
  impl_->set_keep_alive_timeout(impl_->options_.keep_alive_seconds);
  if (impl_->options_.port == 0) {
    impl_->port_ = impl_->bind_to_any_port(impl_->options_.bind_address);
  } else if (impl_->bind_to_port(impl_->options_.bind_address, impl_->options_.port)) {
    impl_->port_ = impl_->options_.port;
  } else {
    impl_->port_ = -1;
  }
  if (impl_->port_ <= 0) {
    *error = "cannot listen on " + impl_->options_.bind_address + " port " +
             std::to_string(impl_->options_.port);
    return false;
  }
  return true;
}

int ModelServer::port() const { return impl_->port_; }
void ModelServer::run() { impl_->listen_after_bind(); }

void ModelServer::stop() {
  impl_->stop_.stop();
  impl_->stop();
}

std::uint64_t ModelServer::requestsServed() const { return impl_->served_.load(); }
std::uint64_t ModelServer::connectionsRefused() const { return impl_->refused_.load(); }

}  // namespace octopoint::net
