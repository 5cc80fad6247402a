// viscor._viscor: the compiled part of the Python module (docs/python.md).
//   cor       one CoR at a working precision (solve_impact, optionally certify), as
//             the JSON object of `viscor cor --json` (a dict of decimal strings)
//   exact, approx, scale, calibrate, dem, physical_cor
//             the one-shot jobs (command_bindings.cpp)
//   table, scene, solve_points
//             the table, scene and point-batch jobs
//   evaluate  accuracy-driven e over arrays of points in double, on worker threads
//             without the GIL (scenes/evaluate.hpp, optionally a surrogate first)
//   surrogate a CoR surrogate file, evaluated in double
// viscor's exceptions become the Python exceptions created here (ValueError
// subclasses for bad input), with the library's messages.
#include <viscor/certify/extern_templates.hpp>  // first: the solvers are compiled once, in libviscor
#include <viscor/core/field_names.hpp>

#include "python_objects.hpp"

#include <viscor/jobs/cor_job.hpp>
#include <viscor/jobs/cor_render.hpp>
#include <viscor/jobs/point_batch.hpp>
#include <viscor/jobs/scene_job.hpp>
#include <viscor/jobs/netcdf_file.hpp>
#include <viscor/jobs/table_dataset.hpp>
#include <viscor/jobs/table_estimate.hpp>
#include <viscor/jobs/table_estimate_render.hpp>
#include <viscor/jobs/table_jobs.hpp>
#include <viscor/jobs/unit_checks.hpp>
#include <viscor/jobs/data_directory.hpp>
#include <viscor/jobs/parallel_for.hpp>
#include <viscor/jobs/surrogate_files.hpp>
#include <viscor/jobs/surrogate_export.hpp>

#include <viscor/core/precision.hpp>
#include <viscor/core/text_fields.hpp>
#include <viscor/impact/solve_impact.hpp>
#include <viscor/scenes/error_map.hpp>
#include <viscor/scenes/evaluate.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/surrogate/surrogate_source.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>
#include <variant>
#include <vector>

namespace py = pybind11;

namespace viscor::python {
namespace {

using json = jobs::json;

// ---- exceptions ----

struct python_exceptions {
  PyObject* error = nullptr;                  // viscor.Error: every error of the library
  PyObject* invalid_parameter = nullptr;      // viscor.InvalidParameter(Error, ValueError)
  PyObject* precision_unavailable = nullptr;  // (InvalidParameter)
  PyObject* parse_error = nullptr;            // (InvalidParameter)
  PyObject* convergence_error = nullptr;      // (Error, RuntimeError)
  PyObject* certification_error = nullptr;    // (Error, RuntimeError)
};
python_exceptions exceptions;

PyObject* new_exception(py::module_& m, const char* name, std::initializer_list<PyObject*> bases, const char* doc) {
  py::tuple base_tuple(bases.size());
  std::size_t i = 0;
  for (PyObject* b : bases) base_tuple[i++] = py::reinterpret_borrow<py::object>(b);
  const std::string qualified = std::string("viscor.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base_tuple.ptr(), nullptr);
  if (!type) throw py::error_already_set();
  m.add_object(name, py::reinterpret_borrow<py::object>(type));
  return type;
}

void register_exceptions(py::module_& m) {
  exceptions.error = new_exception(m, "Error", {PyExc_Exception}, "Base class of every viscor error.");
  exceptions.invalid_parameter = new_exception(m, "InvalidParameter", {exceptions.error, PyExc_ValueError},
                                               "Bad input: the message names the offending value.");
  exceptions.precision_unavailable = new_exception(m, "PrecisionUnavailable", {exceptions.invalid_parameter},
                                                   "A precision (digits, tolerance) this build cannot provide.");
  exceptions.parse_error =
      new_exception(m, "ParseError", {exceptions.invalid_parameter}, "A file or text that cannot be read.");
  exceptions.convergence_error = new_exception(m, "ConvergenceError", {exceptions.error, PyExc_RuntimeError},
                                               "A computation that did not converge.");
  exceptions.certification_error = new_exception(m, "CertificationError", {exceptions.error, PyExc_RuntimeError},
                                                 "Digits or a bound that could not be certified.");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const precision_unavailable& e) {
      PyErr_SetString(exceptions.precision_unavailable, e.what());
    } catch (const parse_error& e) {
      PyErr_SetString(exceptions.parse_error, e.what());
    } catch (const invalid_parameter& e) {
      PyErr_SetString(exceptions.invalid_parameter, e.what());
    } catch (const convergence_error& e) {
      PyErr_SetString(exceptions.convergence_error, e.what());
    } catch (const certification_error& e) {
      PyErr_SetString(exceptions.certification_error, e.what());
    } catch (const error& e) {
      PyErr_SetString(exceptions.error, e.what());
    }
  });
}

