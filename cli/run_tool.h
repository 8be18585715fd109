#pragma once
// The main() of every octopoint tool: runs it and turns every failure into the house rule, one
// line on stderr ("TOOL: message") and exit status 1. A cli::Error, or any std::runtime_error, is
// a message for the user as it is; running out of memory says so; anything else is reported as an
// internal error. The line is made printable and cut to one line whatever the message holds.
//
//   int main(int argc, char** argv) { return octopoint::cli::runTool("octopoint-render", argc,
//   argv, run); }

namespace octopoint::cli {

using ToolMain = int (*)(int argc, char** argv);

int runTool(const char* tool_name, int argc, char** argv, ToolMain run);

// Prints "TOOL: message" as one line on stderr (what runTool does for an error).
void printError(const char* tool_name, const char* message);

}  // namespace octopoint::cli
