// cdref/filters/stage_tags.hpp - the tag that marks a filter as one query's own formulation to the
// exact classification oracle's stages (exact/cdref/oracle/stages.hpp runs them).
// The filters of sphere-box and the box casts here, and each of those queries' later stages in the
// oracle (expansion, double_word, rational, and the sign tests before the filter), take a tag as
// their last argument: `plain`, the query's own algorithm (defaulted, so a direct call names none).
// The runner passes the oracle's tag, which derives from this one, so that argument-dependent
// lookup finds each query's functions in both namespaces from that query's own files: the runner
// is written once and no file has to include every query's stages before it.
#pragma once

namespace cdref::filters::staged {

struct plain {};  // a query's own formulation

}  // namespace cdref::filters::staged
