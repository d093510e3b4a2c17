# Compiles and links a CUDA translation unit with nvcc: -DNVCC, -DSOURCE, -DINCLUDES (list),
# -DOUTPUT, optionally -DDEFINES (list of NAME=VALUE). No GPU is needed: the kernel is compiled
# for a real architecture and linked, not run.
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
execute_process(COMMAND ${NVCC} -std=c++17 -O2 -arch=sm_75
                        -Werror all-warnings -Xcompiler -Wall,-Wextra
                        ${include_flags} ${define_flags} ${SOURCE} -o ${OUTPUT}
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "nvcc failed: ${rc}")
endif()
message(STATUS "nvcc compiled and linked ${OUTPUT}")
