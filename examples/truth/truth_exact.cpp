// examples/truth/truth_exact.cpp - the exact value itself, beyond its rounding: the book's
// algorithm at an exact number type. At CGAL::Gmpq a value with a square root in it is a
// cdref::Quad, a + b sqrt(d) with a, b, d exact rationals.
#include <cdref/cdref.hpp>
#include <cdref/exact.hpp>
#include <cdref/truth.hpp>
#include <cstdio>
#include <iostream>

int main() {
  using Q = CGAL::Gmpq;
  const cdref::Ray<Q> ray{{Q(0), Q(0), Q(-5)}, {Q(0), Q(0), Q(1)}};
  const cdref::Sphere<Q> ball{{Q(1, 2), Q(0), Q(0)}, Q(1)};
  const auto c = cdref::book::cast(ray, ball);  // Cast<cdref::Quad<CGAL::Gmpq>>
  const cdref::Quad<Q>& l = c.lambda_enter;
  std::cout << "lambda_enter = " << l.a() << " + (" << l.b() << ") sqrt(" << l.d() << ")\n";
  // the same, correctly rounded, from the truth API
  const double rounded = cdref::truth::cast(cdref::Ray<double>{{0, 0, -5}, {0, 0, 1}},
                                            cdref::Sphere<double>{{0.5, 0, 0}, 1}).lambda_enter;
  std::printf("rounded to double: %a (%.17g)\n", rounded, rounded);
  // exact: lambda_enter is 5 - sqrt(3/4); its rounding lies within half an ulp of it
  const bool ok = l.a() == Q(5) && l.b() < Q(0) && l.b() * l.b() * l.d() == Q(3, 4) && cdref::round_double(l) == rounded;
  return ok ? 0 : 1;
}
