// viscor table: certified reference tables from a grid spec.
//   viscor table SPEC.json -o OUT.csv [--resume] [--shard i/N] [--threads N] [--quiet]
//   viscor table SPEC.json --estimate [--shard i/N] [--threads N]
//   viscor table SPEC.json -o OUT.csv --format netcdf       (also OUT.nc)
//   viscor table merge A.csv B.csv ... -o OUT.csv
//   viscor table netcdf TABLE.csv [-o TABLE.nc]
//   viscor table sticking SPEC.json -o OUT.csv [--resume] [--shard i/N] [--threads N] [--quiet]
// The options of the table jobs (include/viscor/jobs/table_jobs.hpp), which do the work.
#include "cli_common.hpp"
#include "command_registry.hpp"
#include "test_hooks.hpp"

#include <viscor/jobs/netcdf_file.hpp>
#include <viscor/jobs/table_estimate.hpp>
#include <viscor/jobs/table_estimate_render.hpp>
#include <viscor/jobs/table_jobs.hpp>
#include <viscor/jobs/table_spec.hpp>

#include <iostream>

#include <memory>

namespace viscor::cli::cmd_table {  // named: the subcommands share translation units (unity build)
namespace {

/// Options shared by `table` and `table sticking`.
struct run_options {
  std::string spec_path, shard_text;
  table_run_options run;

  void add_to(CLI::App& app) {
    app.add_option("spec", spec_path, "grid specification, JSON (docs/tables.md, section 'Grid specification')");
    app.add_option("-o,--output", run.output, "output table OUT.csv (its sidecar is OUT.csv.json)")
      ->check(output_options::regular_output_file());
    app.add_flag("--resume", run.resume, "continue an interrupted run from OUT.csv.partial");
    app.add_option("--shard", shard_text, "compute only shard i of N (0 <= i < N): rows with index % N == i");
    app.add_option("--threads", run.threads, "worker threads (default: all cores)")->capture_default_str();
    app.add_flag("--quiet", run.quiet, "no progress output");
  }

  void check_threads() const {
    if (run.threads < 1 || run.threads > 4096)
      throw invalid_parameter("--threads must be from 1 to 4096, got " + std::to_string(run.threads));
  }

  /// The estimate of the run (jobs/table_estimate.hpp): nothing is computed or written.
  void estimate() const {
    if (spec_path.empty()) throw invalid_parameter("viscor table --estimate needs a spec file: viscor table SPEC.json --estimate");
    if (run.resume) throw invalid_parameter("--estimate computes nothing: give it without --resume");
    check_threads();
    const shard part = shard_text.empty() ? shard{} : shard::parse(shard_text);
    std::cout << render::table_estimate_text(estimate_cor_table(read_spec_json(spec_path), part, run.threads));
  }

  /// Checks the options, then reads the spec.
  std::pair<table_spec, table_run_options> read(const std::string& command) const {
    if (spec_path.empty()) throw invalid_parameter(command + " needs a spec file: " + command + " SPEC.json -o OUT.csv");
    if (run.output.empty()) throw invalid_parameter(command + " needs an output file: -o OUT.csv");
    check_threads();
    table_run_options r = run;
    r.part = shard_text.empty() ? shard{} : shard::parse(shard_text);
    r.spec_file = spec_path;
    r.handle_signals = true;
    r.stop_after_rows = test_hooks::table_stop_after_rows();
    r.certified_e_shift = test_hooks::certified_e_shift();
    return {read_spec_json(spec_path), r};
  }
};

struct merge_options {
  std::vector<std::string> inputs;
  std::string output;
  bool quiet = false;
};

void setup(CLI::App& app) {
  auto table = std::make_shared<run_options>();
  table->add_to(app);
  auto estimate = std::make_shared<bool>(false);
  app.add_flag("--estimate", *estimate,
               "print the rows and the expected CPU and wall time (at --threads, of --shard) from the measured cost "
               "per row, and compute nothing (-o not needed)");
  auto format = std::make_shared<std::string>("csv");
  app.add_option("--format", *format,
                 "csv: OUT.csv and its sidecar OUT.csv.json; netcdf: also OUT.nc, their NetCDF form for xarray "
                 "(docs/tables.md, 'NetCDF and xarray')")
      ->check(CLI::IsMember({"csv", "netcdf"}))
      ->capture_default_str();

  CLI::App* netcdf = app.add_subcommand("netcdf", "the NetCDF form of a CoR table file (its sidecar beside it)");
  auto converting = std::make_shared<std::pair<std::string, std::string>>();
  netcdf->add_option("table", converting->first, "the table TABLE.csv (with TABLE.csv.json)")->required();
  netcdf->add_option("-o,--output", converting->second, "the NetCDF file (default: TABLE.nc)")
      ->check(output_options::regular_output_file());
  netcdf->callback([converting] {
    const std::string out = converting->second.empty() ? netcdf_path_for(converting->first) : converting->second;
    write_table_netcdf(converting->first, out);
  });

  CLI::App* merge = app.add_subcommand("merge", "join shard tables (--shard i/N) into the full table");
  auto merging = std::make_shared<merge_options>();
  merge->add_option("tables", merging->inputs, "the shard tables A.csv B.csv ... (each with its .json sidecar)");
  merge->add_option("-o,--output", merging->output, "the merged table OUT.csv");
  merge->add_flag("--quiet", merging->quiet, "no summary line");
  merge->callback([merging] { merge_tables(merging->inputs, merging->output, merging->quiet); });

  CLI::App* sticking = app.add_subcommand(
      "sticking", "certified sticking thresholds g_c(gamma) or gamma_c(g) (spec: solve_for, threshold_digits)");
  auto thresholds = std::make_shared<run_options>();
  thresholds->add_to(*sticking);
  sticking->callback([thresholds] {
    const auto [spec, run] = thresholds->read("viscor table sticking");
    make_sticking_table(spec, run);
  });

  app.require_subcommand(0, 1);
  app.callback([table, estimate, format, &app] {
    if (!app.get_subcommands().empty()) return;
    if (*estimate) return table->estimate();
    auto [spec, run] = table->read("viscor table");
    run.netcdf = *format == "netcdf";
    make_cor_table(spec, run);
  });
}

const registration reg{"table", "certified reference tables from a grid spec (also: table merge, table sticking)",
                       setup};

}  // namespace
}  // namespace viscor::cli::cmd_table
