/// \file
/// cdref/cdref.hpp - the generic core: primitives, number traits and every algorithm of
/// Sections 3.1-3.4 as the chapter writes it (namespace cdref::book), the oriented box as the
/// solid its inputs define (namespace cdref::solid), for any number type that has
/// number_traits. Include <cdref/exact.hpp> for the exact CGAL types and
/// <cdref/float/mpfr.hpp> for MPFR.
#pragma once

#include "book/box_box.hpp"
#include "book/obb.hpp"
#include "book/obb_obb.hpp"
#include "book/ray_box.hpp"
#include "book/ray_sphere.hpp"
#include "book/segment_box.hpp"
#include "book/segment_sphere.hpp"
#include "book/separating_axes.hpp"
#include "book/sphere_box.hpp"
#include "book/sphere_sphere.hpp"
#include "book/point_triangle.hpp"
#include "book/sphere_triangle.hpp"
#include "book/ray_triangle.hpp"
#include "book/triangle_triangle.hpp"
#include "book/polygon.hpp"
#include "book/polygon_obb.hpp"
#include "book/triangle_box.hpp"
#include "error.hpp"
#include "fan.hpp"
#include "fields.hpp"
#include "number_traits.hpp"
#include "primitives.hpp"
#include "results.hpp"
#include "solid/obb.hpp"
#include "vec.hpp"
