// Precompiled for the test program (CMakeLists.txt): the library's set and GoogleTest.
#pragma GCC system_header
#include <gtest/gtest.h>

#include "library.hpp"
