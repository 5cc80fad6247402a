// A CoR surrogate built from a spec (docs/surrogate.md), as `viscor surrogate
// build` builds it: the fit (kept in FILE.fit for resume and shards), the
// verification points drawn after the fit with a fixed seed and certified by the
// table machinery (a CoR table FILE.verification.csv: resumable, shardable, merged
// by the table merge), the comparison, and FILE and FILE.json written only if the
// stated bounds (measured maximum x safety factor) meet the spec's targets.
#pragma once

#include <viscor/jobs/files.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/provenance.hpp>
#include <viscor/jobs/surrogate_files.hpp>
#include <viscor/jobs/table_runner.hpp>

#include <viscor/config.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/surrogate/surrogate_fit.hpp>
#include <viscor/surrogate/surrogate_verify.hpp>
#include <viscor/tables/grid_spec.hpp>
#include <viscor/tables/reference_table.hpp>
#include <viscor/tables/table_row.hpp>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace viscor::jobs {

/// A build: the spec file, the surrogate file to write, and how to run the verification table.
struct surrogate_build_request {
  std::string spec_path;         ///< the build spec, JSON
  std::string output;            ///< the surrogate file (with FILE.json and FILE.verification.csv)
  std::string shard;             ///< "i/N": only shard i of N of the verification table; "" for all
  bool resume = false;           ///< continue an interrupted verification table (and reuse the fit)
  bool quiet = false;            ///< no progress output
  int threads = 1;               ///< threads of the verification table
  bool handle_signals = false;          ///< install the Ctrl-C handler (the command-line tool asks for it)
  long long stop_after_rows = -1;       ///< test seam: interrupt after this many rows (-1 never)
  std::function<bool()> should_stop;    ///< polled between rows: true stops with the finished rows kept
};

/// The build spec (docs/surrogate.md).
struct surrogate_spec {
  surrogate::fit_settings fit;
  surrogate::surrogate_targets targets;
  std::size_t points = 20000;
  std::uint64_t seed = 14;
  int digits = 33;            ///< working digits of the certified verification values
  int min_certified_digits = 25;
  double safety_factor = 2;
  json normalised;
};

