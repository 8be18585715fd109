#pragma once
// The one error type of the preparer. Its message is the single line the CLI prints on stderr:
// "<file>: <what went wrong> (<where>)", so it must name the file and the place, and end without
// a newline.

#include <string>

#include "cli/error.h"

namespace octopoint::prepare {

// A cli::Error, so that the tools report it like every other error of their command line.
class PrepareError : public cli::Error {
 public:
  explicit PrepareError(const std::string& message) : cli::Error(message) {}
};

}  // namespace octopoint::prepare
