// Reading a table grid spec (grid_spec.hpp) from JSON, with errors that name
// file, line and field; and writing the spec back as normalised JSON for the
// sidecars (the fingerprint that resume and merge compare).
//
// NOTE: numbers are taken from their source text, never through double: the
// SAX interface of nlohmann-json hands over the text of every floating-point
// number, so "gamma": 0.1 is the exact decimal 0.1. Lines are tracked with a
// counting iterator under the parser (nlohmann 3.11 keeps no positions).
//
// "method": "proven" is a method of the jobs (certified rows plus the columns of a
// proof, table_format.hpp): include/viscor/tables/ may not depend on the proofs,
// so grid_spec holds method certify and table_spec says "proven".
#pragma once

#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/jobs/physical_grid.hpp>

#include <viscor/tables/grid_spec.hpp>
#include <viscor/certify/certified_digits_goal.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace viscor::jobs {

namespace detail {

/// A JSON value with its source line; numbers keep their exact text.
struct spec_node {
  enum class type { null, boolean, number, string, object, array };
  type kind = type::null;
  std::string text;  ///< number text or string value
  bool flag = false;
  std::vector<std::pair<std::string, spec_node>> members;  ///< object, in file order
  std::vector<std::size_t> member_lines;                   ///< line of each key
  std::vector<spec_node> elements;                          ///< array
  std::size_t line = 0;

  std::string type_name() const {
    switch (kind) {
      case type::null: return "null";
      case type::boolean: return "a boolean";
      case type::number: return "a number";
      case type::string: return "a string";
      case type::object: return "an object";
      case type::array: return "an array";
    }
    return "?";
  }
};

/// Input iterator over the text that records how far the parser has read.
struct counting_iterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  const char* p = nullptr;
  const char** furthest = nullptr;

  reference operator*() const { return *p; }
  counting_iterator& operator++() {
    ++p;
    if (p > *furthest) *furthest = p;
    return *this;
  }
  counting_iterator operator++(int) {
    counting_iterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const counting_iterator& o) const { return p == o.p; }
  bool operator!=(const counting_iterator& o) const { return p != o.p; }
};

/// Builds the spec_node tree from SAX events.
class spec_builder : public nlohmann::json_sax<nlohmann::json> {
 public:
  spec_builder(const std::string& text, const std::string& file, const char** furthest)
      : m_text(text), m_file(file), m_furthest(furthest) {}

  spec_node root;

  bool null() override { return scalar(spec_node::type::null, ""); }
  bool boolean(bool v) override {
    spec_node& n = place(spec_node::type::boolean);
    n.flag = v;
    return true;
  }
  bool number_integer(number_integer_t v) override { return scalar(spec_node::type::number, std::to_string(v)); }
  bool number_unsigned(number_unsigned_t v) override { return scalar(spec_node::type::number, std::to_string(v)); }
  bool number_float(number_float_t, const string_t& s) override { return scalar(spec_node::type::number, s); }
  bool string(string_t& v) override { return scalar(spec_node::type::string, v); }
  bool binary(binary_t&) override { return scalar(spec_node::type::null, ""); }
  bool start_object(std::size_t) override {
    refuse_deeper_nesting();
    m_stack.push_back(&place(spec_node::type::object));
    return true;
  }
  bool key(string_t& k) override {
    spec_node& object = *m_stack.back();
    const std::size_t line = current_line();
    for (std::size_t i = 0; i < object.members.size(); ++i)
      if (object.members[i].first == k)
        throw viscor::parse_error(m_file + ":" + std::to_string(line) + ": field " + k + ": given twice (also on line " +
                          std::to_string(object.member_lines[i]) + ")");
    m_key = k;
    m_key_line = line;
    return true;
  }
  bool end_object() override {
    m_stack.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    refuse_deeper_nesting();
    m_stack.push_back(&place(spec_node::type::array));
    return true;
  }
  bool end_array() override {
    m_stack.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    // e.what(): "[json.exception.parse_error.101] parse error at line 3, column 7: ..."
    std::string what = e.what();
    const auto at = what.find("at line ");
    if (at != std::string::npos) what = what.substr(at);
    throw viscor::parse_error(m_file + ": invalid JSON " + what);
  }

