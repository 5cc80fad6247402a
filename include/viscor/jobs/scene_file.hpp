// Reading a scene (scene.hpp) from JSON; the format is documented in docs/scenes.md.
// Numbers keep their source text (the SAX tree of table_spec.hpp), so "0.1" is the
// exact decimal 0.1 at any precision; errors name file, line and field.
#pragma once

#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/jobs/table_spec.hpp>

#include <viscor/scenes/scene.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace viscor::jobs {

/// A parsed scene file: the description, where its fields are, and its options.
struct scene_file {
  scene_description scene;
  std::string error_maps;  ///< directory of error maps named in the file (resolved against the file's directory)
  std::string description;
  std::map<std::string, std::size_t> lines;  ///< field path -> line, for messages
  std::string path;

  /// "FILE:LINE: " for the first field named in `message`, else "FILE: ".
  std::string locate(const std::string& message) const {
    std::size_t best_line = 0, best_length = 0;
    for (const auto& [field, line] : lines) {
      const auto at = message.find(field);
      if (at == std::string::npos || field.size() <= best_length) continue;
      const auto end = at + field.size();
      if (end < message.size() && (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '_'))
        continue;  // "bead.mass" must not match inside "bead.massive"
      best_line = line, best_length = field.size();
    }
    return best_line ? path + ":" + std::to_string(best_line) + ": " : path + ": ";
  }
};

namespace detail {

class scene_reader : public node_reader {
 public:
  using node_reader::node_reader;

  scene_file read(const spec_node& root) {
    scene_file out;
    out.path = m_file;
    if (root.kind != spec_node::type::object) fail(root, "scene", "a scene must be a JSON object");
    scene_description& d = out.scene;
    bool have_law = false, have_tolerance = false, have_gravity = false;
    for (std::size_t i = 0; i < root.members.size(); ++i) {
      const auto& [key, node] = root.members[i];
      out.lines[key] = root.member_lines[i];
      if (key == "description" || key == "comment") {
        out.description = string(node, key);
      } else if (key == "law") {
        d.law = law(node, out);
        have_law = true;
      } else if (key == "bead") {
        bead(node, d, out);
      } else if (key == "wall") {
        wall(node, d, out);
      } else if (key == "contact") {
        const std::string c = string(node, key);
        if (c != "wall" && c != "pair") fail(node, key, "must be \"wall\" or \"pair\", got \"" + c + "\"");
        d.pair = c == "pair";
      } else if (key == "other") {
        other(node, d, out);
      } else if (key == "damping") {
        damping(node, d, out);
      } else if (key == "gravity") {
        d.gravity = number_text(node, key);
        have_gravity = true;
      } else if (key == "force") {
        d.force = number_text(node, key);
      } else if (key == "velocities") {
        velocities(node, d, out);
      } else if (key == "tolerance") {
        d.tolerance = number_text(node, key);
        have_tolerance = true;
      } else if (key == "bound") {
        const std::string b = string(node, key);
        if (b == "absolute") d.relative = false;
        else if (b == "relative_one_minus_e") d.relative = true;
        else fail(node, key, "must be \"absolute\" or \"relative_one_minus_e\", got \"" + b + "\"");
      } else if (key == "contact_time") {
        if (node.kind != spec_node::type::boolean) fail(node, key, "must be true or false, got " + node.type_name());
        d.contact_time = node.flag;
      } else if (key == "error_maps") {
        const std::filesystem::path p = string(node, key);
        out.error_maps = p.is_absolute() ? p.string() : (std::filesystem::path(m_file).parent_path() / p).string();
      } else {
        fail(node, key,
             "unknown field (known: law, bead, wall, contact, other, damping, gravity, force, velocities, "
             "tolerance, bound, contact_time, error_maps, description)");
      }
    }
    if (!have_law) fail(root, "law", "missing (a named law such as \"kuwabara_kono\", or {\"alpha\": .., \"beta\": ..})");
    if (!have_tolerance) fail(root, "tolerance", "missing (the error bound every impact must meet, e.g. 1e-4)");
    if (!have_gravity)
      fail(root, "gravity", "missing (m/s^2 towards the wall, 0 for none): the load changes every CoR, so it never "
                            "defaults");
    return out;
  }

