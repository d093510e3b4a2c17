# Configures apse at the top level as a user without Catch2, Google Benchmark or stb would:
# -DSOURCE, -DBINARY, -DGENERATOR, -DHIDE (a directory to hide from find_path: where stb was
# found). Succeeds only if the configuration succeeds and says what it skipped.
file(REMOVE_RECURSE ${BINARY})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G ${GENERATOR}
                        -DCMAKE_DISABLE_FIND_PACKAGE_Catch2=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON
                        -DCMAKE_IGNORE_PATH=${HIDE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "configure without the test stack failed:\n${out}${err}")
endif()
foreach(expected "Catch2 (3 or 2) not found" "Google Benchmark not found" "stb_image_write.h not found")
  string(FIND "${out}${err}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "no '${expected}' message:\n${out}${err}")
  endif()
endforeach()
message(STATUS "configured without Catch2, Google Benchmark and stb; skipped parts reported")
