// octopoint's HTTP server (net/model_server.h) on 127.0.0.1 and a free port, spoken to over real
// sockets: what it serves, and everything it must refuse.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <numeric>
#include <string>
#include <vector>

#include "net/byte_range.h"
#include "octopoint/http.h"
#include "tests/support/net_test_support.h"

namespace octopoint {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using octopoint::testing::Exchange;
using octopoint::testing::RunningServer;
using octopoint::testing::TempFolder;

std::vector<std::uint8_t> counting(std::size_t size) {
  std::vector<std::uint8_t> bytes(size);
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<std::uint8_t>(i * 7 + i / 251);
  return bytes;
}

struct Served {
  TempFolder folder;
  std::vector<std::uint8_t> file = counting(100'000);
  std::unique_ptr<RunningServer> server;

  explicit Served(net::ServerOptions options = {}) {
    folder.write("model.oct", file);
    std::filesystem::create_directory(folder.path() / "sub");
    folder.write("sub/inner.oct", counting(10));
    std::filesystem::create_symlink("/etc/hostname", folder.path() / "out.oct");
    std::filesystem::create_directory_symlink("/", folder.path() / "root_link");
    std::filesystem::create_symlink(folder.path() / "model.oct", folder.path() / "alias.oct");
    options.root = folder.path();
    options.port = 0;
    server = std::make_unique<RunningServer>(options);
  }
  int port() const { return server->port(); }
  Exchange get(const std::string& target, const std::string& headers = "") const {
    return testing::rawExchange(
        port(),
        "GET " + target + " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n" + headers + "\r\n", 3s);
  }
};

std::string bodyOf(const Exchange& exchange) {
  const std::size_t at = exchange.response.find("\r\n\r\n");
  return at == std::string::npos ? "" : exchange.response.substr(at + 4);
}

TEST(ModelServer, ServesWholeFilesAndSingleRanges) {
  const Served served;
  const Exchange whole = served.get("/model.oct");
  EXPECT_EQ(whole.status(), 200);
  EXPECT_EQ(bodyOf(whole), std::string(served.file.begin(), served.file.end()));
  const Exchange part = served.get("/model.oct", "Range: bytes=1000-1099\r\n");
  EXPECT_EQ(part.status(), 206);
  EXPECT_NE(part.response.find("Content-Range: bytes 1000-1099/100000"), std::string::npos);
  EXPECT_EQ(bodyOf(part), std::string(served.file.begin() + 1000, served.file.begin() + 1100));
  EXPECT_EQ(served.get("/sub/inner.oct").status(), 200);
  EXPECT_EQ(served.get("/alias.oct").status(), 200);  // a link that stays inside is fine
  EXPECT_EQ(served.get("/model.oct?cache=1").status(), 200);
  const Exchange head = testing::rawExchange(
      served.port(), "HEAD /model.oct HTTP/1.1\r\nConnection: close\r\n\r\n", 3s);
  EXPECT_EQ(head.status(), 200);
  EXPECT_NE(head.response.find("Content-Length: 100000"), std::string::npos);
  EXPECT_TRUE(bodyOf(head).empty());
}

// The page (web/) is served beside the models: each kind of file with its type, whatever the case
// of its extension and whether whole or a range; a page with its policy against inline scripts.
TEST(ModelServer, SendsEachFileWithItsContentTypeAndAPageWithItsPolicy) {
  const Served served;
  const struct {
    const char* name;
    const char* type;
  } cases[] = {{"index.html", "text/html; charset=utf-8"},
               {"octopoint.js", "text/javascript; charset=utf-8"},
               {"octopoint.css", "text/css; charset=utf-8"},
               {"octopoint_web.wasm", "application/wasm"},
               {"SHOUT.WASM", "application/wasm"},
               {"Page.HTML", "text/html; charset=utf-8"},
               {"shot.png", "image/png"},
               {"model.oct", "application/octet-stream"},
               {"wasm", "application/octet-stream"},
               {"notes.wasm.bak", "application/octet-stream"}};
  for (const auto& c : cases) {
    if (std::string(c.name) != "model.oct") served.folder.write(c.name, counting(100));
    for (const std::string range : {"", "Range: bytes=10-19\r\n"}) {
      SCOPED_TRACE(std::string(c.name) + (range.empty() ? " whole" : " range"));
      const Exchange exchange = served.get("/" + std::string(c.name), range);
      EXPECT_EQ(exchange.status(), range.empty() ? 200 : 206);
      EXPECT_NE(exchange.response.find("Content-Type: " + std::string(c.type) + "\r\n"),
                std::string::npos);
      EXPECT_NE(exchange.response.find("X-Content-Type-Options: nosniff\r\n"), std::string::npos);
      const bool page = std::string(c.type).starts_with("text/html");
      EXPECT_EQ(exchange.response.find("Content-Security-Policy: default-src 'self'; script-src "
                                       "'self' 'wasm-unsafe-eval'; ") != std::string::npos,
                page);
      EXPECT_EQ(exchange.response.find("unsafe-inline"), std::string::npos);
    }
  }
}

TEST(ModelServer, RefusesEveryPathOutsideItsFolder) {
  const Served served;
  for (const std::string target : {"/../etc/passwd",
                                   "/%2e%2e/etc/passwd",
                                   "/%2E%2E%2Fetc%2Fpasswd",
                                   "/..%2fetc/passwd",
                                   "/%252e%252e/etc/passwd",
                                   "/..%252f..%252fetc/passwd",
                                   "//etc/passwd",
                                   "/sub/../model.oct",
                                   "/./model.oct",
                                   "/out.oct",
                                   "/root_link/etc/passwd",
                                   "http://127.0.0.1/etc/passwd",
                                   "/model.oct%00.txt",
                                   "/sub\\..\\model.oct",
                                   "/sub",
                                   "//",
                                   "/sub//",
                                   "/%2fetc/passwd",
                                   "/\xc0\xae\xc0\xae/etc/passwd",
                                   "/..",
                                   "/."}) {
    const Exchange exchange = served.get(target);
    EXPECT_TRUE(exchange.status() == 403 || exchange.status() == 400)
        << target << ": " << exchange.status();
    EXPECT_EQ(exchange.response.find("root:"), std::string::npos) << target;
  }
  EXPECT_EQ(served.get("/etc/passwd").status(), 404);  // a path in the folder, where there is none
}

// A folder's address serves its page, as a user typing the server's address expects; a folder
// without one is not found (never listed).
TEST(ModelServer, AnswersAFolderWithItsPage) {
  const Served served;
  EXPECT_EQ(served.get("/").status(), 404);
  EXPECT_EQ(served.get("/sub/").status(), 404);
  served.folder.write("index.html", counting(100));
  served.folder.write("sub/index.html", counting(30));
  for (const std::string target : {"/", "/?model=model.oct", "/sub/"}) {
    SCOPED_TRACE(target);
    const Exchange page = served.get(target);
    EXPECT_EQ(page.status(), 200);
    EXPECT_NE(page.response.find("Content-Type: text/html; charset=utf-8\r\n"), std::string::npos);
    EXPECT_NE(page.response.find("Content-Security-Policy: "), std::string::npos);
  }
  EXPECT_EQ(bodyOf(served.get("/sub/")).size(), 30u);
  EXPECT_EQ(served.get("/sub").status(), 403);  // the folder itself is no file
}

TEST(ModelServer, AnswersBadAndUnsatisfiableRangesWith416) {
  const Served served;
  // Ranges cpp-httplib cannot parse it answers 416 itself; those it parses and we refuse (outside
  // the file, several) also name the file's size.
  struct Case {
    std::string range;
    int status;
    std::size_t body;
    bool names_size = false;
  };
  for (const Case& c : std::vector<Case>{{"bytes=0-9", 206, 10},
                                         {"bytes=99990-", 206, 10},
                                         {"bytes=-3", 206, 3},
                                         {"bytes=99000-500000", 206, 1000},  // clamped to the end
                                         {"bytes=100000-", 416, 0, true},
                                         {"bytes=100000-100005", 416, 0, true},
                                         {"bytes=10-5", 416, 0},
                                         {"bytes=-0", 416, 0, true},
                                         {"bytes=abc", 416, 0},
                                         {"bytes=", 416, 0},
                                         {"items=0-5", 416, 0},
                                         {"bytes=0-1,3-4", 416, 0, true},
                                         {"bytes=18446744073709551616-", 416, 0},
                                         {"bytes=-99999999999999999999", 416, 0}}) {
    const Exchange exchange = served.get("/model.oct", "Range: " + c.range + "\r\n");
    EXPECT_EQ(exchange.status(), c.status) << c.range;
    EXPECT_EQ(bodyOf(exchange).size(), c.body) << c.range;
    if (c.names_size) {
      EXPECT_NE(exchange.response.find("Content-Range: bytes */100000"), std::string::npos)
          << c.range;
    }
  }
}

TEST(ModelServer, CutsOffRequestsWithTooMuchHeader) {
  const Served served;
  const std::string filler(1000, 'a');
  std::string request = "GET /model.oct HTTP/1.1\r\n";
  for (int i = 0; i < 20; ++i) request += "X-Filler-" + std::to_string(i) + ": " + filler + "\r\n";
  request += "\r\n";  // 20 kB of headers, past the 16 kB bound
  const Exchange exchange = testing::rawExchange(served.port(), request, 3s);
  EXPECT_NE(exchange.status(), 200);
  EXPECT_TRUE(exchange.closed_by_server);
  EXPECT_EQ(served.get("/model.oct").status(), 200);  // and serves the next client as before
}

TEST(ModelServer, TimesOutAClientThatSendsItsRequestSlowly) {
  net::ServerOptions options;
  options.request_seconds = 1;
  const Served served(options);
  const auto start = Clock::now();
  // One byte every 200 ms: the 40-byte request would take 8 s; the server gives it 1.
  const Exchange exchange = testing::rawExchange(
      served.port(), "GET /model.oct HTTP/1.1\r\nHost: x\r\n\r\n", 6s, 1, 200ms);
  EXPECT_TRUE(exchange.closed_by_server);
  EXPECT_NE(exchange.status(), 200);
  EXPECT_LT(Clock::now() - start, 4s);
}

TEST(ModelServer, CutsOffAClientThatStopsReading) {
  net::ServerOptions options;
  options.write_timeout_seconds = 1;
  options.max_connections = 1;
  TempFolder folder;
  folder.write("big.oct", counting(64 << 20));  // far more than the socket buffers hold
  options.root = folder.path();
  options.port = 0;
  RunningServer server(options);
  testing::IdleConnection reader(server.port());
  reader.send("GET /big.oct HTTP/1.1\r\nHost: x\r\n\r\n");  // then never reads
  std::this_thread::sleep_for(300ms);
  const std::string probe =
      "GET /big.oct HTTP/1.1\r\nRange: bytes=0-9\r\nConnection: close\r\n\r\n";
  EXPECT_EQ(testing::rawExchange(server.port(), probe, 2s).status(),
            503);  // the one worker is taken
  const auto start = Clock::now();
  Exchange after;
  do {
    std::this_thread::sleep_for(200ms);
    after = testing::rawExchange(server.port(), probe, 2s);
  } while (after.status() != 206 && Clock::now() - start < 20s);
  EXPECT_EQ(after.status(), 206);  // the reader was dropped after the write timeout
  EXPECT_LT(Clock::now() - start, 10s);
}

TEST(ModelServer, CapsConnectionsAndAnswersTheRest503) {
  net::ServerOptions options;
  options.max_connections = 4;
  options.keep_alive_seconds = 30;
  const Served served(options);
  std::vector<std::unique_ptr<testing::IdleConnection>> idle;
  for (int i = 0; i < 4; ++i)
    idle.push_back(std::make_unique<testing::IdleConnection>(served.port()));
  std::this_thread::sleep_for(200ms);  // each has a worker now
  const Exchange refused = served.get("/model.oct");
  EXPECT_EQ(refused.status(), 503);
  EXPECT_GE(served.server->server().connectionsRefused(), 1u);
  idle.pop_back();
  const auto start = Clock::now();
  Exchange served_again;
  do {
    served_again = served.get("/model.oct", "Range: bytes=0-0\r\n");
  } while (served_again.status() != 206 && Clock::now() - start < 3s);
  EXPECT_EQ(served_again.status(), 206);
}

TEST(ModelServer, ShapesEachConnectionToItsRateAndLatency) {
  net::ServerOptions options;
  options.rate_bytes_per_second = 50'000;
  options.latency_ms = 300;
  const Served served(options);
  std::string error;
  const std::optional<net::HttpUrl> url =
      net::parseHttpUrl("http://127.0.0.1:" + std::to_string(served.port()) + "/model.oct", &error);
  net::RangeClient client(*url, {});
  std::uint64_t got = 0;
  const auto start = Clock::now();
  const net::FetchResult result =
      client.fetch(0, 50'000, [&](std::uint64_t, std::span<const std::uint8_t> piece) {
        got += piece.size();
        return true;
      });
  const auto took = Clock::now() - start;
  EXPECT_EQ(result.status, net::FetchStatus::kOk) << result.message;
  EXPECT_EQ(got, 50'000u);
  EXPECT_GE(took, 1200ms);  // 300 ms, then 50 kB at 50 kB/s, less one slice sent at once
  EXPECT_LT(took, 5s);
}

}  // namespace
}  // namespace octopoint