// ---- inputs ----

using jobs::resolve_law;

// A decimal, or p/q (a fraction whose decimal expansion does not end: p / q correctly
// rounded when p and q are exact in Real).
template <class Real>
Real parse_value(const std::string& text, const std::string& name) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return parse_real<Real>(text, name);
  const Real p = parse_real<Real>(text.substr(0, slash), name), q = parse_real<Real>(text.substr(slash + 1), name);
  if (q == 0) throw invalid_parameter("parameter " + name + " = " + text + " divides by zero");
  return Real(p / q);
}

// ---- cor ----

struct cor_request {
  std::string name, alpha, beta, gamma, g = "0", method = "taylor", tolerance = "0";
  int digits = 50;
  std::optional<int> certified_digits;  // given: the working precision is chosen
  bool certify = false;
  std::size_t max_steps = solve_options<double>{}.max_steps;
};

// The object of `viscor cor --json` for one scaled point (cmd_cor.cpp, the same fields).
json cor_json(const cor_request& q) {
  const contact_law law = resolve_law(q.name, q.alpha, q.beta);
  if (q.method != "taylor" && q.method != "adaptive")
    throw invalid_parameter("method must be 'taylor' or 'adaptive', got '" + q.method + "'");
  if (q.max_steps < 1) throw invalid_parameter("max_steps must be >= 1, got 0");
  const auto solve = [&](int digits, bool certify) {
    return with_working_precision(digits, [&]<class Real>() {
      const Real gamma = parse_value<Real>(q.gamma, "gamma"), g = parse_value<Real>(q.g, "g");
      solve_options<Real> options;
      options.method = q.method == "taylor" ? integration_method::taylor : integration_method::adaptive;
      options.tolerance = parse_real<Real>(q.tolerance, "tolerance");
      options.max_steps = q.max_steps;
      return jobs::solve_cor(law, gamma, g, options, certify);
    });
  };
  if (q.certified_digits)
    return render::cor_json(jobs::certify_cor_to_goal(*q.certified_digits, [&](int digits) { return solve(digits, true); }));
  return render::cor_json(solve(q.digits, q.certify));
}

py::object cor(const cor_request& q) {
  json j;
  {
    py::gil_scoped_release release;  // the working precision is per thread (scoped_precision)
    j = cor_json(q);
  }
  return to_python(j);
}

// ---- table: the table jobs ----

struct table_request {
  std::string spec_text, spec_name, output, shard;
  bool from_file = false, sticking = false, resume = false, quiet = true;
  int threads = -1;  // -1: every core
  py::object progress = py::none();  // callable(done, total), or None
  bool netcdf = false;                // also the NetCDF form (format="netcdf")
};

