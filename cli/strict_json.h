#pragma once
// JSON files users write (scene files, camera paths), read strictly: a failure is one line naming
// the file and the key being read, a key given twice or nesting past kMaxJsonNesting is refused,
// and so is a NUL byte (junk after it would otherwise pass unseen). Host tools only.

#include <cstddef>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>

#include "cli/text.h"

namespace octopoint::cli {

// How deep objects and lists may nest: a scene needs 3 ({"viewpoints": [{...}]}); the limit keeps a
// file of a million '[' from costing a million nested values.
inline constexpr std::size_t kMaxJsonNesting = 8;

// The JSON value of `text` read from `path`; a cli::Error "PATH: what (key K)" otherwise. `kind`
// names the file in messages ("a scene file").
nlohmann::json parseStrictJson(const std::string& text, const std::string& path,
                               std::string_view kind);

// Reading the values of such a file, each failure one line "PATH: key K: what", thrown as
// `ErrorType` (a cli::Error, or the preparer's own kind of it).
template <typename ErrorType>
class JsonReader {
 public:
  explicit JsonReader(const std::string& path) : path_(displayPath(path)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw ErrorType(path_ + ": key " + inQuotes(key) + ": " + what);
  }

  // A number within [low, high].
  double number(const nlohmann::json& value, const std::string& key, double low,
                double high) const {
    if (!value.is_number()) fail(key, "expected a number");
    const double x = value.get<double>();
    if (!(x >= low && x <= high))
      fail(key, realText(x) + " is outside " + realText(low) + ".." + realText(high));
    return x;
  }

  // Fails when `object` is not an object or has a key outside `known`.
  void onlyKeys(const nlohmann::json& object, const std::string& where,
                std::initializer_list<const char*> known) const {
    if (!object.is_object()) fail(where, "expected an object");
    const std::set<std::string> allowed(known.begin(), known.end());
    for (const auto& item : object.items()) {
      if (!allowed.contains(item.key()))
        fail(where.empty() ? item.key() : where + "." + item.key(), "unknown key");
    }
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace octopoint::cli
