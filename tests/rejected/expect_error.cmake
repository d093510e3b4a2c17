# Compiles -DSOURCE with -DCXX and the flags -DFLAGS (a list; -DINCLUDE: apse's include/) and
# succeeds only if the compilation fails with apse's message -DEXPECT, not some other error.
execute_process(COMMAND ${CXX} ${FLAGS} -fsyntax-only -I${INCLUDE} ${SOURCE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "compiling ${SOURCE} succeeded; apse's check did not fire")
endif()
string(FIND "${out}${err}" "${EXPECT}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${SOURCE} failed without apse's message \"${EXPECT}\":\n${out}${err}")
endif()
message(STATUS "${SOURCE} rejected with apse's message")
