// octopoint-serve: serves a folder of model files over HTTP with Range requests, optionally shaped
// to a slow link, so that streaming (docs/streaming.md) can be measured on one machine.
#include <pthread.h>
#include <signal.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "net/model_server.h"

namespace {

constexpr const char* kUsage =
    R"(usage: octopoint-serve DIR [--port N] [--bind ADDR] [--rate BYTES/S] [--latency MS]
                       [--max-connections N]

Serves the files of DIR (e.g. chunked models written by octopoint-prepare --chunked) over HTTP,
with Range requests, until interrupted (SIGINT or SIGTERM).

  DIR                  the folder served; nothing outside it is (no "..", no links out)
  --port N             TCP port, 0..65535 (default 8080; 0: any free port)
  --bind ADDR          address to listen on (default 127.0.0.1: this machine only)
  --rate BYTES/S       shape each connection to this many bytes per second (default: unshaped)
  --latency MS         wait this long before each response, as a slow link's round trip
  --max-connections N  connections served at once, 1..1024 (default 64); more are answered 503
  -h, --help           show this help

Prints "octopoint-serve: serving DIR at http://ADDR:PORT/ ..." once listening. Requests whose line
and headers pass 16 KiB or take more than 10 s, and clients that take no bytes for 10 s, are cut
off. On any error prints one line on stderr and exits with status 1.
)";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::uint64_t parseCount(const std::string& flag, const std::string& text, std::uint64_t low,
                         std::uint64_t high) {
  errno = 0;
  char* end = nullptr;
  const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || text[0] == '-' || *end != '\0' || errno != 0 || value < low || value > high) {
    throw UsageError(flag + ": '" + text + "' is not a whole number in " + std::to_string(low) +
                     ".." + std::to_string(high));
  }
  return value;
}

octopoint::net::ServerOptions parseOptions(int argc, char** argv) {
  octopoint::net::ServerOptions options;
  bool have_root = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(arg + ": missing value (see --help)");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--port") {
      options.port = static_cast<int>(parseCount(arg, value(), 0, 65535));
    } else if (arg == "--bind") {
      options.bind_address = value();
    } else if (arg == "--rate") {
      options.rate_bytes_per_second = parseCount(arg, value(), 1, std::uint64_t{1} << 40);
    } else if (arg == "--latency") {
      options.latency_ms = static_cast<std::uint32_t>(parseCount(arg, value(), 0, 600'000));
    } else if (arg == "--max-connections") {
      options.max_connections = static_cast<int>(parseCount(arg, value(), 1, 1024));
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown argument '" + arg + "' (see --help)");
    } else if (!have_root) {
      options.root = arg;
      have_root = true;
    } else {
      throw UsageError("unexpected argument '" + arg + "': one DIR only (see --help)");
    }
  }
  if (!have_root) throw UsageError("no DIR given (see --help)");
  return options;
}

int run(int argc, char** argv) {
  const octopoint::net::ServerOptions options = parseOptions(argc, argv);
  // Signals go to one thread that stops the server; every other thread has them blocked.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  octopoint::net::ModelServer server(options);
  std::string error;
  if (!server.bind(&error)) throw UsageError(error);
  std::printf(
      "octopoint-serve: serving %s at http://%s:%d/ (rate %s, latency %u ms, at most %d "
      "connections)\n",
      options.root.c_str(), options.bind_address.c_str(), server.port(),
      options.rate_bytes_per_second == 0
          ? "unshaped"
          : (std::to_string(options.rate_bytes_per_second) + " B/s").c_str(),
      options.latency_ms, options.max_connections);
  std::fflush(stdout);
  std::thread stopper([&] {
    int signal_number = 0;
    sigwait(&signals, &signal_number);
    server.stop();
  });
  server.run();
  pthread_kill(stopper.native_handle(), SIGTERM);  // wakes the stopper when run() ended on its own
  stopper.join();
  std::printf(
      "octopoint-serve: stopped after %llu requests (%llu connections refused as too many)\n",
      static_cast<unsigned long long>(server.requestsServed()),
      static_cast<unsigned long long>(server.connectionsRefused()));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const UsageError& error) {
    std::fprintf(stderr, "octopoint-serve: %s\n", error.what());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "octopoint-serve: unexpected error: %s\n", error.what());
  }
  return 1;
}