/// Reads and checks a surrogate build spec (docs/surrogate.md); errors name the file and field.
inline surrogate_spec read_surrogate_spec(const std::string& path) {
  using namespace viscor::surrogate;
  json j;
  try {
    j = read_json_file(path);
  } catch (const json::exception& e) {
    throw parse_error(path + ": not valid JSON: " + e.what());
  }
  if (!j.is_object()) throw parse_error(path + ": a surrogate spec is a JSON object");
  surrogate_spec s;
  auto field = [&](const char* name) -> const json* { return j.contains(name) ? &j[name] : nullptr; };
  auto number = [&](const char* name, double& out) {
    if (const json* v = field(name)) {
      if (!v->is_number()) throw parse_error(path + ": field " + name + ": must be a number, got " + v->dump());
      out = v->get<double>();
    }
  };
  auto integer = [&](const char* name, auto& out) {
    if (const json* v = field(name)) {
      if (!v->is_number_integer() || v->get<long long>() < 0)
        throw parse_error(path + ": field " + name + ": must be a non-negative integer, got " + v->dump());
      out = static_cast<std::remove_reference_t<decltype(out)>>(v->get<long long>());
    }
  };
  for (auto it = j.begin(); it != j.end(); ++it) {
    static const std::set<std::string> known{"description", "law", "gamma_max", "g_min", "g_max", "gamma_ext",
                                             "order", "threshold_order", "threshold_power", "fit_fraction", "truth", "points", "seed",
                                             "digits", "min_certified_digits", "safety_factor", "targets", "comment"};
    if (!known.count(it.key())) throw parse_error(path + ": field " + it.key() + ": unknown field");
  }
  const json* law = field("law");
  if (!law) throw parse_error(path + ": field law: missing (a named law or {\"alpha\": A, \"beta\": B})");
  if (law->is_string()) {
    s.fit.law = law_by_name(law->get<std::string>());
  } else if (law->is_object() && law->contains("alpha") && law->contains("beta")) {
    auto text = [](const json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); };
    s.fit.law = make_law(exponent::parse(text((*law)["alpha"]), "alpha"), exponent::parse(text((*law)["beta"]), "beta"));
  } else {
    throw parse_error(path + ": field law: must be a law name or {\"alpha\": A, \"beta\": B}, got " + law->dump());
  }
  number("gamma_max", s.fit.gamma_max);
  number("g_min", s.fit.g_min);
  number("g_max", s.fit.g_max);
  number("gamma_ext", s.fit.gamma_ext);
  integer("order", s.fit.order);
  integer("threshold_order", s.fit.threshold_order);
  number("threshold_power", s.fit.threshold_power);
  if (!(s.fit.threshold_power >= 0 && s.fit.threshold_power <= 10))
    throw parse_error(path + ": field threshold_power: must be in [0, 10], got " + std::to_string(s.fit.threshold_power));
  number("fit_fraction", s.fit.fit_fraction);
  if (const json* t = field("truth")) {
    if (*t != "long double" && *t != "double")
      throw parse_error(path + ": field truth: must be \"long double\" or \"double\", got " + t->dump());
    s.fit.long_double_truth = *t == "long double";
  }
  integer("points", s.points);
  integer("seed", s.seed);
  integer("digits", s.digits);
  integer("min_certified_digits", s.min_certified_digits);
  number("safety_factor", s.safety_factor);
  if (const json* t = field("targets")) {
    if (!t->is_object()) throw parse_error(path + ": field targets: must be an object");
    for (auto it = t->begin(); it != t->end(); ++it) {
      if (!it->is_number() || !(it->get<double>() > 0))
        throw parse_error(path + ": field targets." + it.key() + ": must be a positive number, got " + it->dump());
      const double v = it->get<double>();
      if (it.key() == "abs_e") s.targets.abs_e = v;
      else if (it.key() == "abs_e_squared") s.targets.abs_e_squared = v;
      else if (it.key() == "rel_one_minus_e") s.targets.rel_one_minus_e = v;
      else if (it.key() == "small_gamma") s.targets.small_gamma = v;
      else throw parse_error(path + ": field targets." + it.key() + ": unknown target");
    }
  }
  if (s.points < 10) throw parse_error(path + ": field points: at least 10 verification points, got " + std::to_string(s.points));
  if (s.digits < 20 || s.digits > 1000) throw parse_error(path + ": field digits: must be 20..1000, got " + std::to_string(s.digits));
  if (!(s.safety_factor >= 1)) throw parse_error(path + ": field safety_factor: must be >= 1");
  if (!(s.fit.fit_fraction > 0 && s.fit.fit_fraction <= 1)) throw parse_error(path + ": field fit_fraction: must be in (0, 1]");
  if (!(s.fit.g_min < 0 && s.fit.g_max > 1 && s.fit.gamma_max > 0))
    throw parse_error(path + ": fields g_min, g_max, gamma_max: need g_min < 0 < 1 < g_max and gamma_max > 0");
  s.normalised = {{"law", law_json(s.fit.law)},
                  {"gamma_max", s.fit.gamma_max}, {"g_min", s.fit.g_min}, {"g_max", s.fit.g_max},
                  {"gamma_ext", s.fit.gamma_ext}, {"order", s.fit.order}, {"threshold_order", s.fit.threshold_order},
                  {"fit_fraction", s.fit.fit_fraction}, {"truth", s.fit.long_double_truth ? "long double" : "double"},
                  {"points", s.points}, {"seed", s.seed}, {"digits", s.digits},
                  {"min_certified_digits", s.min_certified_digits}, {"safety_factor", s.safety_factor},
                  {"targets", {{"abs_e", s.targets.abs_e}, {"abs_e_squared", s.targets.abs_e_squared},
                               {"rel_one_minus_e", s.targets.rel_one_minus_e}, {"small_gamma", s.targets.small_gamma}}}};
  if (s.fit.threshold_power != 0) s.normalised["threshold_power"] = s.fit.threshold_power;
  if (j.contains("description")) s.normalised["description"] = j["description"];
  return s;
}

