// tests/gmp_pool.cpp - installs GMP's block cache (cdref/exact/gmp_pool.hpp) for the test
// runner. The cache's functions are inline; the test objects are compiled without
// optimisation (tests/CMakeLists.txt), and at -O0 the cache's own calls took a quarter of the
// exact tests' time (`perf` on the oracle's all-outputs test). This file is a library of its
// own, compiled with optimisation and linked before the test objects, so its copies of the
// cache's functions are the ones the linker keeps.
#include <cdref/exact/gmp_pool.hpp>

void cdref_tests_use_gmp_pool() { cdref::exact::use_gmp_pool(); }
