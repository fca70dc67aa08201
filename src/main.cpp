// src/main.cpp - the cdref command line.
#include <cstdio>
#include <exception>

int run_demo();

int main() {
  try {
    return run_demo();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cdref: %s\n", e.what());
    return 1;
  }
}
