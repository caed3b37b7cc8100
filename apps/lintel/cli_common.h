// Shared plumbing of the `lintel` subcommands: how errors and warnings are printed, how vectors
// are parsed, and the exit codes (0 ok, 1 internal failure, 2 bad input).
#pragma once

#include <lintel/scene_io.h>
#include <lintel/status.h>
#include <lintel/world.h>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include <functional>
#include <string>

namespace lintel::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

// The selected subcommand's body; set by the add_*_command functions when CLI11 picks one.
using Command = std::function<int()>;

// "lintel: error: <message>" on stderr; returns kExitBadInput.
int fail(const std::string& message);
// The same for a status; returns its exit code (2 bad input, 1 unsupported or internal).
int fail(const Status& status);
// "lintel: warning: <message>" on stderr.
void warn(const std::string& message);

// Loads and validates a scene, printing its warnings (unless quiet). Returns the status.
Status load_scene(const std::string& path, const LoadOptions& options, World& world, std::vector<std::string>* warnings,
                  bool quiet = false);
// --allow-outside-paths, on every subcommand that loads a scene.
void add_load_options(CLI::App* cmd, LoadOptions& options);

// Parses "x,y,z" (three finite numbers). `what` names the option in the message.
Status parse_vec3(const std::string& text, const std::string& what, glm::vec3& out);

// An option check: a finite number in [lo, hi]. CLI::Range alone lets NaN through (every
// comparison with NaN is false), so every floating-point option uses this instead.
CLI::Validator finite_range(double lo, double hi);
// An option check for thread counts: 1 .. the machine's hardware threads.
CLI::Validator thread_count();

// `text` with control characters (and DEL, and bytes of broken UTF-8 are kept as is) escaped as
// \n, \t, \xNN, so that a scene's names cannot forge lines or send escape sequences to a terminal.
std::string printable(const std::string& text);

// `text` quoted for /bin/sh (single quotes, embedded ones escaped).
std::string shell_quote(const std::string& text);

void add_info_command(CLI::App& app, Command& run);
void add_validate_command(CLI::App& app, Command& run);
void add_gen_command(CLI::App& app, Command& run);
void add_vis_command(CLI::App& app, Command& run);
void add_walk_command(CLI::App& app, Command& run);
void add_cull_command(CLI::App& app, Command& run);
void add_render_command(CLI::App& app, Command& run);
void add_bench_command(CLI::App& app, Command& run);
void add_import_command(CLI::App& app, Command& run);
void add_view_command(CLI::App& app, Command& run);  // view/cmd_view.cpp
void add_export_command(CLI::App& app, Command& run);
void add_optimize_command(CLI::App& app, Command& run);  // cmd_optimize.cpp
// Members of the `bench` group (cmd_bench.cpp).
void add_bench_cull_command(CLI::App& bench, Command& run);
void add_bench_accuracy_command(CLI::App& bench, Command& run);
void add_bench_levels_command(CLI::App& bench, Command& run);
void add_bench_render_command(CLI::App& bench, Command& run);

}  // namespace lintel::cli
