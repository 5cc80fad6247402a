// `viscor bench` (include/viscor/jobs/bench_job.hpp), compiled once.
#include <viscor/jobs/bench_job.hpp>

#include <viscor/core/field_names.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/text_fields.hpp>
#include <viscor/jobs/data_directory.hpp>
#include <viscor/jobs/surrogate_files.hpp>
#include <viscor/approx/approximations.hpp>
#include <viscor/certify/certification.hpp>
#include <viscor/impact/solve_impact.hpp>
#include <viscor/scenes/error_map.hpp>
#include <viscor/scenes/evaluate.hpp>
#include <viscor/surrogate/surrogate_source.hpp>
#include <viscor/surrogate/surrogate_timing.hpp>
#include <viscor/tables/reference_table.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <tuple>

namespace viscor::jobs {

namespace detail::bench {

using clock_type = std::chrono::steady_clock;

struct bench_point {
  contact_law law;
  std::string gamma, g;
  std::string e_table;  // certified, from the table
  int table_digits = 0;
  std::string e_ref;  // at the reference precision, checked against e_table
};

// The table row of (law, gamma, g): e and its certified digits.
std::pair<std::string, int> table_value(const csv_table& t, const std::string& file, const contact_law& law,
                                        const std::string& gamma, const std::string& g) {
  const auto& cols = table_columns(table_kind::cor);
  auto col = [&](const char* name) { return static_cast<std::size_t>(std::find(cols.begin(), cols.end(), name) - cols.begin()); };
  for (const auto& row : t.rows)
    if (row.fields[col("alpha")] == law.alpha.to_string() && row.fields[col("beta")] == law.beta.to_string() &&
        row.fields[col("gamma")] == gamma && row.fields[col("g")] == g)
      return {row.fields[col(field::e)], std::stoi(row.fields[col(field::certified_digits_column)])};
  throw invalid_parameter(VISCOR_FIELD("table")
                          " " + file + " has no row for " + law.describe() + ", gamma = " + gamma +
                          ", g = " + g + " (the bench's point set)");
}

// One method, prepared at a point: `compute` is what is timed (inputs parsed and
// per-law constants built beforehand, as a caller in a loop would have them);
// `text` gives the last result as decimal text. nullopt: does not apply there.
struct prepared {
  std::function<void()> compute;
  std::function<std::string()> text;
};

struct bench_method {
  std::string name, precision;
  std::function<std::optional<prepared>(const bench_point&)> prepare;
};

// Seconds per call of f: repeated until min_time has passed (at least once).
template <class F>
double time_per_call(F&& f, double min_time) {
  int calls = 0;
  const auto start = clock_type::now();
  double elapsed = 0;
  do {
    f();
    ++calls;
    elapsed = std::chrono::duration<double>(clock_type::now() - start).count();
  } while (elapsed < min_time);
  return elapsed / calls;
}

// Taylor in Real (for mpfr_real: at the precision current when called).
template <class Real>
prepared taylor_at(const bench_point& p) {
  struct state {
    contact_law law;
    Real gamma, g, e;
  };
  auto st = std::make_shared<state>(state{p.law, parse_real<Real>(p.gamma, "gamma"), parse_real<Real>(p.g, "g"), Real(0)});
  return {[st] { st->e = solve_impact(st->law, st->gamma, st->g).e; }, [st] { return to_decimal_string(st->e); }};
}

#if VISCOR_HAS_MPFR
// Runs f with mpfr_real at d digits (MPFR even where float128 would do).
template <class F>
auto in_mpfr(int d, F&& f) {
  scoped_precision precision(d);
  return f();
}
#endif

}  // namespace detail::bench

namespace detail {

struct bench_job : bench_request {
  using bench_point = bench::bench_point;
  using bench_method = bench::bench_method;
  using prepared = bench::prepared;

