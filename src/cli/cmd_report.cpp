// viscor report: the report's Tables 2-5 and Figs. 8-11 from the committed tables
// (the report job, jobs/report_job.hpp).
//   viscor report [--data DIR] [--compare] [--csv | -o x.csv] [--values V.csv]
//   viscor report baseline [--data DIR] -o reference_data/approximation_error_baseline.csv
#include "cli_common.hpp"
#include "command_registry.hpp"

#include <viscor/jobs/data_directory.hpp>
#include <viscor/jobs/report_job.hpp>

namespace viscor::cli::cmd_report {  // named: the subcommands share translation units (unity build)
namespace {

void write_report(const report_request& q) {
  const report_output r = make_report(q);
  std::vector<jobs::output_file> files;
  if (!q.values.empty()) files.push_back({q.values, r.values_csv});
  if (!q.output.empty()) files.push_back({q.output, r.text});
  jobs::write_together(files);  // the values and the report together, or neither
  for (const auto& f : files) output_options::say_written(f.path, f.body);
  if (q.output.empty()) std::cout << r.text << std::flush;
}

void write_baseline(const baseline_request& q) {
  const baseline_output r = make_baseline(q);
  for (const auto& w : r.warnings) std::cerr << "viscor report baseline: " << w << "\n";
  output_options::write_atomically(q.output, r.text);
  std::cerr << "viscor report baseline: wrote " << q.output << " (" << r.groups << " groups, " << r.warnings.size()
            << " with non-finite values)\n";
}

void setup(CLI::App& app) {
  auto report = std::make_shared<report_request>();
  app.add_option("--data", report->data,
                 "directory of the certified tables (default: $VISCOR_DATA, else the installed share/viscor, else the "
                 "source tree's reference_data)");
  app.add_option("-o,--output", report->output, "write to FILE (CSV if it ends in .csv, else Markdown)")
      ->check(output_options::regular_output_file());
  app.add_flag("--csv", report->csv, "CSV instead of Markdown");
  app.add_flag("--compare", report->compare, "print the report's values next to ours");
  app.add_option("--values", report->values,
                 "also write every row's reference and approximations to this CSV (for tools/plot_reference.py)");

  CLI::App* baseline = app.add_subcommand("baseline", "write the regression baseline of the approximations' errors");
  auto b = std::make_shared<baseline_request>();
  baseline->add_option("--data", b->data, "directory of the certified tables (default as for report)");
  baseline->add_option("-o,--output", b->output, "the baseline CSV")->required();
  baseline->callback([b] {
    b->data = data_directory(b->data);
    write_baseline(*b);
  });

  app.require_subcommand(0, 1);
  app.callback([report, &app] {
    if (!app.get_subcommands().empty()) return;
    report->data = data_directory(report->data);
    write_report(*report);
  });
}

const registration reg{"report",
                       "the report's Tables 2-5 and Figs. 8-11 from the committed tables (also: report baseline)",
                       setup};

}  // namespace
}  // namespace viscor::cli::cmd_report
