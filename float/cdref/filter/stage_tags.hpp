// cdref/filter/stage_tags.hpp - the tags that name a formulation to the exact classification
// oracle's stages (exact/cdref/oracle/stages.hpp runs them).
// Each of the sphere and box queries' stage functions (filter, expansion, double_word,
// rational, and the sign tests before the filter) takes one as its last argument: `plain`, the
// query's own algorithm (defaulted, so a direct call names none), or `alg32`, Algorithm 3.2's
// formulation of segment-sphere. The runner passes the tag, so that argument-dependent lookup
// finds each query's functions in this namespace from that query's own file: the runner is
// written once and no file has to include every query's stages before it.
#pragma once

namespace cdref::oracle::staged {

struct plain {};  // a query's own formulation
struct alg32 {};  // book::intersect(Segment, Sphere), Algorithm 3.2 (the cast's hit decides it too)

}  // namespace cdref::oracle::staged
