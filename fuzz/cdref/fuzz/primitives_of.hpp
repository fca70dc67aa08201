// cdref/fuzz/primitives_of.hpp - a case's columns as the query's two primitives.
//
// with_primitives<T>(q, in, f) builds the pair the query takes from the case's input
// columns (the layout of fuzz/queries.cpp's table and of the case files), converted to T,
// and returns f(a, b, algorithm_3_2): the last argument tells the segment-sphere
// proximity query (Algorithm 3.2) from the segment cast on a sphere (Algorithm 3.1), which
// take the same primitives.
#pragma once

#include <cdref/primitives.hpp>

#include "campaign.hpp"

namespace cdref::fuzz {

template <class T>
Vec3<T> column3(const Inputs& in, int k) {
  return Vec3<T>(T(in[k]), T(in[k + 1]), T(in[k + 2]));
}

template <class T, class F>
decltype(auto) with_primitives(Query q, const Inputs& in, F&& f) {
  switch (q) {
    case Query::sphere_sphere:
      return f(Sphere<T>{column3<T>(in, 0), T(in[3])}, Sphere<T>{column3<T>(in, 4), T(in[7])}, false);
    case Query::segment_sphere_cast:
      return f(Segment<T>{column3<T>(in, 0), column3<T>(in, 3)}, Sphere<T>{column3<T>(in, 6), T(in[9])}, false);
    case Query::ray_sphere_cast:
      return f(Ray<T>{column3<T>(in, 0), column3<T>(in, 3)}, Sphere<T>{column3<T>(in, 6), T(in[9])}, false);
    case Query::segment_sphere:
      return f(Segment<T>{column3<T>(in, 0), column3<T>(in, 3)}, Sphere<T>{column3<T>(in, 6), T(in[9])}, true);
    case Query::box_box:
      return f(Box<T>{column3<T>(in, 0), column3<T>(in, 3)}, Box<T>{column3<T>(in, 6), column3<T>(in, 9)}, false);
    case Query::segment_box_cast:
      return f(Segment<T>{column3<T>(in, 0), column3<T>(in, 3)}, Box<T>{column3<T>(in, 6), column3<T>(in, 9)}, false);
    case Query::ray_box_cast:
      return f(Ray<T>{column3<T>(in, 0), column3<T>(in, 3)}, Box<T>{column3<T>(in, 6), column3<T>(in, 9)}, false);
    case Query::sphere_box:
      break;
  }
  return f(Sphere<T>{column3<T>(in, 0), T(in[3])}, Box<T>{column3<T>(in, 4), column3<T>(in, 7)}, false);
}

}  // namespace cdref::fuzz