 private:
  bool scalar(spec_node::type t, const std::string& text) {
    place(t).text = text;
    return true;
  }
  void refuse_deeper_nesting() const {
    if (m_stack.size() >= max_json_depth)
      throw viscor::parse_error(m_file + ":" + std::to_string(current_line()) + ": JSON nested deeper than " +
                                std::to_string(max_json_depth) + " levels");
  }
  // Line of the last non-blank character the parser has read (a number's
  // look-ahead character is a blank, ',', ']' or '}' on the number's line).
  // Counted on from the previous call (that end never moves back), so reading a
  // file costs time in proportion to its length, not its square.
  std::size_t current_line() const {
    std::size_t end = static_cast<std::size_t>(*m_furthest - m_text.data());
    while (end > m_counted_to && std::isspace(static_cast<unsigned char>(m_text[end - 1]))) --end;
    m_lines_before += static_cast<std::size_t>(
        std::count(m_text.begin() + static_cast<long>(m_counted_to), m_text.begin() + static_cast<long>(end), '\n'));
    m_counted_to = end;
    return 1 + m_lines_before;
  }
  spec_node& place(spec_node::type t) {
    spec_node* n;
    if (m_stack.empty()) {
      n = &root;
    } else if (m_stack.back()->kind == spec_node::type::object) {
      m_stack.back()->members.emplace_back(m_key, spec_node{});
      m_stack.back()->member_lines.push_back(m_key_line);
      n = &m_stack.back()->members.back().second;
    } else {
      m_stack.back()->elements.emplace_back();
      n = &m_stack.back()->elements.back();
    }
    n->kind = t;
    n->line = current_line();
    return *n;
  }

  const std::string& m_text;
  const std::string& m_file;
  const char** m_furthest;
  std::vector<spec_node*> m_stack;  // NOTE: only the innermost open container grows, so these stay valid
  std::string m_key;
  std::size_t m_key_line = 0;
  mutable std::size_t m_counted_to = 0, m_lines_before = 0;  // current_line's count so far
};

/// Field access shared by the readers of JSON files (specs, scenes): every error
/// names the file, the line and the field.
class node_reader {
 public:
  explicit node_reader(const std::string& file) : m_file(file) {}

 protected:
  [[noreturn]] void fail(const spec_node& n, const std::string& field, const std::string& message) const {
    throw parse_error(m_file + ":" + std::to_string(n.line) + ": field " + field + ": " + message);
  }
  std::string string(const spec_node& n, const std::string& field) const {
    if (n.kind != spec_node::type::string) fail(n, field, "must be a string, got " + n.type_name());
    return n.text;
  }
  // A number given as a JSON number or a string: its exact text.
  std::string number_text(const spec_node& n, const std::string& field) const {
    if (n.kind != spec_node::type::number && n.kind != spec_node::type::string)
      fail(n, field, "must be a number (or a string holding one), got " + n.type_name());
    if (!viscor::detail::looks_like_decimal(n.text))
      fail(n, field, "must be a finite decimal number, got '" + n.text + "'");
    return n.text;
  }

  std::string m_file;
};

}  // namespace detail

/// A table spec as read from its file: the grid, and whether its method is "proven".
struct table_spec {
  grid_spec grid;       ///< with method certify when `proven`; no gamma and g axes when `physical`
  bool proven = false;  ///< "method": "proven": each row certified, then proven (table_format.hpp)
  std::string method_where;  ///< where "method" was given ("spec.json:7"), for errors
  /// The physical axes (beads, walls, v0, gravity, force, gamma0), when the spec is in SI.
  std::optional<physical_axes> physical;
};

