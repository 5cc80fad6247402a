// A certified table computed the way a cluster computes it: in two shards, the
// first one interrupted and resumed, then merged. The merged CSV is byte for byte
// the one `viscor table spec.json -o OUT.csv` writes in one run (the test
// example_table_matches_cli checks it). Usage: example_sharded_table [DIR]
#include <viscor/viscor.hpp>

#include <filesystem>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("viscor_sharded_table");
  fs::create_directories(dir);

  // The spec is the text of a spec file (docs/tables.md); it is also saved, so that
  // the same table can be made with the command-line tool.
  const std::string spec_text = R"({
  "description": "two laws, a small grid",
  "laws": ["linear", "tsuji"],
  "gamma": [0, 0.05, {"from": 0.1, "to": 0.3, "count": 3}],
  "g": [0, 0.5],
  "digits": 20
})";
  viscor::jobs::write_atomically((dir / "spec.json").string(), spec_text + "\n");
  const viscor::jobs::table_spec spec = viscor::jobs::parse_spec_json(spec_text, "spec.json");

  viscor::jobs::table_run_options run;
  run.spec_file = "spec.json";
  run.threads = 2;
  run.quiet = true;

  // Shard 0 of 2, stopped at once, as a time limit would stop it: the rows finished
  // by then are kept in part-0.csv.partial.
  run.part = viscor::shard::parse("0/2");
  run.output = (dir / "part-0.csv").string();
  run.should_stop = [] { return true; };
  try {
    viscor::jobs::make_cor_table(spec, run);
  } catch (const viscor::error& e) {
    std::cout << "shard 0 stopped: " << std::string(e.what()).substr(0, 40) << "...\n";
  }
  // ... and resumed: only the missing rows are computed.
  run.should_stop = nullptr;
  run.resume = true;
  const auto first = viscor::jobs::make_cor_table(spec, run);
  std::cout << "shard 0: " << first.rows << " rows, " << first.rows_from_earlier_sessions
            << " of them from the interrupted session\n";

  run.resume = false;
  run.part = viscor::shard::parse("1/2");
  run.output = (dir / "part-1.csv").string();
  std::cout << "shard 1: " << viscor::jobs::make_cor_table(spec, run).rows << " rows\n";

  const std::string merged = (dir / "table.csv").string();
  const std::size_t rows =
      viscor::jobs::merge_tables({(dir / "part-0.csv").string(), (dir / "part-1.csv").string()}, merged, true);
  std::cout << "merged " << rows << " rows into " << merged << "\n";
  return rows == 20 ? 0 : 1;
}
