#pragma once
// Which names a model may have. The name becomes C++ identifiers in the generated sources
// (`octopoint::models::NAME`, NAME.h), so every name accepted here must compile wherever the
// sources are compiled: a plain identifier of letters, digits and single underscores between
// them (no name is reserved: no leading underscore, no "__"; and no name ends in '_', which
// leaves such names to the generator), at most kMaxModelNameLength
// characters, not a C++ keyword or alternative token (class, and, ...), not a macro a compiler
// predefines (linux, unix in GNU mode), not the name of a standard C or POSIX header (NAME.h
// would hide it), not ending in "_depth" and digits (NAME_depthD.cpp is model NAME's level source),
// and with at least one lower-case letter (the standard headers' macros, INT8_MAX
// and the like, are all capitals).

#include <cstddef>
#include <string>
#include <string_view>

namespace octopoint::prepare {

inline constexpr std::size_t kMaxModelNameLength = 64;

// Empty when `name` is a valid model name; otherwise why not, as the end of a sentence that
// starts with the quoted name ("'class' is a C++ keyword").
std::string modelNameProblem(std::string_view name);

}  // namespace octopoint::prepare
