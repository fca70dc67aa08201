// cdref/oracle/classify.hpp - the fast exact classification oracle for sphere-sphere, the
// sphere casts, segment-sphere, box-box, the box casts and sphere-box at double inputs, all of
// them: each query's stages and its classify() are in its own file (sphere_sphere.hpp,
// sphere_casts.hpp, box_box.hpp, box_casts.hpp, sphere_box.hpp), stages.hpp runs them in order
// (the filter, the double words or the expansions, then the rationals) and expansions.hpp says
// what they share and how each is exact. Code that needs one query includes that query's file.
#pragma once

#include <cdref/oracle/box_box.hpp>
#include <cdref/oracle/box_casts.hpp>
#include <cdref/oracle/sphere_box.hpp>
#include <cdref/oracle/sphere_casts.hpp>
#include <cdref/oracle/sphere_sphere.hpp>
