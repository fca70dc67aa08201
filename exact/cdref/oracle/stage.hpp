// cdref/oracle/stage.hpp - the stages of the fast exact classification oracle.
#pragma once

namespace cdref::oracle {

// filter: a floating-point evaluation with a derived error bound decided; expansion: the
// second stage, double words with a rigorous bound (certain only where they decide exactly)
// and, for the Section 3.1-3.2 queries, exact floating-point expansions after them; rational:
// exact rational arithmetic (CGAL::Gmpq).
enum class Stage { filter, expansion, rational };

}  // namespace cdref::oracle
