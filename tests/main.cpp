// tests/main.cpp - what every test process sets up before its first test: GMP's block cache
// and MPFR at 128 bits (unless a test sets otherwise). Catch2's runner itself is the catch2
// package's prebuilt one (Catch2::Catch2WithMain); this listener runs when the run starts.
#define CATCH_CONFIG_EXTERNAL_INTERFACES  // Catch2 v2: the listener base class
#include <catch2/catch.hpp>
#include <cdref/float/mpfr.hpp>

void cdref_tests_use_gmp_pool();  // gmp_pool.cpp

namespace {

/// Installs the set-up at the start of the run, before any test case.
struct Setup : Catch::TestEventListenerBase {
  using TestEventListenerBase::TestEventListenerBase;
  void testRunStarting(Catch::TestRunInfo const& info) override {
    cdref_tests_use_gmp_pool();  // GMP's small blocks cached per thread (cdref/exact/gmp_pool.hpp)
    mpfr::mpreal::set_default_prec(128);
    TestEventListenerBase::testRunStarting(info);
  }
};

}  // namespace

CATCH_REGISTER_LISTENER(Setup)