// Runs a table job without the GIL. Ctrl-C in Python stops it after the rows in
// progress (the finished ones stay in OUT.partial for resume=True) and raises
// KeyboardInterrupt with the job's message.
std::string table(const table_request& q) {
  const jobs::table_spec spec = q.from_file ? jobs::read_spec_json(q.spec_name)
                                            : jobs::parse_spec_json(q.spec_text, q.spec_name);
  jobs::table_run_options run;
  run.output = q.output;
  run.spec_file = q.from_file ? q.spec_name : std::string();
  run.part = q.shard.empty() ? shard{} : shard::parse(q.shard);
  run.resume = q.resume;
  if (q.threads != -1) run.threads = q.threads;
  run.quiet = q.quiet;
  run.netcdf = q.netcdf;
  run.should_stop = [] {
    py::gil_scoped_acquire gil;
    // The exception stays set: a signal's handler may also have run in the progress callback.
    return PyErr_Occurred() != nullptr || PyErr_CheckSignals() != 0;
  };
  if (!q.progress.is_none())
    run.on_progress = [&progress = q.progress](std::size_t done, std::size_t total) {
      py::gil_scoped_acquire gil;
      if (PyErr_Occurred()) return;  // interrupted already: Python code cannot run
      try {
        progress(done, total);
      } catch (py::error_already_set& e) {
        // A failing display must not stop the run; Ctrl-C or SIGTERM, whose handler the
        // interpreter may run inside the callback, must.
        if (e.matches(PyExc_Exception)) e.discard_as_unraisable("viscor.table's progress callback");
        else e.restore();
      }
    };
  std::exception_ptr failure;
  {
    py::gil_scoped_release release;
    try {
      if (q.sticking) jobs::make_sticking_table(spec, run);
      else jobs::make_cor_table(spec, run);
    } catch (...) {
      failure = std::current_exception();
    }
  }
  if (failure) {
    if (PyErr_Occurred()) {  // interrupted from Python: raise that exception, with what was kept
      try {
        std::rethrow_exception(failure);
      } catch (const jobs::table_interrupted& e) {
        PyErr_Clear();
        const std::string message = "interrupted: " + std::to_string(e.done) + " of " + std::to_string(e.total) +
                                    " rows are done and kept in '" + e.partial +
                                    "'; call table() again with the same arguments and resume=True to continue";
        PyErr_SetString(PyExc_KeyboardInterrupt, message.c_str());
      } catch (const std::exception& e) {
        PyErr_Clear();
        PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
      }
      throw py::error_already_set();
    }
    std::rethrow_exception(failure);
  }
  if (PyErr_Occurred()) throw py::error_already_set();  // interrupted as the last row finished: the table is whole
  return q.output;
}

// The estimate of a table run (jobs/table_estimate.hpp): computes nothing.
py::object table_estimate(const table_request& q) {
  const jobs::table_spec spec = q.from_file ? jobs::read_spec_json(q.spec_name)
                                            : jobs::parse_spec_json(q.spec_text, q.spec_name);
  const shard part = q.shard.empty() ? shard{} : shard::parse(q.shard);
  const int threads = q.threads != -1 ? q.threads : jobs::table_run_options{}.threads;
  return to_python(render::table_estimate_json(jobs::estimate_cor_table(spec, part, threads)));
}

// The columns and rows of a table file, validated by the library's reader.
py::tuple table_columns(const std::string& path) {
  const jobs::table_format format = jobs::table_format::of_file(path);
  const csv_table t = format.read(path);
  py::list header;
  for (const std::string& name : split_fields(format.header())) header.append(name);
  py::list rows;
  for (const auto& r : t.rows) rows.append(py::cast(r.fields));
  return py::make_tuple(header, rows);
}

