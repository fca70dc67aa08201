// cdref/oracle/stage.hpp - the stages of the fast exact classification oracle, and what
// oracle::enter (enter.hpp) returns.
#pragma once

namespace cdref::oracle {

// filter: a floating-point evaluation with a derived error bound decided; expansion: the
// second stage, double words with a rigorous bound (certain only where they decide exactly)
// and, for the Section 3.1-3.2 queries, exact floating-point expansions after them; rational:
// exact rational arithmetic (CGAL::Gmpq).
enum class Stage { filter, expansion, rational };

// The book's cast at an exact type, reduced to what a ray tracer takes from it: whether it
// hits, and lambda_enter rounded to nearest double (0 on a miss and from inside).
struct Entry {
  bool hit = false;
  double lambda_enter = 0;
};

}  // namespace cdref::oracle