  std::vector<bench_method> methods(const std::map<std::string, std::shared_ptr<error_map>>& loaded) const {
    std::vector<bench_method> out;
    auto approximations_of = [](const contact_law& law) {
      // NOTE: the per-law constants are built once per law and kept, as a DEM code would.
      static std::map<std::string, std::shared_ptr<cor_approximations<double>>> cache;
      auto& c = cache[law.describe()];
      if (!c) c = std::make_shared<cor_approximations<double>>(law);
      return c;
    };
    for (auto a : all_approximations) {
      out.push_back({"approx " + to_string(a), "double", [a, approximations_of](const bench_point& p) -> std::optional<prepared> {
                       const auto c = approximations_of(p.law);
                       const double gamma = std::strtod(p.gamma.c_str(), nullptr), g = std::strtod(p.g.c_str(), nullptr);
                       if (!approximate_e(*c, a, gamma, g)) return std::nullopt;
                       auto e = std::make_shared<double>(0);
                       return prepared{[=] { *e = *approximate_e(*c, a, gamma, g); },
                                       [e] { return to_decimal_string(*e); }};
                     }});
    }
    // The committed surrogate of the law (docs/surrogate.md), where there is one.
    out.push_back({"surrogate", "double", [](const bench_point& p) -> std::optional<prepared> {
                     const surrogate::cor_surrogate* s = find_surrogate(p.law);
                     const double gamma = std::strtod(p.gamma.c_str(), nullptr), g = std::strtod(p.g.c_str(), nullptr);
                     if (!s || !(*s)(gamma, g).in_domain) return std::nullopt;
                     auto e = std::make_shared<double>(0);
                     return prepared{[=] { *e = (*s)(gamma, g).e; }, [e] { return to_decimal_string(*e); }};
                   }});
    out.push_back({"taylor", "double", [](const bench_point& p) { return std::optional<prepared>(bench::taylor_at<double>(p)); }});
    out.push_back(
        {"taylor", "long double", [](const bench_point& p) { return std::optional<prepared>(bench::taylor_at<long double>(p)); }});
#if VISCOR_HAS_QD
    out.push_back(
        {"taylor", "double-double", [](const bench_point& p) { return std::optional<prepared>(bench::taylor_at<double_double>(p)); }});
#endif
#if VISCOR_HAS_FLOAT128
    out.push_back({"taylor", "float128", [](const bench_point& p) { return std::optional<prepared>(bench::taylor_at<quad>(p)); }});
#endif
#if VISCOR_HAS_MPFR
    for (int d : digit_list()) {
      out.push_back({"taylor", "mpfr " + std::to_string(d), [d](const bench_point& p) -> std::optional<prepared> {
                       const prepared inner = bench::in_mpfr(d, [&] { return bench::taylor_at<mpfr_real>(p); });
                       // NOTE: printed inside the scope too: to_decimal_string reads the digits from it.
                       return prepared{[d, inner] { bench::in_mpfr(d, inner.compute); },
                                       [d, inner] { return bench::in_mpfr(d, inner.text); }};
                     }});
    }
#endif
    if (certified) {
      out.push_back({"certify", "double", [](const bench_point& p) -> std::optional<prepared> {
                       auto e = std::make_shared<double>(0);
                       const double gamma = std::strtod(p.gamma.c_str(), nullptr), g = std::strtod(p.g.c_str(), nullptr);
                       const contact_law law = p.law;
                       return prepared{[=] { *e = certify(law, gamma, g).e; }, [e] { return to_decimal_string(*e); }};
                     }});
#if VISCOR_HAS_QD
      out.push_back({"certify", "double-double", [](const bench_point& p) -> std::optional<prepared> {
                       auto e = std::make_shared<double_double>(0);
                       const double_double gamma = parse_real<double_double>(p.gamma, "gamma");
                       const double_double g = parse_real<double_double>(p.g, "g");
                       const contact_law law = p.law;
                       return prepared{[=] { *e = certify(law, gamma, g).e; }, [e] { return to_decimal_string(*e); }};
                     }});
#endif
      for (int d : digit_list())
        out.push_back({"certify", "mpfr " + std::to_string(d), [d](const bench_point& p) -> std::optional<prepared> {
                         auto e = std::make_shared<std::string>();
                         const bench_point q = p;
                         return prepared{[=] {
                                           bench::in_mpfr(d, [&] {
                                             *e = to_decimal_string(certify(q.law, parse_real<mpfr_real>(q.gamma, "gamma"),
                                                                            parse_real<mpfr_real>(q.g, "g")).e);
                                           });
                                         },
                                         [e] { return *e; }};
                       }});
    }
    for (const bool with_surrogate : {false, true})
      for (const char* tol : {"1e-4", "1e-10"}) {
        const double t = std::strtod(tol, nullptr);
        out.push_back({std::string("evaluate ") + tol + (loaded.empty() ? "" : " (maps)") + (with_surrogate ? " (surrogate)" : ""),
                       "double", [t, &loaded, with_surrogate](const bench_point& p) -> std::optional<prepared> {
                         evaluate_options o;
                         const auto it = loaded.find(p.law.name);
                         if (it != loaded.end()) o.map = it->second.get();
                         // With the committed surrogate of the law tried first (docs/surrogate.md).
                         std::shared_ptr<surrogate::surrogate_source> source;
                         if (with_surrogate) {
                           const auto* s = find_surrogate(p.law);
                           if (!s) return std::nullopt;
                           source = std::make_shared<surrogate::surrogate_source>(*s);
                         }
                         o.surrogate = source.get();
                         auto ev = std::make_shared<evaluator<double>>(p.law, o);
                         auto e = std::make_shared<double>(0);
                         const double gamma = std::strtod(p.gamma.c_str(), nullptr), g = std::strtod(p.g.c_str(), nullptr);
                         return prepared{[=] { *e = (*ev)(gamma, g, t).e; (void)source; }, [e] { return to_decimal_string(*e); }};
                       }});
      }
    return out;
  }

