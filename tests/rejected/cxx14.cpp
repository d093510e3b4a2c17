// Compiled with -std=c++14 by expect_error.cmake: apse/config.hpp must stop it with its #error.
#include <apse/config.hpp>

int main() { return 0; }
