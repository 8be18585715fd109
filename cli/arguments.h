#pragma once
// Walks a tool's command line: options with values ("--size 320x240" or "--size=320x240"),
// switches ("--fill") and plain arguments (a scan path). Every failure is a cli::Error naming the
// argument, cut to a readable length.
//
//   cli::ArgumentReader args(argc, argv);
//   while (args.next()) {
//     if (args.is("--size")) size = cli::parseFrameSize(args.name(), args.value(), 1, 8192);
//     else if (args.is("--fill")) fill = true;
//     else if (args.isPlain()) scan = args.current();
//     else args.refuseUnknown();
//   }

#include <string>
#include <string_view>

namespace octopoint::cli {

class ArgumentReader {
 public:
  ArgumentReader(int argc, char** argv) : argc_(argc), argv_(argv) {}

  // Moves to the next argument; false when there is none left.
  bool next();
  // The current argument as given.
  const std::string& current() const { return current_; }
  // The current option's name: "--size" also for "--size=320x240".
  const std::string& name() const { return name_; }
  // Whether the current argument is the option `flag` (long options also as "flag=value").
  bool is(std::string_view flag) const { return name_ == flag; }
  // Whether it is a plain argument (not starting with '-', or exactly "-").
  bool isPlain() const { return current_.empty() || current_[0] != '-' || current_ == "-"; }
  // The current option's value: after '=', or the next argument. Throws "--size: missing value".
  std::string value();
  // Throws for a switch given a value ("--fill=yes"): call it for options without values.
  void noValue() const;
  // Throws "unknown option '--frobnicate' (see --help)" or, for a plain argument,
  // "unexpected argument 'x' (see --help)".
  [[noreturn]] void refuseUnknown() const;

 private:
  int argc_;
  char** argv_;
  int at_ = 0;
  std::string current_;
  std::string name_;
  std::string attached_;  // the value after '=' in "--name=value"
  bool has_attached_ = false;
};

}  // namespace octopoint::cli