  std::vector<int> digit_list() const {
    std::vector<int> out;
    for (const std::string& item : split_list(precisions, VISCOR_FIELD("precisions"))) {
      if (item.find_first_not_of("0123456789") != std::string::npos)
        throw invalid_parameter(VISCOR_FIELD("precisions") " expects comma-separated digit counts, got '" + item + "'");
      out.push_back(std::stoi(item));
    }
    return out;
  }

  surrogate_bench_result run_surrogate() const {
    if (surrogate_points < 1)
      throw invalid_parameter(VISCOR_FIELD("points") " must be >= 1, got " + std::to_string(surrogate_points));
    if (surrogate_passes < 1)
      throw invalid_parameter(VISCOR_FIELD("passes") " must be >= 1, got " + std::to_string(surrogate_passes));
    if (taylor_points < 1)
      throw invalid_parameter(VISCOR_FIELD("taylor_points") " must be >= 1, got " + std::to_string(taylor_points));
    std::vector<contact_law> law_list;
    for (const std::string& item : split_list(laws, VISCOR_FIELD("laws"))) law_list.push_back(law_by_name(item));
    surrogate_bench_result out;
    out.points_per_law = surrogate_points, out.passes = surrogate_passes, out.taylor_points = taylor_points;
    surrogate::evaluation_times last;
    for (const auto& law : law_list) {
      const surrogate::cor_surrogate* s = find_surrogate(law);
      if (!s) {
        out.skipped_without_surrogate.push_back(law.name);
        continue;
      }
      const auto all = surrogate::timing_points(*s, static_cast<std::size_t>(surrogate_points));
      for (const bool rebound_only : {false, true}) {
        const auto points = rebound_only ? surrogate::points_with_outcome(*s, all, impact_outcome::rebound) : all;
        if (points.empty()) continue;
        const auto f = [s](double gamma, double g) { return (*s)(gamma, g).e; };
        const auto t = surrogate::time_each_evaluation(f, points, surrogate_passes);
        const double mean = surrogate::stream_mean_ns(f, points, surrogate_passes);
        std::vector<surrogate::timing_point> few(
            points.begin(),
            points.begin() + std::min<std::ptrdiff_t>(taylor_points, static_cast<std::ptrdiff_t>(points.size())));
        const double taylor = surrogate::stream_mean_ns(
            [&law](double gamma, double g) { return solve_impact<double>(law, gamma, g).e; }, few, 3);
        out.rows.push_back({law.name, rebound_only ? "rebound" : "mixed", points.size(), t.median_ns, t.p99_ns,
                            t.max_ns, t.raw_max_ns, mean, taylor, few.size(), taylor / mean});
        last = t;
      }
    }
    out.method =
        "each evaluation timed alone (fenced time-stamp counter, clock step " + std::to_string(last.resolution_ns) +
        " ns, empty-region overhead " + std::to_string(last.overhead_ns) + " ns subtracted), " +
        std::to_string(surrogate_passes) +
        " passes in shuffled orders; median and p99 over all timings, max = the slowest point's least timing; "
        "mean in a stream = the least of the passes' means without a clock read between calls; "
        "Taylor / surrogate = Taylor mean / surrogate mean in a stream, Taylor on the stream's first " +
        std::to_string(taylor_points) + " points (the least of 3 passes' means)";
    out.fma_path = surrogate::cpu_has_fma();
    return out;
  }