// The dataset form of a table file (jobs/table_dataset.hpp), as Table.to_xarray()
// takes it: dims {name: size}; coords and data_vars [(name, dims, values, attrs)],
// numbers as NumPy arrays of the grid's shape, texts as flat lists; attrs.
py::dict table_dataset(const std::string& path) {
  const jobs::table_dataset d = jobs::read_table_dataset(path);
  py::dict dims;
  for (const auto& [name, size] : d.dimensions) dims[py::str(name)] = size;
  const auto shape_of = [&](const jobs::dataset_array& a) {
    std::vector<py::ssize_t> shape;
    for (const std::string& dim : a.dims)
      for (const auto& [name, size] : d.dimensions)
        if (name == dim) shape.push_back(static_cast<py::ssize_t>(size));
    return shape;
  };
  const auto arrays = [&](const std::vector<jobs::dataset_array>& list) {
    py::list out;
    for (const jobs::dataset_array& a : list) {
      py::dict attrs;
      for (const auto& [name, value] : a.attributes) attrs[py::str(name)] = value;
      py::object values;
      switch (a.kind) {
        case jobs::dataset_array::type::float64:
          values = py::array_t<double>(shape_of(a), a.numbers.data());
          break;
        case jobs::dataset_array::type::int32:
          values = py::array_t<std::int32_t>(shape_of(a), a.integers.data());
          break;
        case jobs::dataset_array::type::text: values = py::cast(a.texts); break;
      }
      out.append(py::make_tuple(a.name, py::tuple(py::cast(a.dims)), values, attrs));
    }
    return out;
  };
  py::dict attrs;
  for (const auto& [name, value] : d.attributes)
    std::visit([&, key = name](const auto& v) { attrs[py::str(key)] = v; }, value);
  py::dict out;
  out["dims"] = dims;
  out["coords"] = arrays(d.coordinates);
  out["data_vars"] = arrays(d.variables);
  out["attrs"] = attrs;
  return out;
}

// ---- evaluate over arrays ----

// Codes of the method array: evaluation_method in enum order (its last is the surrogate).
constexpr std::int8_t surrogate_method = static_cast<std::int8_t>(evaluation_method::surrogate);

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (int k = 0; k <= surrogate_method; ++k) names.push_back(to_string(static_cast<evaluation_method>(k)));
  return names;
}

struct evaluate_request {
  contact_law law;
  bool relative = false;
  std::string error_maps;  // directory of <law>.csv, "" for none
  std::shared_ptr<const surrogate::cor_surrogate> surrogate;
  unsigned threads = 0;  // 0: every core
};

