#include "codegen/ascii_body.h"

#include <charconv>
#include <fstream>
#include <string_view>
#include <system_error>

#include "cli/text.h"
#include "codegen/scan_header_check.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

// No number a scan writer writes is longer (a double with 17 digits, sign and exponent is ~24).
constexpr std::size_t kMaxValueChars = 64;
// PCL skips blank lines and any spaces; a writer pads columns with a few. 64 KiB of nothing else
// in a row is not data.
constexpr std::uint64_t kMaxSpaceRun = 1 << 16;

// The whole of `text` as a value of `type`: floats may be nan or inf (dropped points are written
// so); integers must be whole and fit the size. Sets `value` for integers (a PLY list's count).
bool parsesAs(std::string_view text, const ValueType& type, std::uint64_t* value = nullptr) {
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  const char* end = text.data() + text.size();
  if (type.kind == 'F') {
    if (type.size == 4) {
      float parsed = 0;
      const auto result = std::from_chars(text.data(), end, parsed);
      return result.ptr == end && result.ec == std::errc();
    }
    double parsed = 0;
    const auto result = std::from_chars(text.data(), end, parsed);
    return result.ptr == end && result.ec == std::errc();
  }
  const int bits = static_cast<int>(8 * type.size);
  if (type.kind == 'U') {
    std::uint64_t parsed = 0;
    const auto result = std::from_chars(text.data(), end, parsed);
    if (value != nullptr) *value = parsed;
    return result.ptr == end && result.ec == std::errc() &&
           (bits == 64 || parsed < (std::uint64_t{1} << bits));
  }
  std::int64_t parsed = 0;
  const auto result = std::from_chars(text.data(), end, parsed);
  if (value != nullptr)
    *value = parsed < 0 ? ~std::uint64_t{0} : static_cast<std::uint64_t>(parsed);
  const std::int64_t limit = bits == 64 ? 0 : std::int64_t{1} << (bits - 1);
  return result.ptr == end && result.ec == std::errc() &&
         (bits == 64 || (parsed >= -limit && parsed < limit));
}

std::string typeName(const ValueType& type) {
  const char* kind = type.kind == 'F' ? "float" : type.kind == 'U' ? "uint" : "int";
  return std::string(kind) + std::to_string(8 * type.size);
}

// Walks the body value by value, knowing which element and property each value belongs to.
class BodyChecker {
 public:
  BodyChecker(const fs::path& path, std::size_t first_line,
              const std::vector<AsciiElement>& elements)
      : path_(path), elements_(elements), line_(first_line) {
    skipFinishedElements();
  }