 private:

  /// A field spelt as before 0.2.0: still read, with a warning naming the new spelling.
  void deprecated(const std::string& field, const std::string& spelling) const {
    deprecation_warning(m_file + ": field " + field, spelling);
  }

  template <class F>
  void members(const spec_node& node, const std::string& field, scene_file& out, F&& each) const {
    if (node.kind != spec_node::type::object) fail(node, field, "must be an object, got " + node.type_name());
    for (std::size_t i = 0; i < node.members.size(); ++i) {
      const std::string path = field + "." + node.members[i].first;
      out.lines[path] = node.member_lines[i];
      each(node.members[i].first, node.members[i].second, path);
    }
  }

  contact_law law(const spec_node& node, scene_file& out) const {
    try {
      if (node.kind == spec_node::type::string) return law_by_name(node.text);
      std::string alpha, beta;
      members(node, "law", out, [&](const std::string& key, const spec_node& v, const std::string& path) {
        if (key == "alpha") alpha = exponent_text(v, path);
        else if (key == "beta") beta = exponent_text(v, path);
        else fail(v, path, "unknown field (known: alpha, beta)");
      });
      if (alpha.empty() || beta.empty()) fail(node, "law", "needs both alpha and beta");
      return make_law(exponent::parse(alpha, "law.alpha"), exponent::parse(beta, "law.beta"));
    } catch (const parse_error&) {
      throw;
    } catch (const invalid_parameter& e) {
      fail(node, "law", e.what());
    }
  }

  std::string exponent_text(const spec_node& node, const std::string& field) const {
    if (node.kind != spec_node::type::number && node.kind != spec_node::type::string)
      fail(node, field, "must be a number or a fraction \"p/q\", got " + node.type_name());
    return node.text;
  }

  void bead(const spec_node& node, scene_description& d, scene_file& out) const {
    members(node, "bead", out, [&](const std::string& key, const spec_node& v, const std::string& path) {
      if (key == "m") d.mass = number_text(v, path);
      else if (key == "k") d.stiffness = number_text(v, path);
      else if (key == "mass") deprecated(path, "bead.m"), d.mass = number_text(v, path);
      else if (key == "stiffness") deprecated(path, "bead.k"), d.stiffness = number_text(v, path);
      else if (key == "density") d.density = number_text(v, path);
      else if (key == "radius") d.radius = number_text(v, path);
      else if (key == "youngs_modulus") d.youngs_modulus = number_text(v, path);
      else if (key == "poisson_ratio") d.poisson_ratio = number_text(v, path);
      else fail(v, path, "unknown field (known: m, k, density, radius, youngs_modulus, poisson_ratio)");
    });
  }

  void wall(const spec_node& node, scene_description& d, scene_file& out) const {
    if (node.kind == spec_node::type::string) {
      if (node.text != "rigid") fail(node, "wall", "must be \"rigid\" or {youngs_modulus, poisson_ratio}");
      return;
    }
    members(node, "wall", out, [&](const std::string& key, const spec_node& v, const std::string& path) {
      if (key == "youngs_modulus") d.wall_youngs_modulus = number_text(v, path);
      else if (key == "poisson_ratio") d.wall_poisson_ratio = number_text(v, path);
      else fail(v, path, "unknown field (known: youngs_modulus, poisson_ratio)");
    });
    if (!d.wall_youngs_modulus || !d.wall_poisson_ratio) fail(node, "wall", "needs youngs_modulus and poisson_ratio");
  }

  void other(const spec_node& node, scene_description& d, scene_file& out) const {
    members(node, "other", out, [&](const std::string& key, const spec_node& v, const std::string& path) {
      if (key == "density") d.other_density = number_text(v, path);
      else if (key == "radius") d.other_radius = number_text(v, path);
      else if (key == "youngs_modulus") d.other_youngs_modulus = number_text(v, path);
      else if (key == "poisson_ratio") d.other_poisson_ratio = number_text(v, path);
      else fail(v, path, "unknown field (known: density, radius, youngs_modulus, poisson_ratio)");
    });
    if (!d.other_density || !d.other_radius || !d.other_youngs_modulus || !d.other_poisson_ratio)
      fail(node, "other", "needs density, radius, youngs_modulus and poisson_ratio");
  }

