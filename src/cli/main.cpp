// viscor command-line tool: one subcommand per src/cli/cmd_*.cpp.
// Exit codes: 0 success, 1 a check that ran and failed (`formula check`), 2 usage or input error (the message names the option or
// value) or a failed write (an output file, or standard output), 3 internal error.
#include "command_registry.hpp"
#include "option_spelling.hpp"

#include <viscor/config.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/jobs/files.hpp>

#include <cstdio>
#include <iostream>

namespace {

/// Whether everything written to standard output reached it: a write error (a full
/// disk, /dev/full, a closed pipe) must not end in exit code 0.
bool standard_output_written() {
  std::cout.flush();
  const bool ok = static_cast<bool>(std::cout) && std::fflush(stdout) == 0 && !std::ferror(stdout);
  return std::fclose(stdout) == 0 && ok;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"viscor: certified coefficient of restitution of visco-elastic impacts under load"};
  app.set_version_flag("--version", std::string("viscor ") + VISCOR_VERSION + " (" + viscor::git_commit() + ")");
  app.require_subcommand(1);
  app.add_flag_callback(
      "--update-committed", [] { viscor::jobs::replacing_committed_data_allowed() = true; },
      "allow outputs to replace committed data (a file a SHA256SUMS beside it lists) and update its checksum line; "
      "give it before the subcommand");
  viscor::cli::add_commands(app);  // every subcommand; empty values refused
  viscor::current_warning_handler() = viscor::cli::print_warning;  // fields spelled as options
  try {
    viscor::cli::refuse_empty_assignments(argc, argv);
    app.parse(argc, argv);
    if (!standard_output_written()) {
      std::cerr << "viscor: error: writing to standard output failed\n";
      return 2;
    }
  } catch (const viscor::cli::failed_check&) {
    if (!standard_output_written()) {
      std::cerr << "viscor: error: writing to standard output failed\n";
      return 2;
    }
    return 1;
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with exit code 0; every other parse error
    // is a usage error: exit 2, like every bad value found later.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "viscor: error: " << e.what() << "\n(run 'viscor " << (argc > 1 ? argv[1] : "")
              << " --help' for the options)\n";
    return 2;
  } catch (const viscor::error& e) {
    std::cerr << "viscor: error: " << viscor::cli::spelled(e) << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "viscor: internal error: " << e.what() << '\n';
    return 3;
  }
  return 0;
}
