#include "cli/strict_json.h"

#include <set>
#include <vector>

#include "cli/error.h"
#include "cli/text.h"

namespace octopoint::cli {

using nlohmann::json;
constexpr std::size_t kMaxNesting = kMaxJsonNesting;

// Parses the JSON text, naming in a failure the key whose value was being read: nlohmann's own
// message says "number overflow parsing '1e400'" but not where. A key given twice in one object
// (JSON leaves its meaning open, nlohmann keeps the last) and nesting past kMaxNesting are errors.
nlohmann::json parseStrictJson(const std::string& text, const std::string& path,
                               std::string_view kind) {
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos) {
    throw Error(displayPath(path) + ": a NUL byte at byte " + std::to_string(nul) + ": " +
                std::string(kind) + " is JSON text");
  }
  struct Open {  // an object or list being read
    bool object = false;
    std::string key;  // the object's key being read
    std::set<std::string> keys;
  };
  std::vector<Open> open;
  auto where = [&open] {
    std::string keys;
    for (const Open& level : open) {
      if (level.object && !level.key.empty()) keys += (keys.empty() ? "" : ".") + level.key;
    }
    return keys;
  };
  const json::parser_callback_t track_keys = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (open.size() == kMaxNesting) {
          throw Error(displayPath(path) + ": objects and lists nested deeper than " +
                      std::to_string(kMaxNesting) + " levels" +
                      (where().empty() ? std::string() : " (key " + inQuotes(where()) + ")"));
        }
        open.push_back({event == json::parse_event_t::object_start, {}, {}});
        break;
      case json::parse_event_t::key:
        open.back().key = parsed.get<std::string>();
        if (!open.back().keys.insert(open.back().key).second) {
          throw Error(displayPath(path) + ": key " + inQuotes(where()) + ": given twice");
        }
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!open.empty()) open.pop_back();
        break;
      case json::parse_event_t::value:
        break;
    }
    return true;
  };
  try {
    return json::parse(text, track_keys);
  } catch (const json::exception& error) {
    // nlohmann's message reads "[json.exception.parse_error.101] parse error at line L, column C:
    // ...".
    std::string message = error.what();
    const std::size_t cut = message.find("] ");
    if (cut != std::string::npos) message = message.substr(cut + 2);
    const std::string key = where();
    throw Error(displayPath(path) + ": not valid JSON: " + printable(message, 160) +
                (key.empty() ? std::string() : " (key " + inQuotes(key) + ")"));
  }
}

}  // namespace octopoint::cli
