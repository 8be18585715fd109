#pragma once
// The --rule flag of octopoint-reference-closure and octopoint-reference-truth: a SplatRule
// (app/reference_surface.h) written K,SCALE,QUANTILE[,EDGE_OFFSET,EDGE_SCALE].
#include <string>

#include "app/reference_surface.h"

namespace octopoint::tradeoff {

// Throws cli::Error naming `flag` when `text` is not 3 or 5 numbers in range: K 1..64, SCALE
// 0.1..4, QUANTILE 0..1, EDGE_OFFSET 0..1, EDGE_SCALE 0..4 (without the last two, the rule has no
// outline points).
SplatRule parseSplatRule(const std::string& flag, const std::string& text);

}  // namespace octopoint::tradeoff
