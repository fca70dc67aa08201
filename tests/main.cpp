// tests/main.cpp - Catch2 runner. MPFR runs at 128 bits unless a test sets otherwise.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <cdref/float/mpfr.hpp>
#include <cdref/exact/gmp_pool.hpp>

int main(int argc, char* argv[]) {
  cdref::exact::use_gmp_pool();  // GMP's small blocks cached per thread (gmp_pool.hpp)
  mpfr::mpreal::set_default_prec(128);
  return Catch::Session().run(argc, argv);
}
