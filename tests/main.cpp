// tests/main.cpp - Catch2 runner. MPFR runs at 128 bits unless a test sets otherwise.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <cdref/float/mpfr.hpp>

int main(int argc, char* argv[]) {
  mpfr::mpreal::set_default_prec(128);
  return Catch::Session().run(argc, argv);
}
