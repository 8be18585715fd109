#include "cli/arguments.h"

#include "cli/error.h"
#include "cli/text.h"

namespace octopoint::cli {

bool ArgumentReader::next() {
  if (at_ + 1 >= argc_) return false;
  current_ = argv_[++at_];
  name_ = current_;
  has_attached_ = false;
  attached_.clear();
  const std::size_t equals = current_.find('=');
  if (current_.rfind("--", 0) == 0 && equals != std::string::npos) {
    name_ = current_.substr(0, equals);
    attached_ = current_.substr(equals + 1);
    has_attached_ = true;
  }
  return true;
}

std::string ArgumentReader::value() {
  if (has_attached_) return attached_;
  if (at_ + 1 >= argc_) throw Error(printable(name_) + ": missing value (see --help)");
  return argv_[++at_];
}

void ArgumentReader::noValue() const {
  if (has_attached_) throw Error(printable(name_) + ": takes no value, got " + inQuotes(attached_));
}

void ArgumentReader::refuseUnknown() const {
  if (isPlain()) throw Error("unexpected argument " + inQuotes(current_) + " (see --help)");
  throw Error("unknown option " + inQuotes(name_) + " (see --help)");
}

}  // namespace octopoint::cli