namespace detail {

/// Interprets the tree as a table_spec.
class spec_reader : public node_reader {
 public:
  using node_reader::node_reader;

  table_spec read(const spec_node& root) {
    table_spec result;
    grid_spec& spec = result.grid;
    if (root.kind != spec_node::type::object) fail(root, "spec", "the spec must be a JSON object");
    spec.source = m_file;
    bool have_laws = false;
    const spec_node* digits_node = nullptr;
    std::vector<const std::pair<std::string, spec_node>*> physical_nodes;
    for (std::size_t i = 0; i < root.members.size(); ++i) {
      const auto& [key, node] = root.members[i];
      if (key == "description" || key == "comment") {
        spec.description = key == "description" ? string(node, key) : spec.description;
      } else if (key == "laws" || key == "law") {
        if (have_laws) fail(node, key, "give either 'law' or 'laws', not both");
        have_laws = true;
        spec.laws = laws(node, key);
      } else if (key == "gamma") {
        spec.gamma = axis(node, key);
      } else if (key == "g") {
        spec.g = axis(node, key);
      } else if (key == "digits") {
        spec.digits = integer(node, key, 1, max_working_digits);
        digits_node = &node;
      } else if (key == "certified_digits") {
        spec.certified_digits = integer(node, key, 1, max_working_digits - default_safety_margin - 1);
      } else if (key == "method") {
        const std::string m = string(node, key);
        result.method_where = m_file + ":" + std::to_string(node.line);
        result.proven = m == "proven";
        if (m == "auto") spec.method = row_method::automatic;
        else if (m == "exact") spec.method = row_method::exact;
        else if (m == "certify" || m == "proven") spec.method = row_method::certify;
        else fail(node, key, "must be \"auto\", \"exact\", \"certify\" or \"proven\", got \"" + m + "\"");
      } else if (key == "min_digits") {
        spec.min_digits = integer(node, key, 0, max_working_digits);
      } else if (key == "solve_for") {
        const std::string v = string(node, key);
        if (v == "g") spec.solve_for = threshold_variable::g;
        else if (v == "gamma") spec.solve_for = threshold_variable::gamma;
        else fail(node, key, "must be \"g\" or \"gamma\", got \"" + v + "\"");
      } else if (key == "threshold_digits") {
        spec.threshold_digits = integer(node, key, 1, max_working_digits);
      } else if (is_physical_field(key)) {
        physical_nodes.push_back(&root.members[i]);
      } else {
        throw parse_error(m_file + ":" + std::to_string(root.member_lines[i]) + ": field " + key +
                          ": unknown field (known: description, laws, gamma, g, digits, certified_digits, method, "
                          "min_digits, solve_for, threshold_digits; in SI: beads, contact, walls, other, v0, "
                          "gravity, force, gamma0, target_e)");
      }
    }
    if (!physical_nodes.empty()) result.physical = physical(root, physical_nodes, result);
    if (spec.certified_digits > 0) {  // the working precision is chosen (certify/certified_digits_goal.hpp)
      if (digits_node)
        fail(*digits_node, "digits", "give either digits (the working precision) or certified_digits (the working "
                                     "precision is then chosen), not both");
      spec.digits = first_working_digits(spec.certified_digits);
    }
    if (!have_laws) fail(root, "laws", "missing: list the contact laws, e.g. \"laws\": [\"linear\", \"tsuji\"]");
    validate(spec);  // digits, min_digits, laws
    expand(spec);    // every axis error (bad numbers, gamma < 0, non-terminating steps) before any work
    if (result.physical) expand(*result.physical);
    return result;
  }

 private:
  static bool is_physical_field(const std::string& key) {
    for (const char* k : {"beads", "contact", "walls", "other", "v0", "gravity", "force", "gamma0", "target_e"})
      if (key == k) return true;
    return false;
  }

