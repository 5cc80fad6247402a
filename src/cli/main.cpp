// viscor command-line tool: one subcommand per src/cli/cmd_*.cpp.
// Exit codes: 0 success, 2 usage or input error (the message names the option or
// value), 3 internal error.
#include "command_registry.hpp"

#include <viscor/config.hpp>
#include <viscor/core/exceptions.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"viscor: certified coefficient of restitution of visco-elastic impacts under load"};
  app.set_version_flag("--version", std::string("viscor ") + VISCOR_VERSION + " (" + viscor::git_commit() + ")");
  app.require_subcommand(1);
  viscor::cli::add_commands(app);  // every subcommand; empty values refused
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with exit code 0; every other parse error
    // is a usage error: exit 2, like every bad value found later.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "viscor: error: " << e.what() << "\n(run 'viscor " << (argc > 1 ? argv[1] : "")
              << " --help' for the options)\n";
    return 2;
  } catch (const viscor::error& e) {
    std::cerr << "viscor: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "viscor: internal error: " << e.what() << '\n';
    return 3;
  }
  return 0;
}
