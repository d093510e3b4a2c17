// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

// Catch2, version 3 or 2, whichever the build found (tests/CMakeLists.txt defines
// APSE_CATCH2_V3 for version 3): the test macros, template test cases and Approx.
#if defined(APSE_CATCH2_V3)
#include <catch2/catch_approx.hpp>
#include <catch2/catch_template_test_macros.hpp>
#include <catch2/catch_test_macros.hpp>
using Catch::Approx;
#else
#include <catch2/catch.hpp>
#endif
