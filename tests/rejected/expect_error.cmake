# Compiles -DSOURCE with -DCXX in C++14 mode (-DINCLUDE: apse's include/) and succeeds only if the
# compilation fails with apse's "requires C++17" #error, not some other error.
execute_process(COMMAND ${CXX} -std=c++14 -fsyntax-only -I${INCLUDE} ${SOURCE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "compiling apse as C++14 succeeded; config.hpp's #error did not fire")
endif()
string(FIND "${out}${err}" "apse requires C++17 or later" at)
if(at EQUAL -1)
  message(FATAL_ERROR "C++14 compilation failed without apse's message:\n${out}${err}")
endif()
message(STATUS "C++14 rejected with apse's message")
