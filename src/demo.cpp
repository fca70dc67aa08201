// src/demo.cpp - cdref's built-in demonstration: the chapter's algorithms at float and
// double beside the exact answer (CGAL::Gmpq, square roots kept exactly as a + b sqrt d),
// on a few hard cases, printing where the float versions drift.
#include <cdref/exact/rationals.hpp>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace cdref;
using Q = CGAL::Gmpq;

// Error of a float-type result r against the exact value x, in ulps of r's type at the
// correctly rounded x (an ulp of the smallest normal when x rounds to 0).
template <class F, class S>
double ulp_error(F r, const S& x) {
  if (!std::isfinite(r)) return INFINITY;
  const S diff = S(Q(double(r))) - x;
  const double err = std::fabs(round_double(diff));
  F ref = std::fabs(round_to<F>(x));
  if (ref == F(0)) ref = std::numeric_limits<F>::min();
  const double ulp = double(std::nextafter(ref, std::numeric_limits<F>::infinity()) - ref);
  return err / ulp;
}

struct Row {
  std::string query, name, quantity, fl, db, exact;
  double fl_ulps = 0, db_ulps = 0;
  bool wrong_f = false, wrong_d = false;
};

std::string fmt(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}
std::string fmtg(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%g", x);
  return b;
}
std::string fmtb(bool b) { return b ? "hit" : "miss"; }

Vec3<Q> vq(const Vec3<double>& v) { return Vec3<Q>(Q(v[0]), Q(v[1]), Q(v[2])); }
Vec3<float> vf(const Vec3<double>& v) { return Vec3<float>(float(v[0]), float(v[1]), float(v[2])); }
Vec3<double> float_rounded(const Vec3<double>& v) { return Vec3<double>(double(float(v[0])), double(float(v[1])), double(float(v[2]))); }

bool finite_in_float(std::initializer_list<Vec3<double>> vs, double rho) {
  for (const auto& v : vs)
    if (!vf(v).allFinite()) return false;
  return std::isfinite(float(rho));
}

// Segment s->t against a sphere (c, rho): classification and lambda_enter.
void ray_sphere(std::vector<Row>& rows, const std::string& name, Vec3<double> s, Vec3<double> t, Vec3<double> c,
                double rho) {
  const auto d = book::cast(Segment<double>{s, t}, Sphere<double>{c, rho});
  const auto x = book::cast(Segment<Q>{vq(s), vq(t)}, Sphere<Q>{vq(c), Q(rho)});
  Row hit{"segment-sphere cast", name, "hit", "overflows", fmtb(d.hit), fmtb(x.hit)};
  Row le{"segment-sphere cast", name, "lambda_enter", "-", d.hit ? fmt(d.lambda_enter) : "-",
         x.hit ? fmt(round_double(x.lambda_enter)) : "-"};
  hit.wrong_d = d.hit != x.hit;
  if (d.hit && x.hit) le.db_ulps = ulp_error(d.lambda_enter, x.lambda_enter);
  if (finite_in_float({s, t, c}, rho)) {
    // float runs on its own rounding of the inputs: compare it with the truth for those
    const Vec3<double> sf = float_rounded(s), tf = float_rounded(t), cf = float_rounded(c);
    const double rhof = double(float(rho));
    const auto f = book::cast(Segment<float>{vf(sf), vf(tf)}, Sphere<float>{vf(cf), float(rhof)});
    const auto xf = book::cast(Segment<Q>{vq(sf), vq(tf)}, Sphere<Q>{vq(cf), Q(rhof)});
    hit.fl = fmtb(f.hit);
    hit.wrong_f = f.hit != xf.hit;
    if (f.hit) le.fl = fmt(f.lambda_enter);
    if (f.hit && xf.hit) le.fl_ulps = ulp_error(f.lambda_enter, xf.lambda_enter);
  }
  rows.push_back(hit);
  if (x.hit) rows.push_back(le);
}

void sphere_sphere(std::vector<Row>& rows, const std::string& name, Sphere<double> a, Sphere<double> b) {
  const auto d = book::proximity(a, b);
  const auto x = book::proximity(Sphere<Q>{vq(a.center), Q(a.radius)}, Sphere<Q>{vq(b.center), Q(b.radius)});
  Row r{"sphere-sphere", name, "intersect / distance", "-", fmtb(d.intersect) + " / " + fmt(d.distance),
        fmtb(x.intersect) + " / " + fmt(round_double(x.distance))};
  r.wrong_d = d.intersect != x.intersect;
  r.db_ulps = ulp_error(d.distance, x.distance);
  rows.push_back(r);
}

OrientedBox<Q> obb_q(const OrientedBox<double>& b) {
  return {vq(b.center), vq(b.extent), {vq(b.axis[0]), vq(b.axis[1]), vq(b.axis[2])}};
}
OrientedBox<float> obb_f(const OrientedBox<double>& b) {
  return {vf(b.center), vf(b.extent), {vf(b.axis[0]), vf(b.axis[1]), vf(b.axis[2])}};
}
OrientedBox<double> obb_fd(const OrientedBox<double>& b) {  // the float rounding, in double
  return {float_rounded(b.center), float_rounded(b.extent),
          {float_rounded(b.axis[0]), float_rounded(b.axis[1]), float_rounded(b.axis[2])}};
}
std::string fmts(bool intersect, int axis) { return intersect ? "intersect" : "apart (axis " + std::to_string(axis) + ")"; }

