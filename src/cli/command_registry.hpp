// Subcommands register themselves: each src/cli/cmd_<name>.cpp defines one
//   static viscor::cli::registration reg{"name", "help", setup};
// where setup(CLI::App&) adds options and a callback. main.cpp only walks the list.
#pragma once

#include <CLI/CLI.hpp>

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

struct registration {
  registration(std::string name, std::string help, std::function<void(CLI::App&)> setup) {
    commands().push_back({std::move(name), std::move(help), std::move(setup)});
  }
};

}  // namespace viscor::cli