  bench_result run() const {
    if (!(min_time >= 0)) throw invalid_parameter(VISCOR_FIELD("min_time") " must be >= 0");
    std::vector<contact_law> law_list;
    for (const std::string& item : split_list(laws, VISCOR_FIELD("laws"))) law_list.push_back(law_by_name(item));
    std::map<std::string, std::shared_ptr<error_map>> loaded;
    if (!error_maps.empty() && !std::filesystem::is_directory(error_maps))
      throw invalid_parameter(VISCOR_FIELD("error_maps") " '" + error_maps + "' is not a directory");
    if (!error_maps.empty())
      for (const auto& law : law_list) {
        const auto path = std::filesystem::path(error_maps) / (law.name + ".csv");
        if (std::filesystem::exists(path)) loaded[law.name] = std::make_shared<error_map>(read_error_map(path.string()));
      }
    const std::vector<int> digits = digit_list();
    const int ref_digits = (digits.empty() ? 40 : *std::max_element(digits.begin(), digits.end())) + 20;

    const std::string table_path =
        table.empty() ? (std::filesystem::path(data_directory()) / "cor_report_grid.csv").string() : table;
    const csv_table reference_table = read_table(table_path);
    if (reference_table.kind != table_kind::cor)
      throw invalid_parameter(VISCOR_FIELD("table") " " + table_path + " is not a CoR table");
    const auto start = bench::clock_type::now();
    std::vector<bench_point> points;
    int least_table_digits = 1000000;
    for (const auto& law : law_list)
      for (const char* gamma : {"0.001", "0.01", "0.1"})
        for (const char* g : {"0", "0.05", "1"}) {
          bench_point p{law, gamma, g, "", 0, ""};
          std::tie(p.e_table, p.table_digits) = bench::table_value(reference_table, table_path, law, gamma, g);
          least_table_digits = std::min(least_table_digits, p.table_digits);
          p.e_ref = with_working_precision(ref_digits, [&]<class Real>() {
            const prepared r = bench::taylor_at<Real>(p);
            r.compute();
            const std::string e = r.text();
            using std::abs;
            using std::pow;
            const Real certified = parse_real<Real>(p.e_table, field::e), extended = parse_real<Real>(e, field::e);
            // p.table_digits significant digits: |error| < 10^(1 - digits) |e| (e = 0: a certified stick).
            const Real allowed = Real(pow(Real(10), 1 - p.table_digits)) * abs(certified);
            if (!(abs(extended - certified) <= allowed))
              throw certification_error("bench: solve_impact at " + std::to_string(ref_digits) + " digits gives e = " + e +
                                        " at " + law.describe() + ", gamma = " + gamma + ", g = " + g +
                                        ", outside the certified " + p.e_table + " of " + table_path);
            return e;
          });
          points.push_back(p);
        }
    bench_result out;
    out.laws = laws;
    out.points = points.size();
    out.reference_seconds = std::chrono::duration<double>(bench::clock_type::now() - start).count();
    out.reference = "certified table " + table_path + " (>= " + std::to_string(least_table_digits) +
                    " digits), extended by solve_impact at " + std::to_string(ref_digits) +
                    " digits, which agrees with it to every certified digit";

    for (const bench_method& m : methods(loaded)) {
      std::vector<double> times;
      std::vector<std::string> results;
      std::vector<const bench_point*> used;
      for (const auto& p : points) {
        const std::optional<prepared> run = m.prepare(p);
        if (!run) continue;
        times.push_back(bench::time_per_call(run->compute, min_time));
        results.push_back(run->text());
        used.push_back(&p);
      }
      bench_row row;
      row.method = m.name, row.scalar = m.precision, row.points = static_cast<int>(used.size());
      if (!used.empty()) {
        std::sort(times.begin(), times.end());
        row.median_seconds = times[times.size() / 2];
        with_working_precision(ref_digits, [&]<class Ref>() {
          using std::abs;
          std::vector<Ref> abs_err, rel_err;
          for (std::size_t i = 0; i < used.size(); ++i) {
            const Ref ref = parse_real<Ref>(used[i]->e_ref, "reference");
            const Ref err = abs(parse_real<Ref>(results[i], field::e) - ref);
            abs_err.push_back(err);
            if (ref > 0) rel_err.push_back(Ref(err / ref));
          }
          auto summarize = [](std::vector<Ref>& v, std::string& max, std::string& median) {
            if (v.empty()) return;
            std::sort(v.begin(), v.end());
            max = to_decimal_string(v.back(), 2), median = to_decimal_string(v[v.size() / 2], 2);
          };
          summarize(abs_err, row.max_abs_error, row.median_abs_error);
          summarize(rel_err, row.max_rel_error, row.median_rel_error);
        });
      }
      out.rows.push_back(row);
    }
    return out;
  }
};

}  // namespace detail

bench_result run_bench(const bench_request& q) { return detail::bench_job{q}.run(); }

surrogate_bench_result run_surrogate_bench(const bench_request& q) { return detail::bench_job{q}.run_surrogate(); }

}  // namespace viscor::jobs
