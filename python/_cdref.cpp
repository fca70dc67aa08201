// python/_cdref.cpp - the compiled half of `import cdref`: the query descriptors, the exact
// answers over numpy arrays of cases (the GIL released, rows split over threads), and the case
// generator. The Python half (python/cdref/__init__.py) turns each descriptor into a function
// named after its query, with named arguments, and scores and validates on top of these.
//
// Everything goes through the query descriptors (cdref/fuzz/campaign.hpp): a query added to
// cdref is a function of this module without a line here.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cdref/error.hpp>
#include <cdref/fuzz/campaign.hpp>
#include <cmath>
#include <exception>
#include <string>
#include <thread>
#include <vector>

namespace py = pybind11;
using namespace cdref::fuzz;

namespace {

py::dict describe(const QueryInfo& qi) {
  py::dict d;
  d["name"] = qi.name;
  d["classification"] = qi.cls_name;
  d["describe"] = qi.describe;
  d["answer_help"] = qi.answer_help;
  d["inputs"] = qi.inputs;
  py::list outs;
  for (const Output& o : qi.outputs) {
    py::dict g;
    g["name"] = o.name;
    g["width"] = o.width;
    g["when"] = o.when == Output::always ? "always" : (o.when == Output::on_hit ? "on_hit" : "on_miss");
    g["label"] = o.label;
    outs.append(g);
  }
  d["outputs"] = outs;
  py::list fams;
  for (const Family& f : qi.families) {
    py::dict g;
    g["name"] = f.name;
    g["describe"] = f.describe;
    g["scales"] = f.scales;
    fams.append(g);
  }
  d["families"] = fams;
  d["mesh_level"] = qi.mesh_level;
  return d;
}

// The exact answers for the rows of `inputs` (N x the query's input columns, float64): per
// row a status (0 answered, 1 refused: outside the query's domain or, at precision 24, beyond
// float's range) and its message, the classification, and each output group's values
// correctly rounded to the precision (24: float32 arrays; 53: float64).
py::dict answer(const std::string& query, py::array_t<double, py::array::c_style | py::array::forcecast> inputs,
                int precision, int threads, bool exact) {
  const Query q = query_by_name(query);
  const QueryInfo& qi = info(q);
  if (precision != 24 && precision != 53) throw std::invalid_argument("precision must be 24 (float) or 53 (double)");
  const std::size_t ncols = qi.inputs.size();
  if (inputs.ndim() != 2 || std::size_t(inputs.shape(1)) != ncols)
    throw std::invalid_argument(query + " takes " + std::to_string(ncols) + " input columns per row");
  if (threads < 1 || threads > 1024) throw std::invalid_argument("threads must be 1 to 1024");
  const std::size_t n = inputs.shape(0);
  std::size_t nvalues = 0;
  for (const Output& o : qi.outputs) nvalues += o.width;
  std::vector<std::uint8_t> status(n, 0), cls(n, 0);
  std::vector<double> values(n * nvalues, 0.0);
  std::vector<std::string> errors(n);
  const double* in = inputs.data();
  {
    py::gil_scoped_release release;
    const auto work = [&](std::size_t lo, std::size_t hi) {
      Inputs row{};
      for (std::size_t k = lo; k < hi; ++k) {
        for (std::size_t c = 0; c < ncols; ++c) row[c] = in[k * ncols + c];
        try {
          if (precision == 24) {
            const Inputs f = float_inputs(q, row);
            for (std::size_t c = 0; c < ncols; ++c)
              if (std::isfinite(row[c]) && !std::isfinite(f[c]))
                throw cdref::invalid_input(qi.inputs[c] + " is beyond the range of float (" + hexfloat(row[c]) + ")");
            row = f;
          }
          const Answer a = exact ? qi.truth(row, precision) : qi.oracle_truth(row, precision, nullptr);
          cls[k] = a.cls;
          for (std::size_t v = 0; v < nvalues; ++v) values[k * nvalues + v] = double(a.v[v]);
        } catch (const cdref::invalid_input& e) {
          status[k] = 1;
          errors[k] = e.what();
        } catch (const std::exception& e) {
          status[k] = 2;
          errors[k] = std::string("internal error: ") + e.what();
        }
      }
    };
    const std::size_t t = std::min<std::size_t>(std::size_t(threads), std::max<std::size_t>(n / 256, 1));
    if (t <= 1) {
      work(0, n);
    } else {
      std::vector<std::thread> pool;
      for (std::size_t i = 0; i < t; ++i) pool.emplace_back(work, n * i / t, n * (i + 1) / t);
      for (auto& th : pool) th.join();
    }
  }
  py::dict out;
  py::array_t<std::uint8_t> st(n);
  std::copy(status.begin(), status.end(), st.mutable_data());
  out["status"] = st;
  py::array_t<bool> c(n);
  for (std::size_t k = 0; k < n; ++k) c.mutable_data()[k] = cls[k] != 0;
  out[qi.cls_name] = c;
  std::size_t first = 0;
  for (const Output& o : qi.outputs) {
    const auto fill = [&](auto* dst) {
      for (std::size_t k = 0; k < n; ++k)
        for (int w = 0; w < o.width; ++w) dst[k * o.width + w] = values[k * nvalues + first + w];
    };
    if (o.label) {  // an index or a flag
      py::array_t<std::int64_t> a(o.width == 1 ? std::vector<py::ssize_t>{py::ssize_t(n)}
                                               : std::vector<py::ssize_t>{py::ssize_t(n), 3});
      auto* d = a.mutable_data();
      for (std::size_t k = 0; k < n; ++k)
        for (int w = 0; w < o.width; ++w) d[k * o.width + w] = std::int64_t(values[k * nvalues + first + w]);
      out[py::str(o.name)] = a;
    } else if (precision == 24) {
      py::array_t<float> a(o.width == 1 ? std::vector<py::ssize_t>{py::ssize_t(n)}
                                        : std::vector<py::ssize_t>{py::ssize_t(n), 3});
      fill(a.mutable_data());
      out[py::str(o.name)] = a;
    } else {
      py::array_t<double> a(o.width == 1 ? std::vector<py::ssize_t>{py::ssize_t(n)}
                                         : std::vector<py::ssize_t>{py::ssize_t(n), 3});
      fill(a.mutable_data());
      out[py::str(o.name)] = a;
    }
    first += o.width;
  }
  py::dict errs;
  for (std::size_t k = 0; k < n; ++k)
    if (status[k]) errs[py::int_(k)] = errors[k];
  out["errors"] = errs;
  return out;
}

// Cases first .. first + n - 1 of cell (query, family, scale) under `seed`: N x the query's
// input columns, each row the pure function of its index that `cdref cases` writes.
py::array_t<double> cases(const std::string& query, const std::string& family, int scale, std::uint64_t n,
                          std::uint64_t seed, std::uint64_t first) {
  const Query q = query_by_name(query);
  const Family& f = family_by_name(q, family);
  bool known = false;
  for (int s : f.scales) known = known || s == scale;
  if (!known) {
    std::string list;
    for (int s : f.scales) list += (list.empty() ? "" : ", ") + std::to_string(s);
    throw std::invalid_argument("family " + family + " of " + query + " has no scale " + std::to_string(scale) +
                                " (its scales: " + list + ")");
  }
  if (n > (std::uint64_t(1) << 28)) throw std::invalid_argument("n must be at most 2^28 cases a call");
  const std::size_t ncols = info(q).inputs.size();
  py::array_t<double> out({py::ssize_t(n), py::ssize_t(ncols)});
  double* d = out.mutable_data();
  {
    py::gil_scoped_release release;
    const std::uint64_t key = cell_key(seed, q, f, scale);
    for (std::uint64_t i = 0; i < n; ++i) {
      const Inputs in = make_case_of(key, f, scale, first + i);
      for (std::size_t c = 0; c < ncols; ++c) d[i * ncols + c] = in[c];
    }
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(_cdref, m) {
  m.doc() = "cdref's compiled core: exact answers for the queries of Chapter 3 over numpy arrays";
  m.attr("__version__") = CDREF_VERSION;
  m.def("queries", [] {
    py::list l;
    for (const Query q : all_queries()) l.append(describe(info(q)));
    return l;
  }, "The query descriptors: name, input columns, output groups, families.");
  m.def("answer", &answer, py::arg("query"), py::arg("inputs"), py::arg("precision") = 53, py::arg("threads") = 1,
        py::arg("exact") = false,
        "Exact answers for N rows of a query's input columns, every value correctly rounded.");
  m.def("cases", &cases, py::arg("query"), py::arg("family"), py::arg("scale"), py::arg("n"), py::arg("seed") = 1,
        py::arg("first") = 0, "Cases of one (query, family, scale) cell as rows of its input columns.");
  py::register_exception<cdref::invalid_input>(m, "InvalidInput", PyExc_ValueError);
}
