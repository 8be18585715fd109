// The page's chunked model (web/octopoint_web.h, "Streaming"): the page fetches, the module decides
// and checks. What to ask for next is the native client's choice (net/fetch_planner.h over
// ProgressiveModel::fetchPriority, for the view of the last draw); every byte that arrives is
// handed to the same ProgressiveModel the native tools use, which validates the head, the record
// tables and each chunk before it is drawn, and refuses a damaged chunk so that it is asked for
// again (at most ProgressiveModel::kMaxChunkAttempts times). The draw is octopoint-render's of a
// chunked file (tools/chunked_render.cpp: the frame cleared, the progressive draw, resolveToRgb on
// its background, here straight into RGBA), so that the page's frame of a complete view is its PNG,
// pixel for pixel.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "net/fetch_planner.h"
#include "octopoint/progressive.h"
#include "renderer/perspective_fetch.h"
#include "web/octopoint_web.h"
#include "web/web_canvas.h"

namespace {

using namespace octopoint;
using web::fail;
using web::succeed;

// The first request asks for this many bytes: the head fits them in the files the preparer
// writes (net's StreamOptions::first_request_bytes); a larger head is asked for in a second one.
constexpr std::uint64_t kFirstRequestBytes = 4096;
// Bytes the page may copy into the module at once (octopoint_web_input): a piece of a body.
constexpr std::int32_t kMaxInputBytes = 1 << 24;

struct Request {
  std::int32_t id = 0;
  bool head = false;
  net::FetchRange range;
  std::vector<std::uint8_t> body;  // what arrived so far (not kept for the head's request)
  std::uint64_t got = 0;           // bytes that arrived
  std::size_t next = 0;            // the first item of the range not handed to the model yet
};

struct Stream {
  std::vector<std::uint8_t> head;  // the file's first bytes, while the head is being read
  std::uint64_t head_bytes = 0;    // the head's size, once the fixed header is in
  std::optional<ProgressiveModel> model;
  net::FetchPlanner planner{net::FetchPlanOptions{}};
  std::vector<Request> requests;  // in flight
  std::int32_t next_id = 1;
  Camera view;  // the camera of the last draw: what the fetch order follows
  // In walk mode, the perspective view of the last walk frame: what the fetch order follows then.
  std::optional<PerspectiveView> walk_view;
  PerspectiveFetchOrder walk_order;  // the status's count of the walk view's parts still to come
  std::uint64_t point_budget = 0;
  std::uint64_t received = 0;
  std::uint32_t refused = 0;
  bool failed = false;  // a head that is not a chunked model: nothing more is asked
  std::string failure;  // why
  // octopoint_web_stream_request's and octopoint_web_stream_status's answers.
  std::array<std::uint32_t, 3> request_words{};
  std::array<std::uint32_t, 11> status_words{};
  std::uint64_t drawn_points = 0;  // leaves the last draw drew
};

std::optional<Stream>& stream() {
  static std::optional<Stream> instance;
  return instance;
}

// Counts every part any stream's model took (and every stream opened): a new count, new held parts.
std::uint64_t& taken() {
  static std::uint64_t count = 0;
  return count;
}

std::vector<std::uint8_t>& input() {
  static std::vector<std::uint8_t> bytes;
  return bytes;
}

std::string where(const ChunkedIssue& issue) {
  return std::string(describe(issue.error)) + " (byte " + std::to_string(issue.offset) + ")";
}

Request* findRequest(Stream& s, std::int32_t id) {
  const auto found = std::find_if(s.requests.begin(), s.requests.end(),
                                  [id](const Request& request) { return request.id == id; });
  return found == s.requests.end() ? nullptr : &*found;
}

int failStream(Stream& s, std::string why) {
  s.failed = true;
  s.failure = std::move(why);
  return fail(s.failure);
}

// The head's bytes so far: reads its size from the fixed header, makes the model once the whole
// head is in, and gives it the tables and chunks that followed the head in the same request.
int takeHead(Stream& s) {
  ChunkedIssue issue;
  if (s.head_bytes == 0 && s.head.size() >= chunked::kFixedHeaderBytes) {
    const std::optional<std::uint64_t> size = chunkedHeadBytes(s.head, &issue);
    if (!size) return failStream(s, "not a chunked model: " + where(issue));
    s.head_bytes = *size;
  }
  if (!s.model && s.head_bytes > 0 && s.head.size() >= s.head_bytes) {
    std::optional<ProgressiveModel> model = ProgressiveModel::fromHead(s.head, &issue);
    if (!model) return failStream(s, "the model's head is refused: " + where(issue));
    s.model = std::move(model);
    ++taken();
  }
  // A part refused here is asked for again later as an item of its own.
  if (s.model) {
    static_cast<void>(s.model->acceptBytes(0, s.head, &issue));
    ++taken();  // whatever it took: the walk's held parts are assembled again
  }
  return succeed();
}

void endRequest(Stream& s, std::int32_t id) {
  const auto found = std::find_if(s.requests.begin(), s.requests.end(),
                                  [id](const Request& request) { return request.id == id; });
  if (found == s.requests.end()) return;
  if (!found->head) s.planner.abandon(found->range, found->next);
  s.requests.erase(found);
}

}  // namespace

