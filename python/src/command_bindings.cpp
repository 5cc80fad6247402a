// The one-shot jobs of viscor._viscor: exact, approx, scale, calibrate, dem and cor
// with physical inputs, each a call of the library's job (include/viscor/jobs/)
// without the GIL, returning the job's JSON object as Python objects. Inputs arrive
// as the exact decimal text the Python layer made of them (python/viscor/_inputs.py).
#include <viscor/certify/extern_templates.hpp>  // first: the solvers are compiled once, in libviscor

#include "python_objects.hpp"

#include <viscor/jobs/approx_job.hpp>
#include <viscor/jobs/approx_render.hpp>
#include <viscor/jobs/calibrate_job.hpp>
#include <viscor/jobs/calibrate_render.hpp>
#include <viscor/jobs/cor_job.hpp>
#include <viscor/jobs/cor_render.hpp>
#include <viscor/jobs/dem_job.hpp>
#include <viscor/jobs/dem_render.hpp>
#include <viscor/jobs/exact_job.hpp>
#include <viscor/jobs/exact_render.hpp>
#include <viscor/jobs/formula_job.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#include <viscor/jobs/scale_job.hpp>
#include <viscor/jobs/scale_render.hpp>
#include <viscor/jobs/table_jobs.hpp>

#include <viscor/core/scaling.hpp>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace viscor::python {
namespace {

using text_fields = std::map<std::string, std::string>;

// The physical inputs named by the keywords of the Python functions (m=, k=, ...).
jobs::physical_inputs physical_of(const text_fields& fields, bool strict) {
  jobs::physical_inputs p;
  const std::map<std::string, std::optional<std::string>*> slots{
      {"m", &p.m},           {"k", &p.k},
      {"v0", &p.v0},         {"gamma0", &p.gamma0},
      {"gravity", &p.gravity}, {"force", &p.force},
      {"youngs_modulus", &p.youngs_modulus}, {"poisson_ratio", &p.poisson_ratio},
      {"radius", &p.radius}, {"density", &p.density},
      {"contact", &p.contact}, {"wall_youngs_modulus", &p.wall_youngs_modulus},
      {"wall_poisson_ratio", &p.wall_poisson_ratio}, {"other_youngs_modulus", &p.other_youngs_modulus},
      {"other_poisson_ratio", &p.other_poisson_ratio}, {"other_radius", &p.other_radius},
      {"other_density", &p.other_density}};
  for (const auto& [name, value] : fields) {
    const auto slot = slots.find(name);
    if (slot == slots.end()) throw invalid_parameter("unknown physical input '" + name + "'");
    *slot->second = value;
  }
  p.strict = strict;
  return p;
}

std::optional<std::string> optional_text(const std::string& text) {
  return text.empty() ? std::nullopt : std::optional<std::string>(text);
}

// Runs a job and renders its result to JSON without the GIL, and returns the JSON
// object as Python objects.
template <class Job>
py::object run_released(const Job& job) {
  jobs::json object;
  {
    py::gil_scoped_release release;
    object = job();
  }
  return to_python(object);
}

py::object exact(const std::string& name, const std::string& alpha, const std::string& beta, const std::string& gamma,
                 const std::string& g, int digits) {
  jobs::exact_request q;
  q.law = jobs::resolve_law(name, alpha, beta);
  q.gamma = gamma, q.g = g, q.digits = digits;
  return run_released([&] { return render::exact_json(jobs::run_exact(q)); });
}

py::object approx(const std::string& name, const std::string& alpha, const std::string& beta, const std::string& gamma,
                  const std::string& g, const std::string& formula, const std::string& source, int order, int digits) {
  jobs::approx_request q;
  q.law = jobs::resolve_law(name, alpha, beta);
  q.gamma = gamma, q.g = g, q.formula = formula, q.source = source, q.order = order, q.digits = digits;
  return run_released([&] { return render::approx_json(jobs::run_approx(q)); });
}

py::object scale(const std::string& name, const std::string& alpha, const std::string& beta,
                 const text_fields& physical, const std::string& gamma, const std::string& g, int digits, bool strict) {
  jobs::scale_request q;
  q.law = jobs::resolve_law(name, alpha, beta);
  q.physical = physical_of(physical, strict);
  q.gamma = optional_text(gamma), q.g = optional_text(g), q.digits = digits;
  return run_released([&] { return render::scale_json(jobs::run_scale(q)); });
}

py::object calibrate(const std::string& name, const std::string& alpha, const std::string& beta,
                     const text_fields& physical, const std::string& target_e, const std::string& g,
                     const std::string& tolerance, const std::string& gamma_max, const std::string& method, int digits,
                     bool strict) {
  jobs::calibrate_request q;
  q.law = jobs::resolve_law(name, alpha, beta);
  q.physical = physical_of(physical, strict);
  q.target_e = optional_text(target_e), q.g = optional_text(g);
  q.tolerance = tolerance, q.gamma_max = gamma_max, q.method = method, q.digits = digits;
  return run_released([&] { return render::calibrate_json(jobs::run_calibrate(q)); });
}

py::object dem(const text_fields& fields, int digits, bool strict) {
  jobs::dem_request q;
  const std::map<std::string, std::string*> slots{
      {"code", &q.code},           {"damping", &q.damping},
      {"contact", &q.contact},     {"youngs_modulus", &q.youngs_modulus},
      {"poisson_ratio", &q.poisson_ratio}, {"k", &q.stiffness},
      {"radius", &q.radius},       {"density", &q.density},
      {"target_e", &q.target_e},   {"deck_damping", &q.deck_damping},
      {"deck_en", &q.deck_en},     {"v0", &q.v0},
      {"gravity", &q.gravity},     {"force", &q.force},
      {"speeds", &q.speeds},       {"drop_deck", &q.drop_deck_path},
      {"wall_youngs_modulus", &q.wall_youngs_modulus}, {"wall_poisson_ratio", &q.wall_poisson_ratio},
      {"other_youngs_modulus", &q.other_youngs_modulus}, {"other_poisson_ratio", &q.other_poisson_ratio},
      {"other_radius", &q.other_radius}, {"other_density", &q.other_density},
      {"variables", &q.variables_path}, {"method", &q.method}, {"timestep", &q.timestep}};
  for (const auto& [name, value] : fields) {
    const auto slot = slots.find(name);
    if (slot == slots.end()) throw invalid_parameter("dem: unknown input '" + name + "'");
    *slot->second = value;
  }
  q.digits = digits, q.strict = strict;
  return run_released([&] { return render::dem_json(jobs::run_dem(q)); });
}

// One impact from its physical inputs (the physical mode of `viscor cor`).
py::object physical_cor(const std::string& name, const std::string& alpha, const std::string& beta,
                        const text_fields& physical, int digits, std::optional<int> certified_digits, bool certify,
                        const std::string& method, const std::string& tolerance, long long max_steps, bool strict) {
  jobs::cor_request q;
  q.law = jobs::resolve_law(name, alpha, beta);
  q.physical = physical_of(physical, strict);
  q.method = jobs::parse_integration_method(method, "method");
  q.tolerance = tolerance, q.digits = digits, q.certify = certify;
  q.certified_digits = certified_digits;
  if (max_steps < 0) throw invalid_parameter("max_steps must be >= 1, got " + std::to_string(max_steps));
  if (max_steps > 0) q.max_steps = static_cast<std::size_t>(max_steps);
  return run_released([&] { return render::cor_json(jobs::run_cor(q)); });
}

using double_array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Scaled (gamma, g) of flat arrays of physical inputs of one size, in double. The
// bead is (m, k), or a material (youngs_modulus, poisson_ratio, radius, and m or
// density) on a wall (rigid, or wall_youngs_modulus and wall_poisson_ratio) or, for
// contact "pair", meeting a bead like it or the other_* one: absent arrays are
// empty. Refuses the first bad point by its index.
py::tuple scaled_arrays(const std::string& name, const std::string& alpha, const std::string& beta,
                        const std::map<std::string, double_array>& columns, const std::string& contact, bool strict) {
  const contact_law law = jobs::resolve_law(name, alpha, beta);
  {  // which inputs are given, by the library's rules (physical_inputs::check_complete); values come below
    text_fields names{{"contact", contact}};
    for (const auto& [key, values] : columns) names[key] = "1";
    const jobs::physical_inputs given = physical_of(names, strict);
    given.check_complete("evaluate");
    given.require_gamma0("evaluate");
  }
  const dem::contact_kind kind = contact == "pair" ? dem::contact_kind::pair : dem::contact_kind::wall;
  const auto column = [&](const char* key) -> const double* {
    const auto it = columns.find(key);
    return it == columns.end() ? nullptr : it->second.data();
  };
  py::ssize_t n = 0;
  for (const auto& [key, a] : columns) n = a.size();
  for (const auto& [key, a] : columns)
    if (a.size() != n) throw invalid_parameter("evaluate: the physical inputs must broadcast to one shape");
  const double *m = column("m"), *k = column("k"), *v0 = column("v0"), *gamma0 = column("gamma0"),
               *gravity = column("gravity"), *force = column("force"), *E = column("youngs_modulus"),
               *nu = column("poisson_ratio"), *radius = column("radius"), *density = column("density");
  const double *wall_E = column("wall_youngs_modulus"), *wall_nu = column("wall_poisson_ratio"),
               *other_E = column("other_youngs_modulus"), *other_nu = column("other_poisson_ratio"),
               *other_radius = column("other_radius"), *other_density = column("other_density");
  // Inputs far outside their quantity's range (a unit slip: cm/s for m/s) are warned
  // about as cor warns (refused when strict), each at its most extreme points.
  for (const auto& [key, quantity] : std::initializer_list<std::pair<const char*, physical_quantity>>{
           {"youngs_modulus", physical_quantity::youngs_modulus}, {"density", physical_quantity::density},
           {"radius", physical_quantity::radius}, {"v0", physical_quantity::speed},
           {"gravity", physical_quantity::gravity}, {"wall_youngs_modulus", physical_quantity::youngs_modulus},
           {"other_youngs_modulus", physical_quantity::youngs_modulus}, {"other_density", physical_quantity::density},
           {"other_radius", physical_quantity::radius}}) {
    const double* x = column(key);
    if (!x || n == 0) continue;
    const auto [lowest, highest] = std::minmax_element(x, x + n);
    for (const double* extreme : {lowest, highest}) {
      if (extreme == highest && *highest == *lowest) break;
      char text[32];
      std::snprintf(text, sizeof text, "%.17g", *extreme);
      jobs::check_plausible_unit(quantity, std::string(text), "evaluate: " + std::string(key) + " (point " +
                                     std::to_string(extreme - x) + ")", strict);
    }
  }
  py::array_t<double> gamma(n), g(n);
  double* pg = gamma.mutable_data();
  double* pgg = g.mutable_data();
  py::ssize_t i = 0;
  try {
    py::gil_scoped_release release;
    for (; i < n; ++i) {
      physical_parameters<double> p;
      if (E) {
        dem::contact_partner<double> partner;
        if (wall_E) partner.wall = elastic_material<double>{wall_E[i], wall_nu[i]};
        if (other_E) partner.other = dem::bead_material<double>{other_E[i], other_nu[i], other_radius[i], other_density[i]};
        std::tie(p.m, p.k) = jobs::bead_of_material<double>(
            law, E[i], nu[i], radius[i], m ? std::optional<double>(m[i]) : std::nullopt,
            density ? std::optional<double>(density[i]) : std::nullopt, kind, partner);
      } else {
        p.m = m[i], p.k = k[i];
      }
      p.v0 = v0[i], p.gamma0 = gamma0[i], p.force = force ? force[i] : 0.0;
      p.gravity = kind == dem::contact_kind::pair ? 0.0 : gravity[i];  // both beads fall alike
      p.validate();
      const scaled_parameters<double> s = to_scaled(law, p);
      pg[i] = s.gamma, pgg[i] = s.g;
    }
  } catch (const invalid_parameter& e) {
    throw invalid_parameter("evaluate: point " + std::to_string(i) + ": " + e.what());
  }
  return py::make_tuple(gamma, g);
}

// The certified points a formula of the named law is checked at: (gamma, g) arrays.
py::tuple formula_points(const std::string& law) {
  jobs::formula_reference r;
  {
    py::gil_scoped_release release;
    r = jobs::committed_formula_reference(law_by_name(law));
  }
  py::array_t<double> gamma(static_cast<py::ssize_t>(r.points.size())), g(static_cast<py::ssize_t>(r.points.size()));
  double* pg = gamma.mutable_data();
  double* pgg = g.mutable_data();
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    pg[k] = std::strtod(r.points[k].gamma.c_str(), nullptr);
    pgg[k] = std::strtod(r.points[k].g.c_str(), nullptr);
  }
  return py::make_tuple(gamma, g);
}

