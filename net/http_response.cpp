#include "net/http_response.h"

#include <algorithm>
#include <cctype>

namespace octopoint::net {
namespace {

constexpr std::size_t kMaxReasonBytes = 200;  // kept for messages; the rest is read and dropped

bool isTokenChar(char c) {
  const auto u = static_cast<unsigned char>(c);
  return std::isalnum(u) || std::string_view("!#$%&'*+-.^_`|~").find(c) != std::string_view::npos;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

std::string printable(std::string_view text, std::size_t limit) {
  std::string out;
  for (char c : text.substr(0, limit)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  if (text.size() > limit) out += "...";
  return out;
}

}  // namespace

std::optional<std::string> ResponseHead::field(std::string_view name, bool* repeated) const {
  std::optional<std::string> found;
  for (const auto& [key, value] : headers) {
    if (key != name) continue;
    if (found && *found != value) {
      if (repeated != nullptr) *repeated = true;
      return std::nullopt;
    }
    found = value;
  }
  return found;
}

void ResponseHeadParser::failWith(std::string why) {
  state_ = State::kError;
  error_ = std::move(why);
}

std::size_t ResponseHeadParser::feed(std::string_view data) {
  std::size_t used = 0;
  while (state_ == State::kNeedMore && used < data.size()) {
    const std::string_view rest = data.substr(used);
    const std::size_t newline = rest.find('\n');
    const std::string_view piece =
        newline == std::string_view::npos ? rest : rest.substr(0, newline + 1);
    // Checked before anything is kept: no line or head grows past its limit (+ CR LF).
    if (line_.size() + piece.size() > limits_.max_line_bytes + 2) {
      failWith(std::string(status_read_ ? "a header line" : "a status line") + " longer than " +
               std::to_string(limits_.max_line_bytes) + " bytes");
      break;
    }
    if (total_ + piece.size() > limits_.max_head_bytes) {
      failWith("a response head longer than " + std::to_string(limits_.max_head_bytes) + " bytes");
      break;
    }
    total_ += piece.size();
    used += piece.size();
    line_.append(piece);
    if (newline == std::string_view::npos) continue;
    std::string_view line(line_);
    line.remove_suffix(1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    takeLine(line);
    line_.clear();
  }
  return used;
}

void ResponseHeadParser::takeLine(std::string_view line) {
  if (!status_read_) {
    // HTTP/1.x SP 3DIGIT [SP reason]
    if (line.size() < 12 || !line.starts_with("HTTP/1.") || (line[7] != '0' && line[7] != '1') ||
        line[8] != ' ' ||
        !std::all_of(line.begin() + 9, line.begin() + 12,
                     [](char c) { return c >= '0' && c <= '9'; }) ||
        (line.size() > 12 && line[12] != ' ')) {
      return failWith("not an HTTP/1.x status line: '" + printable(line, 40) + "'");
    }
    head_.status = (line[9] - '0') * 100 + (line[10] - '0') * 10 + (line[11] - '0');
    if (head_.status < 100) return failWith("a status code below 100");
    if (line.size() > 13) head_.reason = printable(line.substr(13), kMaxReasonBytes);
    status_read_ = true;
    return;
  }
  if (line.empty()) {
    state_ = State::kDone;
    return;
  }
  if (head_.headers.size() >= limits_.max_headers)
    return failWith("more than " + std::to_string(limits_.max_headers) + " header fields");
  const std::size_t colon = line.find(':');
  const std::string_view name = line.substr(0, colon);
  if (colon == std::string_view::npos || name.empty() ||
      !std::all_of(name.begin(), name.end(), isTokenChar)) {
    return failWith("a malformed header line: '" + printable(line, 40) + "'");
  }
  std::string key(name);
  std::transform(key.begin(), key.end(), key.begin(), [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  });
  head_.headers.emplace_back(std::move(key), std::string(trim(line.substr(colon + 1))));
}

std::optional<std::uint64_t> parseDecimal(std::string_view text) {
  if (text.empty() || text.size() > 19) return std::nullopt;
  std::uint64_t value = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return value;
}

std::optional<BodyLength> bodyLength(const ResponseHead& head, std::string* error) {
  const auto fail = [&](std::string why) -> std::optional<BodyLength> {
    if (error != nullptr) *error = std::move(why);
    return std::nullopt;
  };
  if (head.status == 204 || head.status == 304 || head.status < 200) return BodyLength{};
  bool repeated = false;
  if (const std::optional<std::string> coding = head.field("transfer-encoding", &repeated);
      coding || repeated) {
    return fail("a Transfer-Encoding (" + printable(coding.value_or("several"), 40) +
                ") where a byte range of known length was asked for");
  }
  const std::optional<std::string> length = head.field("content-length", &repeated);
  if (repeated) return fail("two different Content-Length fields");
  if (!length) return BodyLength{BodyLength::Kind::kUntilClose, 0};
  const std::optional<std::uint64_t> bytes = parseDecimal(*length);
  if (!bytes) return fail("a malformed Content-Length '" + printable(*length, 40) + "'");
  return BodyLength{BodyLength::Kind::kLength, *bytes};
}

bool parseContentRange(std::string_view text, std::uint64_t* first, std::uint64_t* last,
                       std::uint64_t* total) {
  if (!text.starts_with("bytes ")) return false;
  text.remove_prefix(6);
  const std::size_t dash = text.find('-');
  const std::size_t slash = text.find('/');
  if (dash == std::string_view::npos || slash == std::string_view::npos || slash < dash)
    return false;
  const std::optional<std::uint64_t> a = parseDecimal(text.substr(0, dash));
  const std::optional<std::uint64_t> b = parseDecimal(text.substr(dash + 1, slash - dash - 1));
  const std::string_view total_text = text.substr(slash + 1);
  const std::optional<std::uint64_t> t =
      total_text == "*" ? std::optional<std::uint64_t>(0) : parseDecimal(total_text);
  if (!a || !b || !t || *a > *b || (*t != 0 && *b >= *t)) return false;
  *first = *a;
  *last = *b;
  *total = *t;
  return true;
}

}  // namespace octopoint::net
