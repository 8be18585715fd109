#include "lab/splat_rule_flag.h"

#include <vector>

#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/real_numbers.h"
#include "cli/text.h"

namespace octopoint::tradeoff {

namespace {

std::vector<std::string> commaSeparated(const std::string& text) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return parts;
}

}  // namespace

SplatRule parseSplatRule(const std::string& flag, const std::string& text) {
  const std::vector<std::string> parts = commaSeparated(text);
  if (parts.size() != 3 && parts.size() != 5) {
    throw cli::Error(flag + ": " + cli::inQuotes(text) +
                     " is not K,SCALE,QUANTILE[,EDGE_OFFSET,EDGE_SCALE]");
  }
  SplatRule rule{cli::parseInt(flag, parts[0], 1, 64), cli::parseReal(flag, parts[1], 0.1, 4.0),
                 cli::parseReal(flag, parts[2], 0.0, 1.0)};
  rule.edge_offset = 0;
  rule.edge_scale = 0;
  if (parts.size() == 5) {
    rule.edge_offset = cli::parseReal(flag, parts[3], 0.0, 1.0);
    rule.edge_scale = cli::parseReal(flag, parts[4], 0.0, 4.0);
  }
  return rule;
}

void parseOutlineRule(const std::string& flag, const std::string& text, SplatRule& rule) {
  rule.outline_neighbours = 0;
  if (text == "none") return;
  const std::vector<std::string> parts = commaSeparated(text);
  if (parts.size() != 4) {
    throw cli::Error(flag + ": " + cli::inQuotes(text) + " is not K,GAP,SCALE,SHIFT or none");
  }
  rule.outline_neighbours = cli::parseInt(flag, parts[0], 3, 64);
  rule.outline_gap_degrees = cli::parseReal(flag, parts[1], 30.0, 359.0);
  rule.outline_scale = cli::parseReal(flag, parts[2], 0.0, 4.0);
  rule.outline_shift = cli::parseReal(flag, parts[3], 0.0, 1.0);
}

double parseSparseFactor(const std::string& flag, const std::string& text) {
  const double factor = cli::parseReal(flag, text, 0.0, 10.0);
  if (factor > 0 && factor < 1)
    throw cli::Error(flag + ": " + cli::inQuotes(text) + " is neither 0 nor in 1..10");
  return factor;
}

}  // namespace octopoint::tradeoff