// A formula's values at formula_points(law), compared cell by cell (jobs/formula_job.hpp).
// The tolerance and the region's bounds come as text ("" for an unbounded side) and go
// through the number parser the CLI uses (jobs::formula_tolerance_of, formula_region_of).
py::object compare_formula(const std::string& law, const double_array& values, const std::string& quantity,
                           const std::string& tolerance, const std::vector<std::string>& region) {
  if (quantity != "e" && quantity != "one_minus_e")
    throw invalid_parameter("compare: quantity must be 'e' or 'one_minus_e', got '" + quantity + "'");
  if (region.size() != 4) throw invalid_parameter("compare: region is (gamma_min, gamma_max, g_min, g_max)");
  const formula_quantity q = quantity == "e" ? formula_quantity::e : formula_quantity::one_minus_e;
  const double tol = jobs::formula_tolerance_of(tolerance);
  const formula_region where = jobs::formula_region_of(region[0], region[1], region[2], region[3]);
  std::vector<double> v(values.data(), values.data() + values.size());
  jobs::json object;
  {
    py::gil_scoped_release release;
    const jobs::formula_reference r = jobs::committed_formula_reference(law_by_name(law));
    const formula_comparison c = compare_formula_values(r.points, v, q, r.grid, tol, where);
    object = jobs::formula_comparison_json(c, r, q);
    object["text"] = jobs::formula_comparison_text(c, r);
  }
  return to_python(object);
}

}  // namespace

