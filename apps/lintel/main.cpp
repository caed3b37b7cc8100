// `lintel`: the command-line face of the library. Each subcommand lives in its own cmd_*.cpp.
#include "cli_common.h"

#include <lintel/version.h>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  CLI::App app{
      "Lintel: indoor cell-and-portal visibility with a GPU-driven draw backend.\n"
      "Scenes are glTF 2.0 files with Lintel data in extras.lintel (docs/scene-format.md).",
      "lintel"};
  app.set_version_flag("--version", std::string("lintel ") + LINTEL_VERSION_STRING + " (scene format " +
                                        std::to_string(LINTEL_SCENE_FORMAT_VERSION) + ")");
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 2 bad input (one-line message on stderr), 1 internal failure.\n"
      "Run 'lintel <command> --help' for a command's options.");

  lintel::cli::Command run;
  lintel::cli::add_info_command(app, run);
  lintel::cli::add_validate_command(app, run);
  lintel::cli::add_gen_command(app, run);
  lintel::cli::add_vis_command(app, run);
  lintel::cli::add_walk_command(app, run);
  lintel::cli::add_cull_command(app, run);
  lintel::cli::add_render_command(app, run);
  lintel::cli::add_bench_command(app, run);
  lintel::cli::add_import_command(app, run);
  lintel::cli::add_view_command(app, run);
  lintel::cli::add_export_command(app, run);
  lintel::cli::add_optimize_command(app, run);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive here too, with exit code 0.
    if (e.get_exit_code() == 0) return app.exit(e);
    // One line, like every other error: CLI11's message with its hint folded in.
    std::string message = e.what();
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';
    while (!message.empty() && message.back() == ' ') message.pop_back();
    // CLI11 reports an unknown command as "A subcommand is required": name what was typed.
    if (argc > 1 && argv[1][0] != '-') {
      try {
        (void)app.get_subcommand(argv[1]);
      } catch (const CLI::Error&) {
        message = std::string("unknown command '") + argv[1] + "'";
      }
    }
    std::fprintf(stderr, "lintel: error: %s (run 'lintel --help' for usage)\n",
                 lintel::cli::printable(message).c_str());
    return lintel::cli::kExitBadInput;
  }
  try {
    return run ? run() : lintel::cli::kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lintel: internal error: %s\n", e.what());
    return lintel::cli::kExitFailure;
  }
}