  // A name for the rows: letters, digits and _ . + -, so that it needs no quoting in CSV.
  std::string row_name(const spec_node& n, const std::string& field) const {
    const std::string s = string(n, field);
    if (s.empty() || s.size() > 64 ||
        s.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.+-") != std::string::npos)
      fail(n, field, "must be 1 to 64 letters, digits, '_', '.', '+' or '-', got \"" + s + "\"");
    return s;
  }

  // A bead: (m, k), or a material (youngs_modulus, poisson_ratio, radius, and m or density).
  physical_bead bead(const spec_node& n, const std::string& field, bool named) const {
    if (n.kind != spec_node::type::object) fail(n, field, "a bead is an object, got " + n.type_name());
    physical_bead b;
    b.where = m_file + ":" + std::to_string(n.line);
    for (std::size_t i = 0; i < n.members.size(); ++i) {
      const auto& [key, value] = n.members[i];
      const std::string f = field + "." + key;
      if (key == "name" && named) b.name = row_name(value, f);
      else if (key == "m") b.m = number_text(value, f);
      else if (key == "k") b.k = number_text(value, f);
      else if (key == "youngs_modulus") b.youngs_modulus = number_text(value, f);
      else if (key == "poisson_ratio") b.poisson_ratio = number_text(value, f);
      else if (key == "radius") b.radius = number_text(value, f);
      else if (key == "density") b.density = number_text(value, f);
      else
        throw parse_error(m_file + ":" + std::to_string(n.member_lines[i]) + ": field " + f + ": unknown field (a " +
                          (named ? "bead has name, and m and k, or youngs_modulus, poisson_ratio, radius and m or "
                                   "density"
                                 : "second bead has youngs_modulus, poisson_ratio, radius and density") + ")");
    }
    const bool material = b.youngs_modulus || b.poisson_ratio || b.radius || b.density;
    if (!named) {  // the pair's other bead is a material with its own density
      if (!b.youngs_modulus || !b.poisson_ratio || !b.radius || !b.density || b.m || b.k)
        fail(n, field, "the second bead needs youngs_modulus, poisson_ratio, radius and density");
      return b;
    }
    if (material) {
      if (b.k) fail(n, field, "give the stiffness either as k or as youngs_modulus, poisson_ratio and radius, not both");
      if (!b.youngs_modulus || !b.poisson_ratio || !b.radius)
        fail(n, field, "a bead of a material needs youngs_modulus, poisson_ratio and radius");
      if (b.m.has_value() == b.density.has_value()) fail(n, field, "a bead of a material needs either m or density");
    } else if (!b.m || !b.k) {
      fail(n, field, "a bead needs m and k, or youngs_modulus, poisson_ratio, radius and m or density");
    }
    return b;
  }

  physical_wall wall(const spec_node& n, const std::string& field) const {
    physical_wall w;
    w.where = m_file + ":" + std::to_string(n.line);
    if (n.kind == spec_node::type::string) {
      if (n.text != "rigid") fail(n, field, "a wall is \"rigid\" or an object with youngs_modulus and poisson_ratio");
      return w;
    }
    if (n.kind != spec_node::type::object)
      fail(n, field, "a wall is \"rigid\" or an object with youngs_modulus and poisson_ratio, got " + n.type_name());
    w.name.clear();
    for (std::size_t i = 0; i < n.members.size(); ++i) {
      const auto& [key, value] = n.members[i];
      const std::string f = field + "." + key;
      if (key == "name") {
        w.name = row_name(value, f);
        if (w.name == "rigid") fail(value, f, "\"rigid\" names the rigid wall, not a wall of a material");
      } else if (key == "youngs_modulus") w.youngs_modulus = number_text(value, f);
      else if (key == "poisson_ratio") w.poisson_ratio = number_text(value, f);
      else
        throw parse_error(m_file + ":" + std::to_string(n.member_lines[i]) + ": field " + f +
                          ": unknown field (a wall has name, youngs_modulus and poisson_ratio)");
    }
    if (!w.youngs_modulus || !w.poisson_ratio) fail(n, field, "a wall of a material needs youngs_modulus and poisson_ratio");
    return w;
  }

  // A list of named things (beads, walls): unnamed ones are called PREFIX + their position.
  template <class Thing, class Read>
  std::vector<Thing> named_list(const spec_node& n, const std::string& field, const std::string& prefix,
                                Read read) const {
    std::vector<const spec_node*> nodes;
    if (n.kind == spec_node::type::array) {
      if (n.elements.empty()) fail(n, field, "give at least one");
      for (const auto& e : n.elements) nodes.push_back(&e);
    } else {
      nodes.push_back(&n);
    }
    std::vector<Thing> all;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const std::string f = field + "[" + std::to_string(i) + "]";
      Thing t = read(*nodes[i], f);
      if (t.name.empty()) t.name = prefix + std::to_string(i);
      for (const auto& seen : all)
        if (seen.name == t.name) fail(*nodes[i], f + ".name", "\"" + t.name + "\" is given twice");
      all.push_back(std::move(t));
    }
    return all;
  }

