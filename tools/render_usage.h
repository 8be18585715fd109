#pragma once
// octopoint-render's --help: every option it takes, what it does and its limits.

namespace octopoint {

extern const char* const kRenderUsage;

}  // namespace octopoint
