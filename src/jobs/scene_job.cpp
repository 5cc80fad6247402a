// The scene job (include/viscor/jobs/scene_job.hpp), compiled once.
#include <viscor/jobs/scene_job.hpp>

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/data_directory.hpp>
#include <viscor/jobs/surrogate_files.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/scenes/error_map.hpp>
#include <viscor/scenes/scene.hpp>
#include <viscor/surrogate/surrogate_source.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

namespace viscor::jobs {

namespace detail {

// Full-precision decimal; double formatted directly (the same text as to_decimal_string, 10x faster).
template <class Real>
std::string full(const Real& x) {
  if constexpr (std::is_same_v<Real, double>) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.16e", x);
    return buffer;
  } else {
    return to_decimal_string(x);
  }
}

template <class Real>
std::string short_number(const Real& x) {
  if constexpr (std::is_same_v<Real, double>) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.2e", x);
    return buffer;
  } else {
    return to_decimal_string(x, 3);
  }
}

inline std::string seconds_text(double s) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.3g", s);
  return buffer;
}

/// The error map of `law` in `dir` (dir/<law name>.csv), if there is one. A directory
/// named by the user (`from` says where) must exist: a typo must not silently turn
/// the approximations off.
inline std::optional<error_map> find_map(const std::string& dir, const std::string& from, const contact_law& law,
                                  std::string& note) {
  if (dir.empty()) {
    note = "none (no --error-maps, scene error_maps, VISCOR_ERROR_MAPS or data directory): approximations not used";
    return std::nullopt;
  }
  if (!std::filesystem::is_directory(dir))
    throw invalid_parameter(from + ": '" + dir + "' is not a directory of error maps" +
                            (std::filesystem::exists(dir) ? " (it is a file)" : " (it does not exist)"));
  if (law.name.empty()) {
    note = "none for a custom law: approximations not used";
    return std::nullopt;
  }
  const std::filesystem::path path = std::filesystem::path(dir) / (law.name + ".csv");
  if (!std::filesystem::exists(path)) {
    note = "none (" + path.string() + " does not exist): approximations not used";
    return std::nullopt;
  }
  note = path.string();
  return read_error_map(path.string());
}

}  // namespace detail

