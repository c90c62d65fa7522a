// The `unidyn` command. Exit status: 0 success, 1 a run failed, 2 bad input.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>

#include "analysis_commands.hpp"
#include "fixed_layout.hpp"
#include "import_command.hpp"
#include "model_commands.hpp"
#include "progress_notices.hpp"
#include "rotation_command.hpp"
#include "sanitizers.hpp"
#include "signals.hpp"
#include "sweep_command.hpp"
#include "unidyn/rotation/errors.hpp"
#include "unidyn/symbolic/expression.hpp"
#include "unidyn/symbolic/printable_text.hpp"

#ifndef UNIDYN_VERSION
#define UNIDYN_VERSION "unknown"
#endif

int main(int argc, char** argv) {
  // past a file-size limit (ulimit -f) a write fails with EFBIG, which the writers handle (the
  // file cut back to its last whole row, exit 1), instead of SIGXFSZ killing the process mid-row
  std::signal(SIGXFSZ, SIG_IGN);
  // Ctrl-C, kill or a closed terminal: no compiler left running for a process that is gone
  unidyn::cli::end_commands_on_signals();
  // the same process layout in every run: equal input, byte-identical output
  unidyn::cli::use_fixed_layout(argv);
  CLI::App app{"unidyn: engineering dynamics after O'Reilly, Intermediate Dynamics for Engineers"};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", "unidyn " UNIDYN_VERSION);
  app.footer(
      "MODEL is a model file or the name of a bundled model (`unidyn models` lists them). The "
      "model\n"
      "language is described in docs/model-format.md, the commands in docs/commands.md.");
  unidyn::cli::RotationCommand rotation;
  unidyn::cli::add_rotation_command(app, rotation);
  unidyn::cli::ModelCommands models;
  unidyn::cli::add_model_commands(app, models);
  unidyn::cli::AnalysisCommands analysis;
  unidyn::cli::add_analysis_commands(app, analysis);
  unidyn::cli::SweepCommand sweep;
  unidyn::cli::add_sweep_command(app, sweep);
  unidyn::cli::ImportCommand import;
  unidyn::cli::add_import_command(app, import);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "unidyn: error: {}\n", unidyn::printable(e.what()));
    return 2;
  }

  // bare `unidyn`: how to use it
  if (app.get_subcommands().empty()) {
    fmt::print("{}", app.help());
    return 0;
  }

  try {
    int status = 0;
    {
      // "still working" on a terminal while a long command runs
      const unidyn::cli::ProgressNotices notices;
      status = rotation.rotation->parsed() ? unidyn::cli::run_rotation_command(rotation)
               : sweep.sweep->parsed()     ? unidyn::cli::run_sweep_command(sweep)
               : import.import->parsed()   ? unidyn::cli::run_import_command(import)
               : analysis.linearize->parsed() || analysis.modes->parsed() ||
                       analysis.equilibria->parsed()
                   ? unidyn::cli::run_analysis_commands(analysis)
                   : unidyn::cli::run_model_commands(models);
    }
    if (status < 0) status = 2;
    // what could not be written to standard output (a full disk, /dev/full) is a failure
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
      fmt::print(stderr, "unidyn: error: cannot write standard output: {}\n", std::strerror(errno));
      return 1;
    }
    // the command's memory left to the system rather than freed node by node (the expression
    // trees and printing memos of the bicycle took 0.3 s to free); every stream is flushed and
    // every file closed by now. A leak-checked build exits normally, for the leak check.
#if !defined(UNIDYN_ADDRESS_SANITIZER)
    std::cout.flush();
    std::fflush(stderr);
    std::_Exit(status);
#endif
    return status;
  } catch (const unidyn::ModelError& e) {
    fmt::print(stderr, "{}\n", e.what());  // escaped when it was made
    return 2;
  } catch (const unidyn::SingularConfiguration& e) {
    // a parametrisation asked for where it does not exist (the Rodrigues vector at angle π)
    fmt::print(stderr, "unidyn: error: {}\n", unidyn::printable(e.what()));
    return 2;
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "unidyn: error: {}\n", unidyn::printable(e.what()));
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "unidyn: error: {}\n", unidyn::printable(e.what()));
    return 1;
  }
}