namespace octopoint::web {

bool streamOpen() { return stream().has_value(); }

int drawStream(Variant variant, const Camera& camera) {
  Stream& s = *stream();
  s.view = camera;
  s.walk_view.reset();
  if (!s.model) return fail(s.failed ? s.failure : "waiting for the head");
  Canvas& out = canvas();
  Framebuffer& frame = out.sized(camera.width, camera.height);
  frame.clear();
  s.model->setPointBudget(s.point_budget);
  ProgressiveDrawStats stats;
  if (!s.model->draw(camera, variant, frame, &stats)) return fail(describe(CameraError::kOverflow));
  s.drawn_points = stats.points;
  out.resolveColour(s.model->baseModel(), kBackground);
  return succeed();
}

const ProgressiveModel* streamModel() {
  return stream() && stream()->model ? &*stream()->model : nullptr;
}

std::uint64_t streamTaken() { return taken(); }

void streamFollow(const PerspectiveView& view) {
  if (stream()) stream()->walk_view = view;
}

}  // namespace octopoint::web

extern "C" {

int octopoint_web_stream_open(void) {
  stream().emplace();
  ++taken();
  return succeed();
}

int octopoint_web_stream_close(void) {
  stream().reset();
  return succeed();
}

std::uint8_t* octopoint_web_input(std::int32_t bytes) {
  if (bytes < 1 || bytes > kMaxInputBytes) {
    fail("octopoint_web_input takes 1..16777216 bytes");
    return nullptr;
  }
  input().resize(static_cast<std::size_t>(bytes));
  return input().data();
}

std::int32_t octopoint_web_stream_next(void) {
  if (!stream()) return fail("no chunked model is open");
  Stream& s = *stream();
  if (s.failed) return fail(s.failure);
  Request request;
  if (!s.model) {
    const bool head_asked =
        std::any_of(s.requests.begin(), s.requests.end(), [](const Request& r) { return r.head; });
    if (head_asked) return 0;
    // Until the fixed header is in, ask for the first bytes; then for the rest of the head.
    std::uint64_t want = s.head_bytes > 0 ? s.head_bytes : kFirstRequestBytes;
    if (want <= s.head.size()) want = s.head.size() + 1;
    request.head = true;
    request.range.offset = s.head.size();
    request.range.size = want - s.head.size();
  } else if ((s.walk_view ? s.planner.next(*s.model, *s.walk_view, UINT64_MAX, request.range)
                          : s.planner.next(*s.model, s.view, UINT64_MAX, request.range)) !=
             net::FetchPlanner::Outcome::kRange) {
    return 0;
  }
  request.id = s.next_id++;
  s.request_words = {static_cast<std::uint32_t>(request.range.offset),
                     static_cast<std::uint32_t>(request.range.offset >> 32),
                     static_cast<std::uint32_t>(request.range.size)};
  s.requests.push_back(std::move(request));
  succeed();
  return s.requests.back().id;
}

const std::uint32_t* octopoint_web_stream_request(void) {
  return stream() ? stream()->request_words.data() : nullptr;
}

int octopoint_web_stream_receive(std::int32_t id, std::int32_t bytes) {
  if (!stream()) return fail("no chunked model is open");
  Stream& s = *stream();
  Request* request = findRequest(s, id);
  if (request == nullptr) return fail("no such request");
  if (bytes < 0 || static_cast<std::size_t>(bytes) > input().size())
    return fail("more bytes than octopoint_web_input gave room for");
  if (request->got + static_cast<std::uint64_t>(bytes) > request->range.size) {
    endRequest(s, id);
    return fail("the server sent more bytes than the " + std::to_string(request->range.size) +
                " asked for");
  }
  const std::span<const std::uint8_t> piece(input().data(), static_cast<std::size_t>(bytes));
  s.received += piece.size();
  request->got += piece.size();
  if (request->head) {
    s.head.insert(s.head.end(), piece.begin(), piece.end());
    return takeHead(s);
  }
  request->body.insert(request->body.end(), piece.begin(), piece.end());
  std::string refusal;
  request->next = s.planner.deliver(
      *s.model, request->range, request->body, request->next,
      [&](const FetchItem& item, const ChunkedIssue& issue) {
        if (issue.error == ChunkedError::kNone) {
          ++taken();
          return;
        }
        ++s.refused;
        refusal = std::string("refused a damaged ") +
                  (item.kind == FetchItem::Kind::kChunk ? "chunk" : "record table") + " of level " +
                  std::to_string(item.level) + ": " + where(issue);
      });
  if (refusal.empty()) return succeed();
  fail(refusal);
  return 1;  // the request goes on: its other items may be whole
}

int octopoint_web_stream_end(std::int32_t id) {
  if (!stream()) return fail("no chunked model is open");
  Stream& s = *stream();
  const Request* request = findRequest(s, id);
  if (request == nullptr) return fail("no such request");
  // The head's request may end early at the file's end (a file shorter than the first request).
  const bool whole = request->got == request->range.size || (request->head && s.model);
  const std::string message = "the body ended after " + std::to_string(request->got) + " of the " +
                              std::to_string(request->range.size) + " bytes asked for";
  endRequest(s, id);
  return whole ? succeed() : fail(message);
}

int octopoint_web_set_point_budget(std::int32_t points) {
  if (points < 0) return fail("the point budget is 0 (none) or more points");
  if (stream()) stream()->point_budget = static_cast<std::uint64_t>(points);
  return succeed();
}

const std::uint32_t* octopoint_web_stream_status(void) {
  if (!stream()) return nullptr;
  Stream& s = *stream();
  std::array<std::uint32_t, 11>& words = s.status_words;
  words.fill(0);
  words[0] = s.failed ? 3 : s.model ? 2 : 1;
  words[1] = static_cast<std::uint32_t>(s.received);
  words[2] = static_cast<std::uint32_t>(s.received >> 32);
  if (s.model) {
    const std::uint64_t file_bytes = s.model->head().file_bytes;
    words[3] = static_cast<std::uint32_t>(file_bytes);
    words[4] = static_cast<std::uint32_t>(file_bytes >> 32);
    words[5] = s.model->chunksIn(ChunkState::kHeld);
    std::size_t pending = 0;
    if (s.walk_view) {
      // The walk view is complete when nothing it sees is left to fetch (as net's ModelStream).
      static_cast<void>(s.walk_order.order(*s.model, *s.walk_view, false, {}, &pending));
      words[7] = pending == 0 ? 1 : 0;
    } else {
      s.model->fetchPriority(s.view, false, {}, &pending);
      words[7] = s.model->viewComplete(s.view) ? 1 : 0;
    }
    words[6] = static_cast<std::uint32_t>(pending);
  }
  words[8] = s.refused;
  words[9] = static_cast<std::uint32_t>(s.requests.size());
  words[10] = static_cast<std::uint32_t>(std::min<std::uint64_t>(s.drawn_points, UINT32_MAX));
  return words.data();
}

}  // extern "C"