  // The physical axes; the scaled gamma and g then follow from each row.
  physical_axes physical(const spec_node& root,
                         const std::vector<const std::pair<std::string, spec_node>*>& nodes,
                         const table_spec& table) const {
    const grid_spec& spec = table.grid;
    physical_axes a;
    const spec_node* walls_node = nullptr;
    const spec_node* other_node = nullptr;
    for (const auto* member : nodes) {
      const auto& [key, node] = *member;
      if (key == "beads") {
        a.beads = named_list<physical_bead>(node, key, "bead",
                                            [&](const spec_node& x, const std::string& f) { return bead(x, f, true); });
      } else if (key == "contact") {
        a.contact = string(node, key);
        if (a.contact != "wall" && a.contact != "pair") fail(node, key, "must be \"wall\" or \"pair\", got \"" + a.contact + "\"");
      } else if (key == "walls") {
        walls_node = &node;
        a.walls = named_list<physical_wall>(node, key, "wall",
                                            [&](const spec_node& x, const std::string& f) { return wall(x, f); });
      } else if (key == "other") {
        other_node = &node;
        a.other = bead(node, key, false);
      } else {
        grid_axis& axis = key == "v0"        ? a.v0
                          : key == "gravity" ? a.gravity
                          : key == "force"   ? a.force
                          : key == "gamma0"  ? a.gamma0
                                             : a.target_e;
        axis = this->axis(node, key);
      }
    }
    if (a.beads.empty()) fail(root, "beads", "missing: a spec in SI lists its beads, e.g. \"beads\": [{\"name\": "
                                               "\"steel\", \"youngs_modulus\": 2e11, \"poisson_ratio\": 0.3, "
                                               "\"radius\": 0.005, \"density\": 7850}]");
    if (a.v0.empty()) fail(root, "v0", "missing: the impact speeds (m/s)");
    if (a.gamma0.empty() == a.target_e.empty())
      fail(root, "gamma0", a.gamma0.empty() ? "missing: the damping coefficients gamma0 (SI), or the CoRs target_e "
                                                "to calibrate the damping to"
                                              : "give either gamma0 or target_e (the damping is then calibrated), "
                                                "not both");
    if (a.gravity.empty())
      fail(root, "gravity", "missing: the gravities (m/s^2 towards the wall; 0 for none): the load changes the "
                              "result, so it never defaults");
    if (!spec.gamma.empty() || !spec.g.empty())
      fail(root, !spec.gamma.empty() ? "gamma" : "g",
             "a spec in SI gives v0, gravity and gamma0; the scaled gamma and g follow from each row");
    if (walls_node && a.contact == "pair")
      fail(*walls_node, "walls", "a pair of beads has no wall (contact \"pair\")");
    if (other_node && a.contact != "pair") fail(*other_node, "other", "the second bead belongs to contact \"pair\"");
    if (a.walls.empty()) a.walls.push_back(physical_wall{});  // a rigid wall, as viscor cor assumes
    if (a.contact == "pair")
      for (std::size_t i = 0; i < a.beads.size(); ++i)
        if (!a.beads[i].youngs_modulus)
          fail(root, "beads[" + std::to_string(i) + "]", "a pair of beads needs each bead as a material");
    if (spec.threshold_digits > 0) fail(root, "threshold_digits", "a spec in SI is a CoR table, not sticking thresholds");
    if (table.proven || spec.method == row_method::exact)
      throw parse_error(table.method_where + ": field method: a spec in SI is certified row by row (\"auto\" or "
                        "\"certify\"); a proof or a closed form needs the exact scaled inputs");
    return a;
  }

