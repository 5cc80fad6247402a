// A batch of points (`viscor cor --points FILE|-`, viscor::jobs::solve_points):
// many impacts from one process. Each input line is a
// point, CSV (first line a header naming the columns) or JSON lines, with the law
// (`law`, or `alpha` and `beta`), `gamma`, `g` and optionally `digits` (the working
// precision) or `certified_digits` (the digits to certify); each output
// line is one JSON object with the same fields as `viscor cor --json`, plus `line`
// (the input line) — or `line` and `error` for a refused point. Results are
// printed in input order; with --threads N, N points are solved at a time.
#pragma once

#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/jobs/parallel_for.hpp>
#include <viscor/jobs/cor_job.hpp>
#include <viscor/jobs/cor_render.hpp>
#include <viscor/jobs/table_spec.hpp>

#include <viscor/impact/solve_impact.hpp>
#include <viscor/core/text_fields.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace viscor::jobs {

/// How a batch of points is solved: the integrator, its tolerance and step budget,
/// the digits of a point that gives none, and the worker threads.
struct point_options {
  integration_method method = integration_method::taylor;
  std::string tolerance = "0";
  std::size_t max_steps = solve_options<double>{}.max_steps;  ///< the library's default budget
  int default_digits = 15;
  /// Certified digits of a point that gives neither digits nor certified_digits (empty: none).
  std::optional<int> default_certified_digits;
  unsigned threads = 1;
};

/// One input point as text.
struct point_text {
  std::size_t line = 0;
  std::string law, alpha, beta, gamma, g = "0", digits, certified_digits;
};

namespace detail {

inline std::string* point_field(point_text& p, const std::string& name) {
  if (name == "law") return &p.law;
  if (name == "alpha") return &p.alpha;
  if (name == "beta") return &p.beta;
  if (name == "gamma") return &p.gamma;
  if (name == "g") return &p.g;
  if (name == "digits") return &p.digits;
  if (name == "certified_digits") return &p.certified_digits;
  return nullptr;
}

constexpr const char* point_fields = "law, alpha, beta, gamma, g, digits, certified_digits";

/// Reads one JSON-lines point; numbers keep their exact text (table_spec.hpp's reader).
class point_reader : public node_reader {
 public:
  using node_reader::node_reader;

  point_text read(const spec_node& root, std::size_t line) const {
    if (root.kind != spec_node::type::object) fail(root, "point", "each line must be a JSON object");
    point_text p;
    p.line = line;
    for (const auto& [key, node] : root.members) {
      std::string* slot = point_field(p, key);
      if (!slot) fail(node, key, std::string("unknown field (known: ") + point_fields + ")");
      *slot = key == "law" ? string(node, key) : node.kind == spec_node::type::string ? node.text : number_text(node, key);
    }
    return p;
  }
};

inline point_text parse_json_point(const std::string& text, const std::string& where, std::size_t line) {
  const char* furthest = text.data();
  counting_iterator first{text.data(), &furthest}, last{text.data() + text.size(), &furthest};
  spec_builder builder(text, where, &furthest);
  nlohmann::json::sax_parse(first, last, &builder);
  return point_reader(where).read(builder.root, line);
}

}  // namespace detail

/// Solves the points read from `in` (`name` names it in messages), and hands each
/// result line to `emit` in input order: the fields of `viscor cor --json` plus
/// "line", or "line" and "error" for a refused point. Returns the number refused.
/// Throws invalid_parameter for input that is not a point list at all.
std::size_t solve_points(std::istream& in, const std::string& name, const point_options& o,
                         const std::function<void(const json&)>& emit);

/// Reads points from `path` ("-": standard input), writes one JSON line per point
/// to `out` and names each refused point on standard error; returns the number refused.
std::size_t solve_points(const std::string& path, const point_options& o, std::ostream& out);

}  // namespace viscor::jobs
