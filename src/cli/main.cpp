// viscor command-line tool: one subcommand per src/cli/cmd_*.cpp.
#include "command_registry.hpp"

#include <viscor/config.hpp>
#include <viscor/core/exceptions.hpp>

#include <algorithm>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"viscor: certified coefficient of restitution of visco-elastic impacts under load"};
  app.set_version_flag("--version", std::string("viscor ") + VISCOR_VERSION + " (" + viscor::git_commit() + ")");
  app.require_subcommand(1);
  auto& cmds = viscor::cli::commands();
  std::sort(cmds.begin(), cmds.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  for (auto& c : cmds) c.setup(*app.add_subcommand(c.name, c.help));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);  // usage errors: CLI11 prints them, exit code non-zero
  } catch (const viscor::error& e) {
    std::cerr << "viscor: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "viscor: internal error: " << e.what() << '\n';
    return 3;
  }
  return 0;
}
