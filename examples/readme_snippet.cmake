# Checks that the Markdown page DOC contains, word for word, the code between the
# "// [readme-begin]" and "// [readme-end]" lines of SOURCE, so that the code a page shows is the
# code that is compiled and run as a test.
#   cmake -DDOC=<page.md> -DSOURCE=<file.cpp> -P readme_snippet.cmake
if(NOT DEFINED DOC OR NOT DEFINED SOURCE)
  message(FATAL_ERROR "usage: cmake -DDOC=<page.md> -DSOURCE=<file.cpp> -P readme_snippet.cmake")
endif()
file(READ ${SOURCE} source)
string(FIND "${source}" "// [readme-begin]\n" begin)
string(FIND "${source}" "// [readme-end]" end)
if(begin EQUAL -1 OR end EQUAL -1)
  message(FATAL_ERROR "${SOURCE}: no // [readme-begin] ... // [readme-end] region")
endif()
math(EXPR begin "${begin} + 18")  # past the marker line
math(EXPR length "${end} - ${begin}")
string(SUBSTRING "${source}" ${begin} ${length} snippet)
file(READ ${DOC} doc)
string(FIND "${doc}" "${snippet}" found)
if(found EQUAL -1)
  message(FATAL_ERROR "${DOC} does not contain the example of ${SOURCE} (between its readme markers) "
                      "word for word: copy that region into it")
endif()
message(STATUS "${DOC} contains the example of ${SOURCE}")
