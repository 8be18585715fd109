#include "codegen/model_name.h"

#include <algorithm>
#include <iterator>

namespace octopoint::prepare {
namespace {

// C++20's keywords ([lex.key]) and alternative tokens ([lex.digraph]). The identifiers with a
// special meaning only in some places (final, override, import, module) stay valid names: the
// generated sources use the name where they are plain identifiers (tests/generated_names).
constexpr std::string_view kKeywords[] = {"alignas",       "alignof",     "and",
                                          "and_eq",        "asm",         "auto",
                                          "bitand",        "bitor",       "bool",
                                          "break",         "case",        "catch",
                                          "char",          "char8_t",     "char16_t",
                                          "char32_t",      "class",       "compl",
                                          "concept",       "const",       "consteval",
                                          "constexpr",     "constinit",   "const_cast",
                                          "continue",      "co_await",    "co_return",
                                          "co_yield",      "decltype",    "default",
                                          "delete",        "do",          "double",
                                          "dynamic_cast",  "else",        "enum",
                                          "explicit",      "export",      "extern",
                                          "false",         "float",       "for",
                                          "friend",        "goto",        "if",
                                          "inline",        "int",         "long",
                                          "mutable",       "namespace",   "new",
                                          "noexcept",      "not",         "not_eq",
                                          "nullptr",       "operator",    "or",
                                          "or_eq",         "private",     "protected",
                                          "public",        "register",    "reinterpret_cast",
                                          "requires",      "return",      "short",
                                          "signed",        "sizeof",      "static",
                                          "static_assert", "static_cast", "struct",
                                          "switch",        "template",    "this",
                                          "thread_local",  "throw",       "true",
                                          "try",           "typedef",     "typeid",
                                          "typename",      "union",       "unsigned",
                                          "using",         "virtual",     "void",
                                          "volatile",      "wchar_t",     "while",
                                          "xor",           "xor_eq"};

// Object-like macros in lower case: predefined by GCC and Clang in their GNU modes (CMake's
// default, -std=gnu++20), where a model called linux would be compiled as "1", and the C library's
// (<cerrno>, <cmath>) in an app that includes them beside the model's header.
constexpr std::string_view kPredefinedMacros[] = {"linux", "unix",  "i386",
                                                  "vax",   "errno", "math_errhandling"};

// The preparer writes NAME.h, and apps put its directory on the include path: a model called stdint
// would hide <stdint.h> from everything compiled with it, the generated sources included. These
// are the C standard library's headers, POSIX's and glibc's top-level ones that C++ headers pull
// in.
constexpr std::string_view kHeaderNames[] = {
    "assert",   "complex", "ctype",    "errno",   "fenv",   "float",       "inttypes", "iso646",
    "limits",   "locale",  "math",     "setjmp",  "signal", "stdalign",    "stdarg",   "stdatomic",
    "stdbool",  "stddef",  "stdint",   "stdio",   "stdlib", "stdnoreturn", "string",   "tgmath",
    "threads",  "time",    "uchar",    "wchar",   "wctype", "aio",         "cpio",     "dirent",
    "dlfcn",    "fcntl",   "fmtmsg",   "fnmatch", "ftw",    "glob",        "grp",      "iconv",
    "langinfo", "libgen",  "monetary", "mqueue",  "ndbm",   "netdb",       "nl_types", "poll",
    "pthread",  "pwd",     "regex",    "sched",   "search", "semaphore",   "spawn",    "strings",
    "stropts",  "syslog",  "tar",      "termios", "trace",  "ulimit",      "unistd",   "utime",
    "utmpx",    "wordexp", "features", "alloca",  "endian", "malloc",      "memory",   "link",
    "elf",      "getopt",  "libintl",  "values",  "ctime"};

bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Model m writes its depth-3 level as m_depth3.cpp, which is also the descriptor of a model called
// m_depth3: prepared into one folder, either would overwrite the other's source.
bool endsLikeALevelSource(std::string_view name) {
  constexpr std::string_view kLevelMark = "_depth";
  const std::size_t digits_begin = name.find_last_not_of("0123456789") + 1;
  if (digits_begin == name.size()) return false;
  const std::string_view before_digits = name.substr(0, digits_begin);
  return before_digits.size() > kLevelMark.size() && before_digits.ends_with(kLevelMark);
}

}  // namespace

std::string modelNameProblem(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name.size() > kMaxModelNameLength) {
    return "is " + std::to_string(name.size()) + " characters long, at most " +
           std::to_string(kMaxModelNameLength);
  }
  for (char c : name) {
    if (!isLetter(c) && !isDigit(c) && c != '_') {
      return "has a character other than letters, digits and '_'";
    }
  }
  if (isDigit(name.front())) return "starts with a digit";
  if (name.front() == '_' || name.back() == '_' || name.find("__") != std::string_view::npos) {
    return "has an underscore at its start or end or two in a row (such names are reserved)";
  }
  if (std::find(std::begin(kKeywords), std::end(kKeywords), name) != std::end(kKeywords)) {
    return "is a C++ keyword";
  }
  if (std::find(std::begin(kPredefinedMacros), std::end(kPredefinedMacros), name) !=
      std::end(kPredefinedMacros)) {
    return "is a macro of some compilers or of the C library";
  }
  if (std::find(std::begin(kHeaderNames), std::end(kHeaderNames), name) != std::end(kHeaderNames)) {
    return "is the name of a standard header (" + std::string(name) + ".h would hide <" +
           std::string(name) + ".h>)";
  }
  if (endsLikeALevelSource(name)) {
    return "ends in _depth and a number, the name the preparer gives another model's level source "
           "(" +
           std::string(name) + ".cpp would be that model's)";
  }
  if (std::none_of(name.begin(), name.end(), [](char c) { return c >= 'a' && c <= 'z'; })) {
    return "has no lower-case letter (names in capitals are left to macros)";
  }
  return {};
}

}  // namespace octopoint::prepare
