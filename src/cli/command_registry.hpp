// Subcommands register themselves: each src/cli/cmd_<name>.cpp defines one
//   static viscor::cli::registration reg{"name", "help", setup};
// where setup(CLI::App&) adds options and a callback. main.cpp only walks the list.
#pragma once

#include <viscor/core/exceptions.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace viscor::cli {

struct command {
  std::string name;
  std::string help;
  std::function<void(CLI::App&)> setup;
};

inline std::vector<command>& commands() {
  static std::vector<command> all;  // function-local: safe across static initialisation order
  return all;
}

/// Thrown after a check has printed its result and failed (a formula outside its
/// tolerance): main exits 1, which tells a failed check from bad input (2).
struct failed_check {};

struct registration {
  registration(std::string name, std::string help, std::function<void(CLI::App&)> setup) {
    commands().push_back({std::move(name), std::move(help), std::move(setup)});
  }
};

/// Adds every registered subcommand to `app` (sorted by name) and refuses empty
/// values for every option: `--g ''` must not mean g = 0. Used by main.cpp and by
/// the Python module's in-process runner, so both parse alike.
inline void add_commands(CLI::App& app) {
  auto& cmds = commands();
  std::sort(cmds.begin(), cmds.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  for (auto& c : cmds) c.setup(*app.add_subcommand(c.name, c.help));
  static const CLI::Validator non_empty(
      [](std::string& value) {
        return value.empty() ? std::string("empty value (give a value or leave the option out)") : std::string();
      },
      "", "NON_EMPTY");
  const auto refuse_empty = [](auto& self, CLI::App& a) -> void {
    for (CLI::Option* option : a.get_options())
      if (option->get_type_size() != 0) option->check(non_empty);
    for (CLI::App* sub : a.get_subcommands([](CLI::App*) { return true; })) self(self, *sub);
  };
  refuse_empty(refuse_empty, app);
}

/// Throws invalid_parameter for an argument "--name=" with nothing after the '='
/// (CLI11 would take the next argument as the value: `--gamma= --g 0` read gamma
/// as "--g"). Used by main.cpp and the Python module before parsing.
inline void refuse_empty_assignments(int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") return;
    if (arg.size() > 3 && arg.rfind("--", 0) == 0 && arg.back() == '=' && arg.find('=') == arg.size() - 1)
      throw invalid_parameter("option " + arg.substr(0, arg.size() - 1) +
                              " has an empty value (give a value after '=' or leave the option out)");
  }
}

}  // namespace viscor::cli
