// viscor command-line tool: one subcommand per src/cli/cmd_*.cpp.
// Exit codes: 0 success, 2 usage or input error (the message names the option or
// value), 3 internal error.
#include "command_registry.hpp"

#include <viscor/config.hpp>
#include <viscor/core/exceptions.hpp>

#include <algorithm>
#include <iostream>

namespace {

// An empty value is never meaningful (`--g ''` must not mean g = 0): refused for
// every option of every subcommand.
const CLI::Validator non_empty(
    [](std::string& value) { return value.empty() ? std::string("empty value (give a value or leave the option out)") : std::string(); },
    "", "NON_EMPTY");

void refuse_empty_values(CLI::App& app) {
  for (CLI::Option* option : app.get_options())
    if (option->get_type_size() != 0) option->check(non_empty);
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) refuse_empty_values(*sub);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"viscor: certified coefficient of restitution of visco-elastic impacts under load"};
  app.set_version_flag("--version", std::string("viscor ") + VISCOR_VERSION + " (" + viscor::git_commit() + ")");
  app.require_subcommand(1);
  auto& cmds = viscor::cli::commands();
  std::sort(cmds.begin(), cmds.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  for (auto& c : cmds) c.setup(*app.add_subcommand(c.name, c.help));
  refuse_empty_values(app);
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
