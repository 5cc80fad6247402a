// Point batches (include/viscor/jobs/point_batch.hpp), compiled once.
#include <viscor/jobs/point_batch.hpp>

namespace viscor::jobs {

namespace detail {

/// A point's whole-number field (digits, certified_digits); empty when not given.
std::optional<int> whole_number_field(const std::string& text, const char* name) {
  if (text.empty()) return std::nullopt;
  if (text.find_first_not_of("0123456789") != std::string::npos || text.size() > 6 || std::stoi(text) < 1)
    throw invalid_parameter(std::string(name) + " must be a whole number from 1 to 999999, got '" + text + "'");
  return std::stoi(text);
}

/// Solves one point; the JSON line (or an "error" line).
json solve_point(const point_text& p, const point_options& o, bool& refused) {
  json j;
  j["line"] = p.line;
  try {
    // A point's fields are named law, alpha, beta: the messages say so.
    if (!p.law.empty() && (!p.alpha.empty() || !p.beta.empty()))
      throw invalid_parameter("give either law or alpha and beta, not both");
    if (p.law.empty() && (p.alpha.empty() || p.beta.empty())) throw invalid_parameter("needs law, or both alpha and beta");
    const contact_law law = resolve_law(p.law, p.alpha, p.beta);
    if (p.gamma.empty()) throw invalid_parameter("missing gamma");
    const std::optional<int> digits = whole_number_field(p.digits, "digits");
    const std::optional<int> certified_digits = whole_number_field(p.certified_digits, "certified_digits");
    if (digits && certified_digits) throw invalid_parameter("give either digits or certified_digits, not both");
    const auto solve = [&](int working_digits, bool certify) {
      return with_working_precision(working_digits, [&]<class Real>() {
        solve_options<Real> options;
        options.method = o.method;
        options.tolerance = parse_real<Real>(o.tolerance, "tolerance");
        options.max_steps = o.max_steps;
        const Real gamma = parse_real<Real>(p.gamma, "gamma"), g = parse_real<Real>(p.g, "g");
        return solve_cor(law, gamma, g, options, certify);
      });
    };
    // The point's own digits or certified digits first, then the batch's.
    const std::optional<int> goal = digits ? std::nullopt : certified_digits ? certified_digits : o.default_certified_digits;
    if (!goal) {
      render::add_cor_fields(j, solve(digits.value_or(o.default_digits), false));
    } else {
      render::add_cor_fields(j, certify_cor_to_goal(*goal, [&](int working_digits) { return solve(working_digits, true); }));
    }
  } catch (const error& e) {
    j["error"] = e.what();
    refused = true;
  }
  return j;
}

}  // namespace detail

/// Solves the points read from `in` (`name` names it in messages), and hands each
/// result line to `emit` in input order: the fields of `viscor cor --json` plus
/// "line", or "line" and "error" for a refused point. Returns the number refused.
/// Throws invalid_parameter for input that is not a point list at all.
std::size_t solve_points(std::istream& in, const std::string& name, const point_options& o,
                         const std::function<void(const json&)>& emit) {
  std::vector<std::string> header;  // CSV columns, once read
  bool csv = false, decided = false;
  std::size_t line_number = 0, refused_count = 0;
  std::vector<point_text> batch;
  std::vector<std::string> batch_errors;  // parse errors, per batch entry ("" if none)

  auto flush = [&] {
    std::vector<json> results(batch.size());
    std::vector<char> refused(batch.size(), 0);
    parallel_for_options options;
    options.threads = o.threads;
    const parallel_for_result run = parallel_for(
        batch.size(),
        [&](std::size_t i) {
          if (!batch_errors[i].empty()) {
            results[i] = json{{"line", batch[i].line}, {"error", batch_errors[i]}};
            refused[i] = 1;
            return;
          }
          bool r = false;
          results[i] = detail::solve_point(batch[i], o, r);
          refused[i] = r;
        },
        options);
    if (run.failed()) std::rethrow_exception(run.failure);  // solve_point answers each point's own error
    for (std::size_t i = 0; i < batch.size(); ++i) {
      emit(results[i]);
      refused_count += refused[i];
    }
    batch.clear();
    batch_errors.clear();
  };

  std::string line;
  const std::size_t batch_size = o.threads <= 1 ? 1 : 4 * o.threads;
  while (std::getline(in, line)) {
    ++line_number;
    if (const std::size_t bad = first_invalid_utf8(line); bad != std::string::npos) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(line[bad])));
      throw invalid_parameter(VISCOR_FIELD("points")
                              ": " + name + ":" + std::to_string(line_number) + ": not UTF-8 text (byte " +
                              hex + " at column " + std::to_string(bad + 1) + ")");
    }
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    if (!decided) {
      decided = true;
      csv = line[line.find_first_not_of(" \t")] != '{';
      if (csv) {
        header = split_trimmed_fields(line);
        point_text probe;
        for (std::size_t c = 0; c < header.size(); ++c) {
          const std::string& column = header[c];
          if (!detail::point_field(probe, column))
            throw invalid_parameter(VISCOR_FIELD("points")
                                    ": " + name + ":" + std::to_string(line_number) + ": unknown column '" +
                                    column + "' (known: " + detail::point_fields + ")");
          if (std::find(header.begin(), header.begin() + static_cast<long>(c), column) != header.begin() + static_cast<long>(c))
            throw invalid_parameter(VISCOR_FIELD("points")
                                    ": " + name + ":" + std::to_string(line_number) + ": column '" + column +
                                    "' given twice");
        }
        continue;
      }
    }
    point_text p;
    p.line = line_number;
    std::string problem;
    try {
      if (csv) {
        const auto fields = split_trimmed_fields(line);
        if (fields.size() != header.size())
          throw invalid_parameter(std::to_string(fields.size()) + " fields where the header names " +
                                  std::to_string(header.size()));
        for (std::size_t c = 0; c < header.size(); ++c)
          if (!fields[c].empty()) *detail::point_field(p, header[c]) = fields[c];
      } else {
        p = detail::parse_json_point(line, name + ":" + std::to_string(line_number), line_number);
      }
    } catch (const error& e) {
      problem = e.what();
      if (problem.empty()) problem = "unreadable line";
    }
    batch.push_back(p);
    batch_errors.push_back(problem);
    if (batch.size() >= batch_size) flush();
  }
  flush();
  if (line_number == 0) throw invalid_parameter(VISCOR_FIELD("points") ": " + name + " holds no points");
  return refused_count;
}

/// Reads points from `path` ("-": standard input), writes one JSON line per point
/// to `out` and names each refused point on standard error; returns the number refused.
std::size_t solve_points(const std::string& path, const point_options& o, std::ostream& out) {
  std::ifstream file;
  if (path != "-") {
    file.open(path);
    if (!file) throw invalid_parameter(VISCOR_FIELD("points") ": cannot read '" + path + "'");
  }
  const std::string name = path == "-" ? std::string("<stdin>") : path;
  const std::size_t refused = solve_points(path == "-" ? std::cin : file, name, o, [&](const json& result) {
    out << result.dump(-1, ' ', false, json::error_handler_t::replace) << '\n' << std::flush;  // streamed
    if (result.contains("error"))
      std::cerr << "viscor: error: " << name << ":" << result["line"].get<std::size_t>() << ": "
                << result["error"].get<std::string>() << '\n';
  });
  return refused;
}

}  // namespace viscor::jobs