py::tuple evaluate(const evaluate_request& q, py::array_t<double, py::array::c_style | py::array::forcecast> gamma,
                   py::array_t<double, py::array::c_style | py::array::forcecast> g,
                   py::array_t<double, py::array::c_style | py::array::forcecast> tol) {
  const py::ssize_t n = gamma.size();
  if (g.size() != n || tol.size() != n)
    throw invalid_parameter("evaluate: gamma, g and tol must have the same size after broadcasting");
  py::array_t<double> e(n), one_minus_e(n), bound(n);
  py::array_t<std::int8_t> method(n), outcome(n);
  const double* pg = gamma.data();
  const double* pgg = g.data();
  const double* pt = tol.data();
  double* pe = e.mutable_data();
  double* pome = one_minus_e.mutable_data();
  double* pb = bound.mutable_data();
  std::int8_t* pm = method.mutable_data();
  std::int8_t* po = outcome.mutable_data();
  {
    py::gil_scoped_release release;
    std::optional<error_map> map;
    if (!q.error_maps.empty() && !q.law.name.empty()) {
      const std::filesystem::path path = std::filesystem::path(q.error_maps) / (q.law.name + ".csv");
      if (std::filesystem::exists(path)) map = read_error_map(path.string());
      if (map && map->cells().empty()) map.reset();  // nothing to vouch for (and at() would rebuild every call)
    }
    // NOTE: error_map::at builds its index on the first call (mutable members, no
    // lock): one call here, before the workers share the map, so they only read it.
    if (map) (void)map->at(0, 0);
    evaluate_options options;
    options.relative = q.relative;
    options.map = map ? &*map : nullptr;
    // evaluate's own rule decides where the surrogate's bound meets the tolerance.
    std::optional<surrogate::surrogate_source> source;
    if (q.surrogate) source.emplace(*q.surrogate);
    options.surrogate = source ? &*source : nullptr;
    const evaluator<double> evaluate_one(q.law, options);
    // Points are handed out in blocks; the first failing point (lowest index) is reported.
    jobs::parallel_for_options loop;
    loop.block = 256;
    const unsigned threads = q.threads ? q.threads : std::max(1u, std::thread::hardware_concurrency());
    loop.threads = static_cast<unsigned>(std::min<py::ssize_t>(threads, std::max<py::ssize_t>(1, n / 64)));
    const jobs::parallel_for_result run = jobs::parallel_for(
        static_cast<std::size_t>(n),
        [&](std::size_t i) {
          const evaluation<double> r = evaluate_one(pg[i], pgg[i], pt[i]);
          pe[i] = r.e, pome[i] = r.one_minus_e, pb[i] = r.bound;
          pm[i] = static_cast<std::int8_t>(r.method);
          po[i] = static_cast<std::int8_t>(r.outcome);  // 0 rebound, 1 stick, 2 undecided
        },
        loop);
    if (run.failed()) {
      const std::size_t i = run.failed_at;
      const std::string where = "evaluate: point " + std::to_string(i) + " (gamma = " + to_decimal_string(pg[i], 17) +
                                ", g = " + to_decimal_string(pgg[i], 17) + ", tol = " + to_decimal_string(pt[i], 3) +
                                "): ";
      try {
        std::rethrow_exception(run.failure);
      } catch (const precision_unavailable& ex) {  // before invalid_parameter, its base
        throw precision_unavailable(where + ex.what());
      } catch (const invalid_parameter& ex) {
        throw invalid_parameter(where + ex.what());
      } catch (const certification_error& ex) {
        throw certification_error(where + ex.what());
      } catch (const convergence_error& ex) {
        throw convergence_error(where + ex.what());
      } catch (const std::exception& ex) {
        throw error(where + ex.what());
      }
    }
  }
  return py::make_tuple(e, one_minus_e, bound, method, outcome);
}

}  // namespace
}  // namespace viscor::python