  // A value longer than any number, or a long run of white space, fails where it starts to be
  // one: a 1 GiB body of NUL bytes or of spaces is refused after 64 KiB, not after reading it all.
  void feed(std::string_view chunk) {
    for (char c : chunk) {
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        endValue();
        if (++space_run_ > kMaxSpaceRun) {
          fail(path_,
               "more than " + std::to_string(kMaxSpaceRun) +
                   " bytes of white space in a row (spaces or blank lines): not scan data",
               where());
        }
        if (c == '\n') endLine(false);
      } else {
        space_run_ = 0;
        token_ += c;
        if (token_.size() > kMaxValueChars) endValue();  // fails: no value is that long
      }
    }
  }

  void finish() {
    endValue(true);
    const std::size_t end_line = line_;  // the last line, or the empty one after a final newline
    endLine(true);
    if (element_ < elements_.size()) {
      const AsciiElement& element = elements_[element_];
      const std::string declared = "header declares " + std::to_string(element.count) + " " +
                                   element.plural + " but the ascii data has " +
                                   counted(item_, "data line") +
                                   (element_ > 0 ? " of them (after the earlier elements)" : "");
      // Blank lines are skipped (PCL skips them too): when there were some, the data may be whole
      // and a blank line stand where a point was meant; the first is the place to look.
      if (blank_lines_ > 0) {
        const char* verb = blank_lines_ == 1 ? ", which holds no " : ", which hold no ";
        fail(path_, declared + " and " + counted(blank_lines_, "blank line") + verb + element.name,
             (blank_lines_ == 1 ? "line " : "the first at line ") +
                 std::to_string(first_blank_line_));
      }
      fail(path_, "truncated: " + declared, "line " + std::to_string(end_line));
    }
  }

 private:
  std::string where() const { return "line " + std::to_string(line_); }

  static std::string counted(std::uint64_t n, const std::string& what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  }

  void skipFinishedElements() {
    while (element_ < elements_.size() && item_ == elements_[element_].count) {
      ++element_;
      item_ = 0;
    }
  }

  // Moves to the next value the current line expects; false when the line is complete.
  bool nextSlot() {
    const auto& properties = elements_[element_].properties;
    while (property_ < properties.size()) {
      const AsciiProperty& property = properties[property_];
      const std::uint64_t values =
          property.is_list ? (list_started_ ? list_items_ : 0) : property.repeat;
      if (property.is_list && !list_started_) return true;  // the list's count comes first
      if (in_property_ < values) return true;
      ++property_;
      in_property_ = 0;
      list_started_ = false;
    }
    return false;
  }

  // `at_end_of_file`: the file ends right after this value, so one that does not parse may be cut.
  void endValue(bool at_end_of_file = false) {
    if (token_.empty()) return;
    if (element_ == elements_.size()) {
      fail(path_, "more data lines than the header declares", where());
    }
    if (!nextSlot()) {
      fail(path_,
           "more values than the header declares for a " + printable(elements_[element_].name) +
               " item",
           where());
    }
    const AsciiProperty& property = elements_[element_].properties[property_];
    const bool is_count = property.is_list && !list_started_;
    const ValueType& type = is_count ? property.list_count : property.type;
    std::uint64_t value = 0;
    if (token_.size() > kMaxValueChars || !parsesAs(token_, type, &value)) {
      const std::string quoted = cli::inQuotes(token_);
      const std::string expected = std::string(is_count ? "a list length, " : "") + "a " +
                                   typeName(type) + " (" + elements_[element_].property_word +
                                   " '" + printable(property.name) + "')";
      fail(path_,
           at_end_of_file ? "truncated: the data ends in " + quoted + ", which is not " + expected
                          : quoted + " is not " + expected,
           where());
    }
    if (is_count) {
      list_started_ = true;
      list_items_ = value;
    } else {
      ++in_property_;
    }
    ++values_in_line_;
    token_.clear();
  }

  void endLine(bool at_end_of_file) {
    if (values_in_line_ > 0) {
      if (nextSlot()) {
        const std::string what = "a data line of " + std::to_string(values_in_line_) +
                                 " values, short of what the header declares for a " +
                                 printable(elements_[element_].name) + " item";
        fail(path_, at_end_of_file ? "truncated: " + what : what, where());
      }
      ++item_;
      skipFinishedElements();
    } else if (!at_end_of_file && element_ < elements_.size()) {
      if (blank_lines_++ == 0) first_blank_line_ = line_;
    }
    values_in_line_ = 0;
    property_ = 0;
    in_property_ = 0;
    list_started_ = false;
    ++line_;
  }

  const fs::path& path_;
  const std::vector<AsciiElement>& elements_;
  std::size_t line_;
  std::size_t element_ = 0;
  std::uint64_t item_ = 0;  // data lines of the current element so far
  std::uint64_t values_in_line_ = 0;
  std::size_t property_ = 0;
  std::uint64_t in_property_ = 0;
  bool list_started_ = false;
  std::uint64_t list_items_ = 0;
  std::uint64_t blank_lines_ = 0;  // lines without a value among the data, skipped
  std::size_t first_blank_line_ = 0;
  std::string token_;
  std::uint64_t space_run_ = 0;  // white space bytes since the last value byte
};

}  // namespace

void checkAsciiBody(const fs::path& path, std::uint64_t body_offset, std::size_t first_line,
                    const std::vector<AsciiElement>& elements) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(body_offset));
  BodyChecker checker(path, first_line, elements);
  std::string buffer(1 << 16, '\0');
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    checker.feed(std::string_view(buffer.data(), static_cast<std::size_t>(in.gcount())));
  }
  checker.finish();
}

}  // namespace octopoint::prepare