// An output_lock that Python can release at the end of a with block.
struct held_output_lock {
  std::optional<jobs::output_lock> lock;
};

// The library's safe writer (jobs/files.hpp): [(path, text), ...] published together.
void write_together(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<jobs::output_file> outputs;
  for (const auto& [path, body] : files) outputs.push_back({path, body});
  py::gil_scoped_release release;
  jobs::write_together(outputs);
}

void bind_commands(py::module_& m) {
  m.def("exact", &exact, py::arg("name"), py::arg("alpha"), py::arg("beta"), py::arg("gamma"), py::arg("g"),
        py::arg("digits"), "The exact job (jobs/exact_job.hpp): the object of `viscor exact --json`.");
  m.def("approx", &approx, py::arg("name"), py::arg("alpha"), py::arg("beta"), py::arg("gamma"), py::arg("g"),
        py::arg("formula"), py::arg("source"), py::arg("order"), py::arg("digits"),
        "The approx job (jobs/approx_job.hpp): the object of `viscor approx --json`.");
  m.def("scale", &scale, py::arg("name"), py::arg("alpha"), py::arg("beta"), py::arg("physical"), py::arg("gamma"),
        py::arg("g"), py::arg("digits"), py::arg("strict"),
        "The scale job (jobs/scale_job.hpp): the object of `viscor scale --json`.");
  m.def("calibrate", &calibrate, py::arg("name"), py::arg("alpha"), py::arg("beta"), py::arg("physical"),
        py::arg("target_e"), py::arg("g"), py::arg("tolerance"), py::arg("gamma_max"), py::arg("method"),
        py::arg("digits"), py::arg("strict"),
        "The calibrate job (jobs/calibrate_job.hpp): the object of `viscor calibrate --json`.");
  m.def("dem", &dem, py::arg("fields"), py::arg("digits"), py::arg("strict"),
        "The dem job (jobs/dem_job.hpp): the object of `viscor dem --json`.");
  m.def("physical_cor", &physical_cor, py::arg("name"), py::arg("alpha"), py::arg("beta"), py::arg("physical"),
        py::arg("digits"), py::arg("certified_digits"), py::arg("certify"), py::arg("method"), py::arg("tolerance"),
        py::arg("max_steps"), py::arg("strict"), "The cor job from physical inputs (jobs/cor_job.hpp): the object of `viscor cor --json`.");
  m.def("formula_points", &formula_points, py::arg("law"),
        "The (gamma, g) arrays of the certified points a formula of the law is checked at.");
  m.def("compare_formula", &compare_formula, py::arg("law"), py::arg("values"), py::arg("quantity"),
        py::arg("tolerance"), py::arg("region"),
        "A formula's values at formula_points(law) against the certified e, per cell (a dict); tolerance and\n"
        "region (gamma_min, gamma_max, g_min, g_max) as decimal text, \"\" for an unbounded side.");
  m.def("formula_tolerance", &jobs::formula_tolerance_of, py::arg("tolerance"),
        "A formula check's tolerance on |de| from decimal text, refused outside [0, 1) (as the CLI's --tolerance).");
  m.def(
      "merge_tables",
      [](const std::vector<std::string>& inputs, const std::string& output) {
        py::gil_scoped_release release;
        return jobs::merge_tables(inputs, output, /*quiet=*/true);
      },
      py::arg("inputs"), py::arg("output"),
      "Merges shard tables into one (jobs/table_jobs.hpp, as `viscor table merge`); returns its rows.");
  py::class_<held_output_lock>(m, "OutputLock",
                               "The library's lock on an output (jobs/files.hpp, output_lock: OUT.lock, held with\n"
                               "flock while a job writes OUT): `with OutputLock(out):`; raises when another holds it.")
      .def(py::init([](const std::string& output) {
             auto held = std::make_unique<held_output_lock>();
             held->lock.emplace(output);
             return held;
           }),
           py::arg("output"))
      .def("__enter__", [](held_output_lock& h) -> held_output_lock& { return h; }, py::return_value_policy::reference)
      .def("__exit__", [](held_output_lock& h, const py::args&) {
        h.lock.reset();
        return false;
      });
  m.def("write_together", &write_together, py::arg("files"),
        "Writes [(path, text), ...] as one command's outputs (jobs/files.hpp, write_together): each checked,\n"
        "written to an exclusive temporary, then all renamed; a failure before the renames replaces nothing.");
  m.def("scaled_arrays", &scaled_arrays, py::arg("name"), py::arg("alpha"), py::arg("beta"), py::arg("columns"),
        py::arg("contact") = "wall", py::arg("strict") = false,
        "Flat float64 arrays of physical inputs -> (gamma, g) arrays by the report's scaling, in double.");
}

}  // namespace viscor::python