// Two oriented boxes: the book's 15-axis test at float and double (and a patch of it) against
// the solid the inputs define, at Gmpq.
template <class Test>
void obb_obb(std::vector<Row>& rows, const std::string& name, const std::string& what, const OrientedBox<double>& a,
             const OrientedBox<double>& b, Test test) {
  const auto d = test(a, b);
  const auto x = solid::separate(obb_q(a), obb_q(b));
  const auto f = book::separate(obb_f(a), obb_f(b));
  const auto xf = solid::separate(obb_q(obb_fd(a)), obb_q(obb_fd(b)));
  Row r{"obb-obb", name, what, fmts(f.intersect, f.axis), fmts(d.intersect, d.axis), fmts(x.intersect, x.axis)};
  r.wrong_d = d.intersect != x.intersect;
  r.wrong_f = f.intersect != xf.intersect;
  rows.push_back(r);
}

}  // namespace

// printf to std::cout: standard output goes through cdref's checked stream (src/output.hpp).
[[gnu::format(printf, 1, 2)]] static void say(const char* format, ...) {
  char buf[1024];
  va_list args;
  va_start(args, format);
  const int n = std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  if (n > 0) std::cout.write(buf, std::min<std::streamsize>(n, sizeof buf - 1));
}

int run_demo() {
  std::vector<Row> rows;
  const Vec3<double> o(0, 0, 0);
  for (double R : {1e2, 1e4, 1e6, 1e8, 1e12})
    ray_sphere(rows, "through the centre from " + fmtg(R) + " radii", Vec3<double>(-R, 0, 0),
               Vec3<double>(R, 0, 0), o, 1.0);
  const double y_out = 1 + std::ldexp(1.0, -40);
  for (double R : {1e2, 1e4})
    ray_sphere(rows, "passing 2^-40 radii outside, from " + fmtg(R), Vec3<double>(-R, y_out, 0),
               Vec3<double>(R, y_out, 0), o, 1.0);
  const double big = std::ldexp(1.0, 532);
  ray_sphere(rows, "coordinates near 1e160", Vec3<double>(-3 * big, 0, 0), Vec3<double>(3 * big, 0, 0), o, big);
  sphere_sphere(rows, "disjoint by 2.5e-9 at 1e8", Sphere<double>{o, 1e8}, Sphere<double>{Vec3<double>(2e8, 1, 0), 1e8});
  sphere_sphere(rows, "1e160 apart", Sphere<double>{o, big}, Sphere<double>{Vec3<double>(3 * big, 0, 0), big});
  {
    // B turned about x by 2^-20 rad, its lowest point 2^-30 above A's top face
    const double t = std::ldexp(1.0, -20), c = std::cos(t), sn = std::sin(t), g = std::ldexp(1.0, -30);
    const OrientedBox<double> A{o, Vec3<double>(1, 1, 1), {Vec3<double>(1, 0, 0), Vec3<double>(0, 1, 0), Vec3<double>(0, 0, 1)}};
    const OrientedBox<double> B{Vec3<double>(0, 0, 1 + c + sn + g), Vec3<double>(1, 1, 1),
                                {Vec3<double>(1, 0, 0), Vec3<double>(0, c, sn), Vec3<double>(0, -sn, c)}};
    auto book_test = [](const auto& x, const auto& y) { return book::separate(x, y); };
    auto rapid = [](const auto& x, const auto& y) { return book::separate_rapid(x, y); };
    obb_obb(rows, "2^-30 apart, frames 2^-20 rad apart", "separate", A, B, book_test);
    obb_obb(rows, "the same, RAPID's |R| + 1e-6 at double", "separate", A, B, rapid);
  }

  say("cdref: the chapter's algorithms (book versions) at float and double, against the exact answer\n");
  say("(CGAL::Gmpq, square roots kept exactly as a + b sqrt d, correctly rounded for display).\n");
  say("Errors are in ulps of the type's own precision; float is judged on its own rounding of the inputs.\n\n");
  say("Oriented boxes: the book's 15-axis test against the solid the rounded axes span (cdref::solid).\n\n");
  say("%-20s %-40s %-21s %-26s %-26s %-26s %s\n", "query", "case", "quantity", "float", "double",
              "exact", "drift");
  int wrong = 0;
  for (const Row& r : rows) {
    std::string drift;
    if (r.wrong_d) drift += "DOUBLE MISCLASSIFIES  ";
    if (r.wrong_f) drift += "FLOAT MISCLASSIFIES  ";
    if (r.db_ulps > 0.5) drift += "double " + fmt(std::round(r.db_ulps)) + " ulps  ";
    if (r.fl_ulps > 0.5) drift += "float " + fmt(std::round(r.fl_ulps)) + " ulps";
    wrong += r.wrong_d + r.wrong_f;
    say("%-20s %-40s %-21s %-26s %-26s %-26s %s\n", r.query.c_str(), r.name.c_str(), r.quantity.c_str(),
                r.fl.c_str(), r.db.c_str(), r.exact.c_str(), drift.c_str());
  }
  say("\n%d misclassifications in %zu rows.\n", wrong, rows.size());
  return 0;
}
