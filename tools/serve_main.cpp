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

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/run_tool.h"
#include "net/model_server.h"

namespace {

constexpr const char* kUsage =
    R"(usage: octopoint-serve DIR [--port N] [--bind ADDR] [--rate BYTES/S] [--latency MS]
                       [--max-connections N]

Serves the files of DIR (e.g. chunked models written by octopoint-prepare --chunked) over HTTP,
with Range requests, until interrupted (SIGINT or SIGTERM). The web page (build/wasm/web/,
docs/web.md) is served too: .html, .js, .css, .wasm (application/wasm), .png, .json, .svg and .txt
files with their content types, a page with a Content-Security-Policy that allows no inline
script; anything else as application/octet-stream. A folder's address (/, /sub/) serves its
index.html; folders are never listed.

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

octopoint::net::ServerOptions parseOptions(int argc, char** argv) {
  using namespace octopoint;
  net::ServerOptions options;
  bool have_root = false;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::cout << kUsage;
      std::exit(0);
    } else if (args.is("--port")) {
      options.port = cli::parseInt(args.name(), args.value(), 0, 65535);
    } else if (args.is("--bind")) {
      options.bind_address = args.value();
    } else if (args.is("--rate")) {
      options.rate_bytes_per_second = static_cast<std::uint64_t>(
          cli::parseInteger(args.name(), args.value(), 1, std::int64_t{1} << 40));
    } else if (args.is("--latency")) {
      options.latency_ms =
          static_cast<std::uint32_t>(cli::parseInt(args.name(), args.value(), 0, 600'000));
    } else if (args.is("--max-connections")) {
      options.max_connections = cli::parseInt(args.name(), args.value(), 1, 1024);
    } else if (args.isPlain() && !have_root) {
      options.root = args.current();
      have_root = true;
    } else {
      args.refuseUnknown();
    }
  }
  if (!have_root) throw cli::Error("no DIR given (see --help)");
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
  if (!server.bind(&error)) throw octopoint::cli::Error(error);
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
  return octopoint::cli::runTool("octopoint-serve", argc, argv, run);
}