PYBIND11_MODULE(_viscor, m) {
  using namespace viscor::python;
  namespace vp = viscor::python;
  m.doc() = "viscor's compiled core (use the package viscor; docs/python.md)";
  register_exceptions(m);
  m.attr("version") = VISCOR_VERSION;
  m.attr("git_commit") = viscor::git_commit();
  m.attr("max_working_digits") = viscor::max_working_digits;
  m.attr("evaluation_methods") = method_names();

  m.def(
      "cor",
      [](const std::string& name, const std::string& alpha, const std::string& beta, const std::string& gamma,
         const std::string& g, int digits, std::optional<int> certified_digits, bool certify, const std::string& method,
         const std::string& tolerance, long long max_steps) {
        if (max_steps < 0) throw viscor::invalid_parameter("max_steps must be >= 1, got " + std::to_string(max_steps));
        cor_request q;
        q.name = name, q.alpha = alpha, q.beta = beta, q.gamma = gamma, q.g = g, q.digits = digits;
        q.certified_digits = certified_digits, q.certify = certify, q.method = method, q.tolerance = tolerance;
        if (max_steps > 0) q.max_steps = static_cast<std::size_t>(max_steps);  // 0: the library's default
        return vp::cor(q);
      },
      py::arg("name"), py::arg("alpha"), py::arg("beta"), py::arg("gamma"), py::arg("g"), py::arg("digits"),
      py::arg("certified_digits"), py::arg("certify"), py::arg("method"), py::arg("tolerance"), py::arg("max_steps"),
      "One CoR: the object of `viscor cor --json` as a dict (decimal strings).");

  py::class_<table_request>(m, "TableRequest")
      .def(py::init<>())
      .def_readwrite("spec_text", &table_request::spec_text)
      .def_readwrite("spec_name", &table_request::spec_name)
      .def_readwrite("from_file", &table_request::from_file)
      .def_readwrite("output", &table_request::output)
      .def_readwrite("shard", &table_request::shard)
      .def_readwrite("sticking", &table_request::sticking)
      .def_readwrite("resume", &table_request::resume)
      .def_readwrite("quiet", &table_request::quiet)
      .def_readwrite("threads", &table_request::threads)
      .def_readwrite("progress", &table_request::progress)
      .def_readwrite("netcdf", &table_request::netcdf);
  m.def("table", &vp::table, py::arg("request"),
        "Runs a table job (jobs/table_jobs.hpp) without the GIL; returns the output path.");
  m.def("table_estimate", &vp::table_estimate, py::arg("request"),
        "The estimate of a table run (jobs/table_estimate.hpp) as a dict; computes nothing.");
  m.def("table_dataset", &vp::table_dataset, py::arg("path"),
        "The dataset form of a CoR table file (jobs/table_dataset.hpp): dims, coords, data_vars, attrs.");
  m.def("netcdf_available", &viscor::jobs::netcdf_available, "Whether this build writes NetCDF (libnetcdf).");
  m.def("table_columns", &vp::table_columns, py::arg("path"),
        "(column names, rows of decimal strings) of a viscor table file, checked by the library's reader.");
  m.def(
      "scene",
      [](const std::string& path, const std::string& error_maps, const std::string& output) {
        viscor::jobs::json object;
        {
          py::gil_scoped_release release;
          const viscor::jobs::scene_file file = viscor::jobs::read_scene_json(path);
          viscor::jobs::check_plausible_scene_units(file.scene, false,
                                                    [&](const std::string& field) { return file.locate(field); });
          const bool as_json = output.empty() || output.ends_with(".json");
          viscor::jobs::scene_result r = viscor::jobs::run_scene_file(file, path, error_maps, as_json);
          if (!output.empty()) viscor::jobs::write_atomically(output, r.body);
          object = std::move(r.object);
        }
        return output.empty() ? vp::to_python(object) : py::object(py::none());
      },
      py::arg("path"), py::arg("error_maps"), py::arg("output"),
      "The scene job (jobs/scene_job.hpp): its JSON object as a dict, or with `output` the file written (CSV, or "
      "JSON when it ends in .json) and None.");

  m.def(
      "solve_points",
      [](const std::string& source, bool from_file, int digits, std::optional<int> certified_digits, unsigned threads,
         const std::string& method, const std::string& tolerance, long long max_steps) {
        viscor::jobs::point_options o;
        o.method = viscor::jobs::parse_integration_method(method, "method");
        o.tolerance = tolerance;
        if (max_steps < 0) throw viscor::invalid_parameter("max_steps must be >= 1, got " + std::to_string(max_steps));
        if (max_steps > 0) o.max_steps = static_cast<std::size_t>(max_steps);
        o.default_digits = digits;
        o.default_certified_digits = certified_digits;
        if (threads < 1 || threads > 4096)
          throw viscor::invalid_parameter("threads must be from 1 to 4096, got " + std::to_string(threads));
        o.threads = threads;
        std::vector<viscor::jobs::json> results;
        {
          py::gil_scoped_release release;
          std::ifstream file;
          std::istringstream text;
          if (from_file) {
            file.open(source);
            if (!file) throw viscor::invalid_parameter("points: cannot read '" + source + "'");
          } else {
            text.str(source);
          }
          std::istream& in = from_file ? static_cast<std::istream&>(file) : text;
          viscor::jobs::solve_points(in, from_file ? source : std::string("<points>"), o,
                                     [&](const viscor::jobs::json& r) { results.push_back(r); });
        }
        py::list out;
        for (const auto& r : results) out.append(vp::to_python(r));
        return out;
      },
      py::arg("source"), py::arg("from_file"), py::arg("digits"), py::arg("certified_digits"), py::arg("threads"),
      py::arg("method"), py::arg("tolerance"), py::arg("max_steps"),
      "A batch of points (jobs/point_batch.hpp): one dict per point, as `viscor cor --points` prints them.");

  vp::bind_commands(m);
  // The command-line tool built with this module: where run_cli finds it (build tree, then installed).
  m.attr("cli_candidates") = std::vector<std::string>{VISCOR_BUILT_CLI, VISCOR_INSTALLED_CLI};

  m.def("data_directory", [] { return viscor::jobs::data_directory(); },
        "The data directory (certified tables, error maps) the CLI code would use.");
  m.def("default_error_maps", [] { return viscor::jobs::default_error_maps(); },
        "The error maps directory of the data directory, or ''.");

  py::class_<viscor::surrogate::cor_surrogate, std::shared_ptr<viscor::surrogate::cor_surrogate>>(m, "Surrogate")
      .def(py::init([](const std::string& path) {
             return std::make_shared<viscor::surrogate::cor_surrogate>(viscor::surrogate::read_cor_surrogate(path));
           }),
           py::arg("path"), "Reads a surrogate file (reference_data/surrogates/<law>.surrogate).")
      .def("in_domain", &viscor::surrogate::cor_surrogate::in_domain, py::arg("gamma"), py::arg("g"))
      .def("critical_gamma", &viscor::surrogate::cor_surrogate::critical_gamma, py::arg("g"))
      .def("gamma_for", &viscor::surrogate::cor_surrogate::gamma_for, py::arg("e"), py::arg("g"))
      .def(
          "__call__",
          [](const viscor::surrogate::cor_surrogate& s, double gamma, double g) {
            const viscor::surrogate::surrogate_value v = s(gamma, g);
            py::dict d;
            d["in_domain"] = v.in_domain;
            if (!v.in_domain) return d;
            d[viscor::field::outcome] = std::string(viscor::to_string(v.outcome));
            d[viscor::field::e] = v.e;
            d[viscor::field::one_minus_e] = v.one_minus_e;
            d["e_squared"] = v.e_squared;
            return d;
          },
          py::arg("gamma"), py::arg("g"))
      .def_property_readonly("error_bound", [](const viscor::surrogate::cor_surrogate& s) {
        return vp::to_python(viscor::jobs::surrogate_bound_json(s));
      });

  py::class_<evaluate_request>(m, "Evaluator")
      .def(py::init([](const std::string& name, const std::string& alpha, const std::string& beta, bool relative,
                       const std::string& error_maps,
                       std::shared_ptr<viscor::surrogate::cor_surrogate> surrogate, unsigned threads) {
             evaluate_request q;
             q.law = resolve_law(name, alpha, beta);
             q.law.validate();
             q.relative = relative;
             if (!error_maps.empty() && !std::filesystem::is_directory(error_maps))
               throw viscor::invalid_parameter("error_maps: '" + error_maps + "' is not a directory");
             q.error_maps = error_maps;
             q.surrogate = std::move(surrogate);
             q.threads = threads;
             return q;
           }),
           py::arg("name"), py::arg("alpha"), py::arg("beta"), py::arg("relative"), py::arg("error_maps"),
           py::arg("surrogate"), py::arg("threads"))
      .def("__call__", &vp::evaluate, py::arg("gamma"), py::arg("g"), py::arg("tol"),
           "Flat float64 arrays of one size -> (e, one_minus_e, bound, method code, outcome code).");

  // The committed surrogates as C99 files (jobs/surrogate_export.hpp); viscor.export_surrogates wraps it.
  m.def("surrogate_export",
        [](const std::string& output, const std::vector<std::string>& laws, const std::string& language,
           const std::string& directory) {
          viscor::jobs::surrogate_export_options o;
          o.output_directory = output, o.laws = laws, o.language = language;
          o.surrogate_directory = directory.empty() ? viscor::jobs::surrogate_directory() : directory;
          return viscor::jobs::export_surrogates(o);
        },
        py::arg("output"), py::arg("laws"), py::arg("language"), py::arg("surrogate_directory"),
        "Writes the C export into `output`; returns the paths written.");
}
