#pragma once
// Each `covsim` subcommand registers itself on the application; the work is done by the
// libraries, so commands only parse arguments and print.
#include <CLI/CLI.hpp>

namespace covsim::app {

void add_cells_command(CLI::App& app);
void add_describe_command(CLI::App& app);
void add_kernel_demo_command(CLI::App& app);
void add_list_command(CLI::App& app);
void add_merge_command(CLI::App& app);
void add_planner_contract_command(CLI::App& app);
void add_plot_command(CLI::App& app);
void add_random_env_command(CLI::App& app);
void add_replay_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_sweep_command(CLI::App& app);

}  // namespace covsim::app