/// The verification statistics of one region, as the sidecar records them.
inline json region_json(const surrogate::region_errors& r) {
  using namespace viscor::surrogate;
  auto where = [](const surrogate::reference_value& v) { return json{{"gamma", exact_text(v.gamma)}, {"g", exact_text(v.g)}}; };
  return {{"points", r.points}, {"max_abs_e", r.abs_e}, {"max_abs_e_squared", r.abs_e_squared},
          {"max_rel_one_minus_e", r.rel_one_minus_e}, {"wrong_outcomes", r.wrong_outcomes},
          {"exempt_within_1e-10_of_threshold", r.exempt}, {"outside_domain", r.outside_domain},
          {"judged_by_absolute_digits", r.judged_by_absolute_digits}, {"left_out_too_few_digits", r.left_out},
          {"worst_abs_e_at", where(r.worst_e)}, {"worst_abs_e_squared_at", where(r.worst_e_squared)},
          {"worst_rel_one_minus_e_at", where(r.worst_rel)}};
}

namespace detail {

using say_function = std::function<void(const std::string&)>;

/// A fitted surrogate and the record of its fit.
struct fitted_surrogate {
  surrogate::cor_surrogate surrogate;
  json fit;
};

// The fit, kept in FILE.fit (+ FILE.fit.json) so that a resumed build and the shards reuse it.
inline fitted_surrogate fit_or_reuse(const surrogate_spec& spec, const std::string& output, bool resume,
                                     const say_function& say) {
  using namespace viscor::surrogate;
  fit_report report;
  cor_surrogate s;
  json fit_json;
  const std::string fit_file = output + ".fit";
  json fit_key = spec.normalised;
  for (const char* k : {"points", "seed", "digits", "min_certified_digits", "safety_factor", "description"}) fit_key.erase(k);
  fit_key["viscor_version"] = VISCOR_VERSION;
  bool reused = false;
  if (resume && std::filesystem::exists(fit_file) && std::filesystem::exists(fit_file + ".json")) {
    const json meta = read_json_file(fit_file + ".json");
    if (meta.value("fit_spec", json()) == fit_key) {
      s = read_cor_surrogate(fit_file);
      fit_json = meta.value("fit", json());
      reused = true;
      say("reusing the fit in '" + fit_file + "'");
    }
  }
  if (!reused) {
    s = fit_cor_surrogate(spec.fit, spec.targets, report, say);
    fit_json = {{"solves", report.solves}, {"threshold_solves", report.threshold_solves},
                {"patches_low_load", report.patches_low}, {"patches_high_load", report.patches_high},
                {"threshold_intervals", report.threshold_intervals},
                {"unconverged_patches", report.unconverged_patches},
                {"worst_check_over_tolerance", report.worst_check_ratio}, {"seconds", report.seconds},
                {"g_split", s.g_split}, {"git_commit", git_commit()}, {"date", iso_time_utc(std::time(nullptr))}};
    std::ostringstream fitted;
    write_cor_surrogate(fitted, s);
    const json fit_side{{"what", "unverified fit (viscor surrogate build); reused by --resume"},
                        {"fit_spec", fit_key},
                        {"fit", fit_json}};
    write_together({{fit_file, fitted.str()}, {fit_file + ".json", fit_side.dump(2) + "\n"}});
    say("fit: " + std::to_string(report.patches_low) + " + " + std::to_string(report.patches_high) + " patches, " +
        std::to_string(report.solves) + " solves, " + duration_text(report.seconds));
  }
  return {s, fit_json};
}

// The verification points of this shard, certified by the table machinery into a
// CoR table; returns its path.
inline std::string certify_verification_points(const surrogate_build_request& q, const surrogate_spec& spec,
                                               const surrogate::cor_surrogate& s, const shard& part) {
  using namespace viscor::surrogate;
  const std::string& output = q.output;
  const auto drawn = surrogate::draw_verification_points(s, spec.points, spec.seed);
  auto points = std::make_shared<std::vector<grid_point>>();
  for (std::size_t i = 0; i < drawn.size(); ++i)
    if (part.contains(static_cast<std::int64_t>(i)))
      points->push_back({static_cast<std::int64_t>(i), spec.fit.law, exact_text(drawn[i].gamma), exact_text(drawn[i].g)});
  const std::string table = output + ".verification" +
      (part.whole() ? std::string() : ".shard-" + std::to_string(part.index) + "-of-" + std::to_string(part.count)) + ".csv";
  table_job job = new_table_job(q, table_kind::cor, false, table, static_cast<std::int64_t>(drawn.size()), part,
                                q.spec_path);
  json& p = job.provenance;
  p["spec"] = {{"what", "verification points of a CoR surrogate: fixed-seed random points in five strata "
                        "(surrogate_verify.hpp), drawn after the fit"},
               {"surrogate_spec", spec.normalised}};
  p["scalar"] = {{"requested_digits", spec.digits}};
  p["method"] = {{"requested", "certify"}, {"certify_available", true}};
  table_settings settings{spec.digits, row_method::certify, 0};
  for (const auto& point : *points) job.indices.push_back(point.index);
  job.compute_line = [points, settings](std::size_t i) { return csv_line(compute_row((*points)[i], settings)); };
  run_table_job(job);
  return table;
}

// Compares, states the bounds in s.bound, and refuses (throws) if they miss the
// spec's targets; returns the statistics per region for the sidecar.
inline json state_bounds(surrogate::cor_surrogate& s, const surrogate_spec& spec,
                         const std::vector<surrogate::reference_value>& refs, const std::string& output,
                         const std::string& table) {
  using namespace viscor::surrogate;
  const auto regions = compare_with_reference(s, refs, spec.targets, spec.min_certified_digits);
  const region_errors& all = regions.front();
  s.bound = {all.abs_e * spec.safety_factor, all.abs_e_squared * spec.safety_factor,
             all.rel_one_minus_e * spec.safety_factor, spec.safety_factor};
  json stats;
  for (const auto& r : regions) stats[r.name] = region_json(r);
  stats["rule_below_min_certified_digits"] =
      "a rebound row certified to d < min_certified_digits digits is judged on each check whose uncertainty "
      "(10^(1-d) e in e, about 2 e 10^(1-d) e in e^2, 10^(1-d) relative in 1 - e) is at most 1e-3 of its target; "
      "rows that decide no check are left out and counted (docs/surrogate.md)";
  std::ostringstream summary;
  summary << "verification on " << refs.size() << " certified points (rebound rows below " << spec.min_certified_digits
          << " digits: " << all.judged_by_absolute_digits << " judged by their absolute digits, " << all.left_out
          << " left out):\n";
  for (const auto& r : regions)
    summary << "  " << std::left << std::setw(15) << r.name << std::setw(7) << r.points << " max|de| "
            << std::setprecision(3) << r.abs_e << "  max|de^2| " << r.abs_e_squared << "  max rel d(1-e) "
            << r.rel_one_minus_e << "  wrong outcomes " << r.wrong_outcomes << "  exempt " << r.exempt << "\n";
  summary << "bounds (measured max x " << spec.safety_factor << "): |de| " << s.bound.abs_e << ", |de^2| "
          << s.bound.abs_e_squared << ", rel d(1-e) " << s.bound.rel_one_minus_e << "\n";
  std::cerr << summary.str();
  std::string misses;
  if (s.bound.abs_e > spec.targets.abs_e) misses += " |de| bound above " + exact_text(spec.targets.abs_e) + ";";
  if (s.bound.abs_e_squared > spec.targets.abs_e_squared)
    misses += " |de^2| bound above " + exact_text(spec.targets.abs_e_squared) + ";";
  if (s.bound.rel_one_minus_e > spec.targets.rel_one_minus_e)
    misses += " relative 1 - e bound above " + exact_text(spec.targets.rel_one_minus_e) + ";";
  if (all.wrong_outcomes > 0) misses += " " + std::to_string(all.wrong_outcomes) + " wrong outcomes;";
  if (all.outside_domain > 0) misses += " " + std::to_string(all.outside_domain) + " points outside the domain;";
  if (!misses.empty())
    throw error("surrogate build: the surrogate misses its targets (" + misses.substr(1) + "); not writing '" + output +
                "' (the verification table '" + table + "' is kept)");
  return stats;
}

}  // namespace detail

