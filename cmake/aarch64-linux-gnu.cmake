# CMake toolchain file: cross-compile for AArch64 Linux with Debian's g++-aarch64-linux-gnu and run
# the executables (tests, Catch2 test discovery) under qemu-user. tools/test.sh uses it:
#   cmake -S . -B build/aarch64 -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake
# GLM and Catch2 2.x are header-only, so the host's copies (/usr/include, found through their
# CMake packages) serve the target too; /usr/include is searched after the cross compiler's own
# system directories (-idirafter), so the host's C library headers never shadow the target's.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /usr/aarch64-linux-gnu)

set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)

# The header-only packages' INTERFACE_INCLUDE_DIRECTORIES is /usr/include. With -idirafter, the
# compiler lists /usr/include among its own search directories, which CMake then treats as
# implicit and does not add again as -isystem (that would put it before the target's libc).
set(CMAKE_CXX_FLAGS_INIT "-idirafter /usr/include")
