#pragma once
// octopoint-render --info: what a user needs to know of a model before drawing it, above all where
// its cube lies in the scan (the line `cube X0,Y0,Z0 EDGE`), so that --eye can be placed.

#include <string>

#include "tools/model_source.h"

namespace octopoint {

// The text --info prints for `loaded` (several lines, each ending in a newline).
std::string modelInfo(const LoadedModel& loaded);

}  // namespace octopoint
