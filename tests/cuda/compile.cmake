# Compiles and links a CUDA translation unit with nvcc: -DNVCC, -DSOURCE, -DINCLUDES (list),
# -DOUTPUT, optionally -DDEFINES (list of NAME=VALUE). No GPU is needed: the kernel is compiled
# for a real architecture and linked, not run. The device front end optimises at -O1
# (-Xcicc -O1): this proves that every call compiles, assembles and links as device code, which
# does not depend on the optimisation level, in ~45 s per type instead of ~4 minutes (at the
# default -O3 cicc inlines every kernel into a 25 000-line function that ptxas takes minutes over).
# The GPU runtime test and the throughput benchmark, which run, are built at full optimisation.
set(include_flags)
foreach(dir IN LISTS INCLUDES)
  if(dir)
    list(APPEND include_flags -I${dir})
  endif()
endforeach()
set(define_flags)
foreach(def IN LISTS DEFINES)
  if(def)
    list(APPEND define_flags -D${def})
  endif()
endforeach()
execute_process(COMMAND ${NVCC} -std=c++17 -O2 -Xcicc -O1 -arch=sm_75
                        -Werror all-warnings -Xcompiler -Wall,-Wextra
                        ${include_flags} ${define_flags} ${SOURCE} -o ${OUTPUT}
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "nvcc failed: ${rc}")
endif()
message(STATUS "nvcc compiled and linked ${OUTPUT}")
