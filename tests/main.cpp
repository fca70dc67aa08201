// tests/main.cpp - Catch2 runner. MPFR runs at 128 bits unless a test sets otherwise.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <cdref/float/mpfr.hpp>

void cdref_tests_use_gmp_pool();  // gmp_pool.cpp

int main(int argc, char* argv[]) {
  cdref_tests_use_gmp_pool();  // GMP's small blocks cached per thread (cdref/exact/gmp_pool.hpp)
  mpfr::mpreal::set_default_prec(128);
  return Catch::Session().run(argc, argv);
}