  long long integer(const spec_node& n, const std::string& field, long long lo, long long hi) const {
    const std::string t = n.kind == spec_node::type::number ? n.text : std::string("x");
    if (t.empty() || t.size() > 15 || t.find_first_not_of("0123456789-") != std::string::npos ||
        t.find('-', 1) != std::string::npos || t == "-")
      fail(n, field, "must be an integer, got " + (n.kind == spec_node::type::number ? "'" + n.text + "'" : n.type_name()));
    const long long v = std::stoll(t);
    if (v < lo || v > hi)
      fail(n, field, "must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + t);
    return v;
  }

  contact_law law(const spec_node& n, const std::string& field) const {
    try {
      if (n.kind == spec_node::type::string) return law_by_name(n.text);
      if (n.kind != spec_node::type::object)
        fail(n, field, "must be a law name or an object {\"alpha\": ..., \"beta\": ...}, got " + n.type_name());
      std::string alpha, beta;
      const spec_node *alpha_node = nullptr, *beta_node = nullptr;
      for (std::size_t i = 0; i < n.members.size(); ++i) {
        const auto& [key, value] = n.members[i];
        if (key != "alpha" && key != "beta")
          throw parse_error(m_file + ":" + std::to_string(n.member_lines[i]) + ": field " + field + "." + key +
                            ": unknown field (a custom law has alpha and beta)");
        if (value.kind != spec_node::type::number && value.kind != spec_node::type::string)
          fail(value, field + "." + key, "must be a number or a fraction \"p/q\", got " + value.type_name());
        (key == "alpha" ? alpha : beta) = value.text;
        (key == "alpha" ? alpha_node : beta_node) = &value;
      }
      if (!alpha_node || !beta_node) fail(n, field, "a custom law needs both alpha and beta");
      exponent a, b;
      try {
        a = exponent::parse(alpha, "alpha");
      } catch (const invalid_parameter& e) {
        fail(*alpha_node, field + ".alpha", e.what());
      }
      try {
        b = exponent::parse(beta, "beta");
      } catch (const invalid_parameter& e) {
        fail(*beta_node, field + ".beta", e.what());
      }
      if (!a.at_least_one()) fail(*alpha_node, field + ".alpha", "must be >= 1, got " + alpha);
      if (!b.at_least_one()) fail(*beta_node, field + ".beta", "must be >= 1, got " + beta);
      return make_law(a, b);
    } catch (const parse_error&) {
      throw;
    } catch (const invalid_parameter& e) {
      fail(n, field, e.what());
    }
  }
  std::vector<contact_law> laws(const spec_node& n, const std::string& field) const {
    if (n.kind != spec_node::type::array) return {law(n, field)};
    if (n.elements.empty()) fail(n, field, "at least one contact law is needed");
    std::vector<contact_law> all;
    for (std::size_t i = 0; i < n.elements.size(); ++i) {
      const std::string f = field + "[" + std::to_string(i) + "]";
      contact_law l = law(n.elements[i], f);
      for (const auto& seen : all)
        if (seen.alpha == l.alpha && seen.beta == l.beta) fail(n.elements[i], f, "this law is listed twice");
      all.push_back(std::move(l));
    }
    return all;
  }

  axis_item item(const spec_node& n, const std::string& field) const {
    axis_item it;
    it.where = m_file + ":" + std::to_string(n.line);
    if (n.kind != spec_node::type::object) {
      it.type = axis_item::kind::value;
      it.from = number_text(n, field);
      return it;
    }
    std::string spacing = "linear";
    bool have_from = false, have_to = false, have_count = false, have_digits = false;
    for (std::size_t i = 0; i < n.members.size(); ++i) {
      const auto& [key, value] = n.members[i];
      const std::string f = field + "." + key;
      it.field_where[key] = m_file + ":" + std::to_string(value.line);
      if (key == "from") it.from = number_text(value, f), have_from = true;
      else if (key == "to") it.to = number_text(value, f), have_to = true;
      else if (key == "step") it.step = number_text(value, f);
      else if (key == "count") it.count = integer(value, f, 2, max_axis_values), have_count = true;
      else if (key == "spacing") spacing = string(value, f);
      else if (key == "digits") it.log_digits = static_cast<int>(integer(value, f, 1, 30)), have_digits = true;
      else
        throw parse_error(m_file + ":" + std::to_string(n.member_lines[i]) + ": field " + f +
                          ": unknown field (a range has from, to, and count or step; optional spacing "
                          "\"linear\" or \"log\", and digits for log ranges)");
    }
    if (!have_from || !have_to) fail(n, field, "a range needs 'from' and 'to'");
    if (spacing == "linear") {
      it.type = axis_item::kind::linear;
      if (have_count == !it.step.empty()) fail(n, field, "a linear range needs exactly one of 'count' and 'step'");
      if (have_digits) fail(n, field + ".digits", "only log ranges round to digits");
    } else if (spacing == "log") {
      it.type = axis_item::kind::log;
      if (!have_count || !it.step.empty()) fail(n, field, "a log range needs 'count' (and no 'step')");
    } else {
      fail(n, field + ".spacing", "must be \"linear\" or \"log\", got \"" + spacing + "\"");
    }
    return it;
  }
  grid_axis axis(const spec_node& n, const std::string& field) const {
    grid_axis a;
    if (n.kind != spec_node::type::array) {
      a.items.push_back(item(n, field));
      return a;
    }
    if (n.elements.empty()) fail(n, field, "an axis needs at least one value or range");
    for (std::size_t i = 0; i < n.elements.size(); ++i)
      a.items.push_back(item(n.elements[i], field + "[" + std::to_string(i) + "]"));
    return a;
  }
};

}  // namespace detail

/// Parses spec JSON text; `file` names it in errors. Throws viscor::parse_error.
inline table_spec parse_spec_json(const std::string& text, const std::string& file) {
  const char* furthest = text.data();
  detail::counting_iterator first{text.data(), &furthest}, last{text.data() + text.size(), &furthest};
  detail::spec_builder builder(text, file, &furthest);
  nlohmann::json::sax_parse(first, last, &builder);
  return detail::spec_reader(file).read(builder.root);
}

/// Reads a spec file. Throws viscor::error if it cannot be read, parse_error if malformed.
inline table_spec read_spec_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw error("cannot read spec file '" + path + "'");
  std::stringstream s;
  s << in.rdbuf();
  return parse_spec_json(s.str(), path);
}

