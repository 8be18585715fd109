# The page built without a model: web/index.html with its body marked `without-model`, which
# web/octopoint.css reads to leave the embedded model and the styles out of the help.
# usage: cmake -P without_model_page.cmake IN.html OUT.html
# (cmake -P puts its own arguments first: the script's two are the last two.)
math(EXPR in_index "${CMAKE_ARGC} - 2")
math(EXPR out_index "${CMAKE_ARGC} - 1")
set(in "${CMAKE_ARGV${in_index}}")
set(out "${CMAKE_ARGV${out_index}}")
file(READ "${in}" html)
string(FIND "${html}" "<body>" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${in}: no <body> to mark")
endif()
string(REPLACE "<body>" "<body class=\"without-model\">" html "${html}")
file(WRITE "${out}" "${html}")