  void damping(const spec_node& node, scene_description& d, scene_file& out) const {
    members(node, "damping", out, [&](const std::string& key, const spec_node& v, const std::string& path) {
      if (key == "gamma0") d.gamma0 = number_text(v, path);
      else if (key == "measured_e") d.measured_e = number_text(v, path);
      else if (key == "v0") d.measured_speed = number_text(v, path);
      else if (key == "speed") deprecated(path, "damping.v0"), d.measured_speed = number_text(v, path);
      else if (key == "gravity") d.measured_gravity = number_text(v, path);
      else if (key == "force") d.measured_force = number_text(v, path);
      else fail(v, path, "unknown field (known: gamma0; or measured_e, v0, gravity, force)");
    });
    const bool measured = d.measured_e || d.measured_speed || d.measured_gravity || d.measured_force;
    if (d.gamma0 && measured) fail(node, "damping", "give gamma0 or a measurement (measured_e, v0, gravity), not both");
    if (!d.gamma0 && !measured) fail(node, "damping", "needs gamma0, or measured_e with v0 and gravity");
    if (measured && !d.measured_e) fail(node, "damping.measured_e", "missing (the measured CoR)");
    if (measured && !d.measured_speed) fail(node, "damping.v0", "missing (the impact speed of the measurement, m/s)");
    if (measured && !d.measured_gravity)
      fail(node, "damping.gravity", "missing (gravity during the measurement, m/s^2; 0 for none): the load changes "
                                    "the calibrated damping");
  }

  void velocities(const spec_node& node, scene_description& d, scene_file& out) const {
    if (node.kind == spec_node::type::array) {
      for (std::size_t i = 0; i < node.elements.size(); ++i) {
        const std::string path = "velocities[" + std::to_string(i) + "]";
        out.lines[path] = node.elements[i].line;
        d.velocities.push_back(number_text(node.elements[i], path));
      }
      if (d.velocities.empty()) fail(node, "velocities", "is empty");
      return;
    }
    bool have_count = false;
    members(node, "velocities", out, [&](const std::string& key, const spec_node& v, const std::string& path) {
      if (key == "from") {
        d.velocity_from = number_text(v, path);
      } else if (key == "to") {
        d.velocity_to = number_text(v, path);
      } else if (key == "count") {
        const std::string t = number_text(v, path);
        if (t.find_first_not_of("0123456789") != std::string::npos || t.size() > 9 || std::stol(t) < 1 ||
            static_cast<std::size_t>(std::stol(t)) > max_scene_impacts)
          fail(v, path, "must be a whole number from 1 to " + std::to_string(max_scene_impacts) + " (the most "
                        "impacts one scene evaluates), got " + t);
        d.velocity_count = static_cast<std::size_t>(std::stol(t));
        have_count = true;
      } else if (key == "spacing") {
        const std::string s = string(v, path);
        if (s == "log") d.velocity_log = true;
        else if (s == "linear") d.velocity_log = false;
        else fail(v, path, "must be \"linear\" or \"log\", got \"" + s + "\"");
      } else {
        fail(v, path, "unknown field (known: from, to, count, spacing)");
      }
    });
    if (!d.velocity_from || !d.velocity_to || !have_count)
      fail(node, "velocities", "a range needs from, to and count");
  }

};

}  // namespace detail

/// Parses scene JSON text; `file` names it in errors. Throws viscor::parse_error.
inline scene_file parse_scene_json(const std::string& text, const std::string& file) {
  const char* furthest = text.data();
  detail::counting_iterator first{text.data(), &furthest}, last{text.data() + text.size(), &furthest};
  detail::spec_builder builder(text, file, &furthest);
  nlohmann::json::sax_parse(first, last, &builder);
  return detail::scene_reader(file).read(builder.root);
}

/// Reads a scene file (see parse_scene_json).
inline scene_file read_scene_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw error("cannot read scene file '" + path + "'");
  std::ostringstream s;
  s << in.rdbuf();
  return parse_scene_json(s.str(), path);
}

}  // namespace viscor::jobs