/// The spec as normalised JSON: what resume and merge compare, and what the
/// sidecar records (source positions and formatting are left out).
inline json spec_to_json(const table_spec& table) {
  const grid_spec& spec = table.grid;
  json j;
  if (!spec.description.empty()) j["description"] = spec.description;
  j["laws"] = json::array();
  for (const auto& law : spec.laws) j["laws"].push_back(law_json(law));
  auto axis_json = [](const grid_axis& axis) {
    json a = json::array();
    for (const auto& it : axis.items) {
      json x;
      if (it.type == axis_item::kind::value) {
        x["value"] = it.from;
      } else {
        x["from"] = it.from, x["to"] = it.to;
        if (it.step.empty()) x["count"] = it.count;
        else x["step"] = it.step;
        x["spacing"] = it.type == axis_item::kind::log ? "log" : "linear";
        if (it.type == axis_item::kind::log) x["digits"] = it.log_digits;
      }
      a.push_back(x);
    }
    return a;
  };
  if (!spec.gamma.empty()) j["gamma"] = axis_json(spec.gamma);
  if (!spec.g.empty()) j["g"] = axis_json(spec.g);
  if (table.physical) {
    const physical_axes& a = *table.physical;
    const auto bead_json = [](const physical_bead& b) {
      json x;
      if (!b.name.empty()) x["name"] = b.name;
      for (const auto& [key, value] : {std::pair{"m", &b.m}, {"k", &b.k}, {"youngs_modulus", &b.youngs_modulus},
                                       {"poisson_ratio", &b.poisson_ratio}, {"radius", &b.radius},
                                       {"density", &b.density}})
        if (*value) x[key] = **value;
      return x;
    };
    j["beads"] = json::array();
    for (const auto& b : a.beads) j["beads"].push_back(bead_json(b));
    j["contact"] = a.contact;
    if (a.contact == "wall") {
      j["walls"] = json::array();
      for (const auto& w : a.walls)
        j["walls"].push_back(!w.youngs_modulus ? json("rigid")
                                               : json{{"name", w.name},
                                                      {"youngs_modulus", *w.youngs_modulus},
                                                      {"poisson_ratio", *w.poisson_ratio}});
    }
    if (a.other) {
      physical_bead other = *a.other;
      other.name.clear();
      j["other"] = bead_json(other);
    }
    j["v0"] = axis_json(a.v0);
    j["gravity"] = axis_json(a.gravity);
    if (!a.force.empty()) j["force"] = axis_json(a.force);
    if (!a.gamma0.empty()) j["gamma0"] = axis_json(a.gamma0);
    if (!a.target_e.empty()) j["target_e"] = axis_json(a.target_e);
  }
  if (spec.certified_digits > 0) j["certified_digits"] = spec.certified_digits;  // digits follows from it
  else j["digits"] = spec.digits;
  j["method"] = table.proven ? std::string("proven") : to_string(spec.method);
  j["min_digits"] = spec.min_digits;
  if (spec.threshold_digits > 0) {
    j["solve_for"] = to_string(spec.solve_for);
    j["threshold_digits"] = spec.threshold_digits;
  }
  return j;
}

/// Reads back a spec that spec_to_json normalised (a table's sidecar records it):
/// `table merge` expands the grid from it to check each row's grid point. The
/// normalised form names a law as {name, alpha, beta} and a single axis value as
/// {"value": v}; the spec reader takes a law's name (or {alpha, beta} for an
/// unnamed one) and the bare value, so those are written back first.
/// `where` names the file in errors. Throws viscor::parse_error.
inline table_spec parse_normalised_spec(json normalised, const std::string& where) {
  if (!normalised.is_object()) throw parse_error(where + ": field spec: not a JSON object");
  if (normalised.contains("laws") && normalised["laws"].is_array())
    for (auto& law : normalised["laws"])
      if (law.is_object() && law.contains("name") && law["name"].is_string()) {
        if (!law["name"].get<std::string>().empty()) law = law["name"];
        else law.erase("name");
      }
  for (const char* axis : {"gamma", "g", "v0", "gravity", "force", "gamma0", "target_e"})
    if (normalised.contains(axis) && normalised[axis].is_array())
      for (auto& item : normalised[axis])
        if (item.is_object() && item.contains("value")) item = item["value"];
  return parse_spec_json(normalised.dump(1), where);
}

}  // namespace viscor::jobs
