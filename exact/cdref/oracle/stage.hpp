// cdref/oracle/stage.hpp - the stages of the fast exact classification oracle.
#pragma once

namespace cdref::oracle {

// filter: a floating-point evaluation with a derived error bound decided; expansion: exact
// floating-point expansions; rational: exact rational arithmetic (CGAL::Gmpq).
enum class Stage { filter, expansion, rational };

}  // namespace cdref::oracle