/// Evaluates every impact of `file` (read from `path`, named in the output).
/// `error_maps`: a directory of error maps given by the caller ("" for the scene's
/// error_maps, then $VISCOR_ERROR_MAPS, then the data directory's error_maps).
scene_result run_scene_file(const scene_file& file, const std::string& path, const std::string& error_maps,
                            bool as_json) {
  using namespace detail;
  scene_result result;
  int digits = 0;
  try {
    digits = scene_digits(file.scene.tolerance);
  } catch (const invalid_parameter& e) {
    throw parse_error(file.locate("tolerance") + e.what());
  }
  std::string dir = error_maps, from = VISCOR_FIELD("error_maps");
  if (dir.empty()) dir = file.error_maps, from = file.locate("error_maps") + "field error_maps";
  if (dir.empty())
    if (const char* env = std::getenv("VISCOR_ERROR_MAPS"); env && *env) dir = env, from = "VISCOR_ERROR_MAPS";
  if (dir.empty()) dir = default_error_maps(), from = "the data directory";
  std::string map_note;
  const std::optional<error_map> map = find_map(dir, from, file.scene.law, map_note);
  // The committed surrogate of the law, tried first where its bound meets the tolerance.
  const surrogate::cor_surrogate* fitted = find_surrogate(file.scene.law);
  std::optional<surrogate::surrogate_source> source;
  if (fitted && fitted->bound.verified()) source.emplace(*fitted);
  const std::string surrogate_note = source ? file.scene.law.name + ".surrogate (committed surrogate, tried first)" : "none";

  with_working_precision(digits, [&]<class Real>() {
    const auto start = std::chrono::steady_clock::now();
    resolved_scene<Real> s;
    try {
      s = resolve_scene<Real>(file.scene);
    } catch (const exponent_range_exceeded&) {
      throw;  // with_working_precision retries in a wider type
    } catch (const invalid_parameter& e) {
      throw parse_error(file.locate(e.what()) + e.what());
    }
    const auto resolved = std::chrono::steady_clock::now();

    std::string csv;
    json rows = json::array();
    std::map<std::string, std::size_t> methods;
    std::size_t index = 0, sticking = 0;
    double evaluation_seconds = 0;
    Real worst_bound = 0;
    if (!as_json) {
      csv.reserve(s.velocities.size() * 200);
      csv += std::string("index,v0,gamma,g,outcome,sticking,e,one_minus_e,contact_time_s,") +
             (s.relative ? field::empirical_bound_relative : field::empirical_bound) +
             ",method,working_digits,seconds\n";
    }
    run_scene(s, map ? &*map : nullptr, [&](const scene_row<Real>& row) {
      const evaluation<Real>& r = row.result;
      const bool stuck = r.outcome == impact_outcome::stick;
      ++methods[to_string(r.method)];
      sticking += stuck;
      evaluation_seconds += r.seconds;
      if (r.bound > worst_bound) worst_bound = r.bound;
      const std::string t = row.contact_time ? full(*row.contact_time) : std::string();
      if (as_json) {
        json j;
        j["index"] = index, j["v0"] = full(row.v0), j["gamma"] = full(row.gamma), j["g"] = full(row.g);
        j[field::outcome] = std::string(to_string(r.outcome)), j["sticking"] = stuck;
        j[field::e] = full(r.e), j[field::one_minus_e] = full(r.one_minus_e);
        j[field::contact_time_s] = row.contact_time ? json(t) : json(nullptr);
        j[s.relative ? field::empirical_bound_relative : field::empirical_bound] = short_number(r.bound);
        j[field::method] = to_string(r.method), j[field::working_digits] = r.working_digits;
        j[field::seconds] = r.seconds;
        rows.push_back(std::move(j));
      } else {
        csv += std::to_string(index) + ',' + full(row.v0) + ',' + full(row.gamma) + ',' + full(row.g) + ',' +
               std::string(to_string(r.outcome)) + ',' + (stuck ? "true" : "false") + ',' + full(r.e) + ',' +
               full(r.one_minus_e) + ',' + t + ',' + short_number(r.bound) + ',' + to_string(r.method) +
               ',' + std::to_string(r.working_digits) + ',' + seconds_text(r.seconds) + '\n';
      }
      ++index;
    }, source ? &*source : nullptr);
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double resolve_seconds = std::chrono::duration<double>(resolved - start).count();

    std::ostringstream method_text;
    json method_json;
    for (const auto& [m, n] : methods) {
      method_text << " " << m << " " << n;
      method_json[m] = n;
    }
    std::ostringstream summary;
    summary << "scene      " << path << (file.description.empty() ? "" : " (" + file.description + ")") << "\n"
            << "law        " << s.law.describe() << "\n"
            << "bead       m = " << to_decimal_string(s.mass, 8) << " kg, k = " << to_decimal_string(s.stiffness, 8)
            << (s.stiffness_from_material ? " N/m^1.5 (Hertz, from the materials)" : "") << "\n"
            << "damping    gamma0 = " << to_decimal_string(s.gamma0, 12);
    if (s.calibration)
      summary << " (calibrated: e = " << *file.scene.measured_e << " at v0 = " << *file.scene.measured_speed
              << " m/s, gravity " << *file.scene.measured_gravity << " at " << s.calibration->working_digits
              << " digits: scaled gamma " << s.calibration->gamma << " at g " << s.calibration->g
              << ", |e - measured| <= " << s.calibration->target_bound << ")";
    summary << "\n"
            << "load       gravity = " << file.scene.gravity << " m/s^2, force = " << file.scene.force << " N\n"
            << "impacts    " << index << " at tolerance " << file.scene.tolerance
            << (s.relative ? " (relative on 1 - e)" : " (absolute on e)") << ", " << decimal_digits<Real>()
            << " working digits\n"
            << "error map  " << map_note << "\n"
            << "surrogate  " << surrogate_note << "\n"
            << "methods   " << method_text.str() << "\n"
            << "sticking   " << sticking << "\n"
            << "max empirical bound  " << to_decimal_string(worst_bound, 3) << "\n"
            << "time       " << seconds_text(total) << " s (" << seconds_text(evaluation_seconds)
            << " s evaluating, " << seconds_text(resolve_seconds) << " s resolving the scene)\n";

    std::string body;
    if (as_json) {
      json j;
      j["command"] = "scene";
      j["file"] = path;
      j["law"] = law_json(s.law);
      json physical;
      physical["m"] = full(s.mass), physical["k"] = full(s.stiffness), physical["gamma0"] = full(s.gamma0);
      physical["gravity"] = file.scene.gravity, physical["force"] = file.scene.force;
      j["physical"] = physical;
      if (s.calibration) {
        json c;
        c["measured_e"] = *file.scene.measured_e, c["v0"] = *file.scene.measured_speed;
        c["gravity"] = *file.scene.measured_gravity;
        c["force"] = file.scene.measured_force ? *file.scene.measured_force : std::string("0");
        c["gamma0"] = s.calibration->gamma0;
        c["gamma"] = s.calibration->gamma, c["g"] = s.calibration->g;
        c[field::target_bound] = s.calibration->target_bound;
        c["precision"] = json{{"digits", s.calibration->working_digits}};
        j["calibration"] = c;
      }
      j["tolerance"] = file.scene.tolerance;
      j["bound"] = s.relative ? "relative_one_minus_e" : "absolute";
      j["precision"] = scalar_json<Real>(digits);
      j["error_map"] = map_note;
      j["surrogate"] = surrogate_note;
      j["impacts"] = index, j["sticking_impacts"] = sticking, j["methods"] = method_json;
      j[field::seconds] = total;
      j["rows"] = std::move(rows);
      body = j.dump(1) + "\n";
    result.object = std::move(j);
    } else {
      body = std::move(csv);
    }
    result.body = std::move(body);
    result.summary = summary.str();
  });
  return result;
}

}  // namespace viscor::jobs
