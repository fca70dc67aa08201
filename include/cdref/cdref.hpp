// cdref/cdref.hpp - the generic core: primitives, number traits and every algorithm of
// Sections 3.1-3.2 as the chapter writes it (namespace cdref::book), for any number type
// that has number_traits. Include <cdref/exact.hpp> for the exact CGAL types and
// <cdref/float/mpfr.hpp> for MPFR.
#pragma once

#include "book/box_box.hpp"
#include "book/ray_box.hpp"
#include "book/ray_sphere.hpp"
#include "book/segment_sphere.hpp"
#include "book/sphere_box.hpp"
#include "book/sphere_sphere.hpp"
#include "error.hpp"
#include "number_traits.hpp"
#include "primitives.hpp"
#include "results.hpp"
#include "vec.hpp"
