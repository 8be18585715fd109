#pragma once
// The --rule flag of octopoint-reference-closure and octopoint-reference-truth: a SplatRule
// (lab/reference_surface.h) written K,SCALE,QUANTILE[,EDGE_OFFSET,EDGE_SCALE]; and the flags that
// set its other parts.
#include <string>

#include "lab/reference_surface.h"

namespace octopoint::tradeoff {

// Throws cli::Error naming `flag` when `text` is not 3 or 5 numbers in range: K 1..64, SCALE
// 0.1..4, QUANTILE 0..1, EDGE_OFFSET 0..1, EDGE_SCALE 0..4 (without the last two, the rule has no
// outline points).
SplatRule parseSplatRule(const std::string& flag, const std::string& text);

// The --outline flag of octopoint-reference-truth: sets `rule`'s outline points from
// K,GAP,SCALE,SHIFT (K 3..64, GAP 30..359 degrees, SCALE 0..4, SHIFT 0..1), or none; throws
// cli::Error naming `flag` otherwise.
void parseOutlineRule(const std::string& flag, const std::string& text, SplatRule& rule);

// The --sparse flag of octopoint-reference-closure and octopoint-tradeoff: SplatRule's
// sparse_factor, 0 (no point is a sparse outlier) or 1..10; throws cli::Error naming `flag`
// otherwise.
double parseSparseFactor(const std::string& flag, const std::string& text);

}  // namespace octopoint::tradeoff
