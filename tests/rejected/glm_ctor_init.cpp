// Compiled by expect_error.cmake: GLM_FORCE_CTOR_INIT makes GLM's vectors non-trivially copyable,
// which apse's plain-data samplers cannot allow; apse must stop with its message.
#define GLM_FORCE_CTOR_INIT
#include <apse/apse.hpp>

int main() { return 0; }
