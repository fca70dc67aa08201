// bench/bench_classify.cpp - the fast exact classification oracle against the book at double.
// Per query: book::hit / book::intersect at double and oracle::classify on 1024 pre-generated
// cases of the uniform family (cycled), and the expansion stage alone on the near-tangent /
// near-touching / grazing families at their hardest scale (2^-52), where the filter cannot
// decide. Quote ratios taken in one run (medians of --benchmark_repetitions=3); Debian's
// libbenchmark is a debug build (its own per-iteration overhead is in every figure).
#include <benchmark/benchmark.h>

#include <cdref/fuzz/campaign.hpp>
#include <cdref/fuzz/primitives_of.hpp>
#include <cdref/oracle/classify.hpp>
#include <string>
#include <vector>

using namespace cdref;
using namespace cdref::fuzz;
namespace staged = cdref::oracle::staged;

namespace {

template <class A, class B>
bool book_decision(const A& a, const B& b, bool alg32) {
  if constexpr (std::is_same_v<A, Segment<double>> || std::is_same_v<A, Ray<double>>) {
    if constexpr (std::is_same_v<A, Segment<double>> && std::is_same_v<B, Sphere<double>>)
      if (alg32) return book::intersect(a, b);
    return book::hit(a, b);
  } else {
    return book::intersect(a, b);
  }
}
template <class A, class B>
bool oracle_decision(const A& a, const B& b, bool alg32) {
  if constexpr (std::is_same_v<A, Segment<double>> && std::is_same_v<B, Sphere<double>>)
    if (alg32) return oracle::classify_segment_sphere(a, b);
  return oracle::classify(a, b);
}

template <class A, class B>
int expansion(const A& a, const B& b, bool alg32) {
  if constexpr (std::is_same_v<A, Segment<double>> && std::is_same_v<B, Sphere<double>>)
    if (alg32) return staged::at_stage(oracle::Stage::expansion, a, b, staged::alg32{});
  return staged::at_stage(oracle::Stage::expansion, a, b);
}

// Typed cases, so that the loop measures the query and not the column unpacking.
template <class A, class B>
struct Cases {
  std::vector<A> a;
  std::vector<B> b;
  bool alg32 = false;
};

template <class A, class B>
Cases<A, B> make(Query q, const char* family, int scale) {
  Cases<A, B> c;
  const Family& f = family_by_name(q, family);
  for (std::uint64_t i = 0; i < 1024; ++i) {
    const Inputs in = make_case(1, q, f, scale, i);
    with_primitives<double>(q, in, [&](const auto& a, const auto& b, bool alg32) {
      if constexpr (std::is_same_v<std::decay_t<decltype(a)>, A> && std::is_same_v<std::decay_t<decltype(b)>, B>) {
        c.a.push_back(a);
        c.b.push_back(b);
        c.alg32 = alg32;
      }
      return 0;
    });
  }
  return c;
}

enum class What { book, oracle, expansion };

template <class A, class B>
void bench(benchmark::State& st, Query q, const char* family, int scale, What what) {
  const Cases<A, B> c = make<A, B>(q, family, scale);
  std::size_t k = 0;
  for (auto _ : st) {
    const std::size_t i = k++ & 1023;
    int r;
    if (what == What::book)
      r = book_decision(c.a[i], c.b[i], c.alg32);
    else if (what == What::oracle)
      r = oracle_decision(c.a[i], c.b[i], c.alg32);
    else
      r = expansion(c.a[i], c.b[i], c.alg32);
    benchmark::DoNotOptimize(r);
  }
  st.SetItemsProcessed(st.iterations());
}

using SS = Sphere<double>;
using SB = Box<double>;
using SG = Segment<double>;
using RY = Ray<double>;

template <class A, class B>
void reg(const std::string& name, Query q, const char* hard) {
  benchmark::RegisterBenchmark((name + "/book/uniform").c_str(), bench<A, B>, q, "uniform", 0, What::book);
  benchmark::RegisterBenchmark((name + "/oracle/uniform").c_str(), bench<A, B>, q, "uniform", 0, What::oracle);
  benchmark::RegisterBenchmark((name + "/book/" + hard + "-52").c_str(), bench<A, B>, q, hard, 52, What::book);
  benchmark::RegisterBenchmark((name + "/oracle/" + hard + "-52").c_str(), bench<A, B>, q, hard, 52, What::oracle);
  benchmark::RegisterBenchmark((name + "/expansion/" + hard + "-52").c_str(), bench<A, B>, q, hard, 52,
                               What::expansion);
}

}  // namespace

int main(int argc, char** argv) {
  reg<SS, SS>("sphere-sphere", Query::sphere_sphere, "near-touching");
  reg<SG, SS>("segment-sphere-cast", Query::segment_sphere_cast, "near-tangent");
  reg<RY, SS>("ray-sphere-cast", Query::ray_sphere_cast, "near-tangent");
  reg<SG, SS>("segment-sphere", Query::segment_sphere, "near-tangent");
  reg<SB, SB>("box-box", Query::box_box, "near-touching");
  reg<SG, SB>("segment-box-cast", Query::segment_box_cast, "grazing");
  reg<RY, SB>("ray-box-cast", Query::ray_box_cast, "grazing");
  reg<SS, SB>("sphere-box", Query::sphere_box, "near-touching");
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