/// Fits, verifies and writes the surrogate of a build spec; returns false when
/// only a shard of the verification table was computed (nothing written yet).
inline bool build_surrogate(const surrogate_build_request& q) {
  using namespace detail;
  using namespace viscor::surrogate;
  const std::string& output = q.output;
  const auto wall_start = std::chrono::steady_clock::now();
  if (q.spec_path.empty()) throw invalid_parameter("surrogate build needs a spec: viscor surrogate build SPEC.json -o FILE");
  if (output.empty()) throw invalid_parameter("surrogate build needs an output file: -o FILE");
  if (q.threads < 1 || q.threads > 4096)
    throw invalid_parameter(VISCOR_FIELD("threads") " must be from 1 to 4096, got " + std::to_string(q.threads));
  const shard part = q.shard.empty() ? shard{} : shard::parse(q.shard);
  const surrogate_spec spec = read_surrogate_spec(q.spec_path);
  const say_function say = [&](const std::string& m) {
    if (!q.quiet) std::cerr << "viscor surrogate: " << m << std::endl;
  };
  auto [s, fit_json] = fit_or_reuse(spec, output, q.resume, say);
  const std::string table = certify_verification_points(q, spec, s, part);
  if (!part.whole()) {
    say("shard " + part.to_string() + " of the verification table is in '" + table + "'. When every shard is done: "
        "viscor table merge " + output + ".verification.shard-*.csv -o " + output + ".verification.csv, then run "
        "this build again with " VISCOR_FIELD("resume") " to verify and write '" + output + "'");
    return false;
  }
  const json stats = state_bounds(s, spec, read_verification_rows(table), output, table);
  std::ostringstream body;
  write_cor_surrogate(body, s);
  json side;
  side["what"] = "CoR surrogate (viscor::surrogate::cor_surrogate) of " + spec.fit.law.describe();
  side["viscor_version"] = VISCOR_VERSION;
  side["git_commit"] = git_commit();
  side["command"] = command_line();
  side["spec_file"] = q.spec_path;
  side["spec"] = spec.normalised;
  side["fit"] = fit_json;
  side["verification_table"] = std::filesystem::path(table).filename().string();
  side["verification"] = stats;
  side["error_bound"] = {{"kind", "measured maximum over the verification points times the safety factor"},
                         {"safety_factor", spec.safety_factor},
                         {"abs_e", s.bound.abs_e}, {"abs_e_squared", s.bound.abs_e_squared},
                         {"rel_one_minus_e", s.bound.rel_one_minus_e}};
  side["wall_time_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  side["date"] = iso_time_utc(std::time(nullptr));
  side["host"] = host_name();
  write_together({{output, body.str()}, {output + ".json", side.dump(2) + "\n"}});
  say("wrote '" + output + "' and '" + output + ".json'");
  return true;
}

}  // namespace viscor::jobs
