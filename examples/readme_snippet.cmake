# Checks that README.md contains, word for word, the code between the "// [readme-begin]" and
# "// [readme-end]" lines of SOURCE (so the README's example is the compiled one). -DREADME, -DSOURCE.
file(READ ${SOURCE} source)
string(FIND "${source}" "// [readme-begin]\n" begin)
string(FIND "${source}" "// [readme-end]" end)
if(begin EQUAL -1 OR end EQUAL -1)
  message(FATAL_ERROR "${SOURCE}: no // [readme-begin] ... // [readme-end] region")
endif()
math(EXPR begin "${begin} + 18")  # past the marker line
math(EXPR length "${end} - ${begin}")
string(SUBSTRING "${source}" ${begin} ${length} snippet)
file(READ ${README} readme)
string(FIND "${readme}" "${snippet}" found)
if(found EQUAL -1)
  message(FATAL_ERROR "README.md does not contain the example of ${SOURCE} (between its readme markers) "
                      "word for word: copy it into the README's \"Integrating into a renderer\" section")
endif()
message(STATUS "README.md contains the example of ${SOURCE}")
