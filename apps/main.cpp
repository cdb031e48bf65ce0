// covsim: the command-line front end. Exit codes: 0 success, 1 a run failed, 2 bad input.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "apps/typo_hint.hpp"
#include "core/trace.hpp"
#include "io/interrupt.hpp"
#include "scenarios/scenario_error.hpp"
#include "sim/provenance.hpp"

namespace {

// What a command printed reached standard output: a full disk or a closed pipe behind it is a
// failed command (exit 1), not a silent loss.
int standard_output_written() {
  std::cout.flush();
  errno = 0;
  if (std::fflush(stdout) == 0 && !std::ferror(stdout) && std::cout) return 0;
  const int error = errno;
  std::cerr << "covsim: cannot write to standard output"
            << (error != 0 ? std::string(": ") + std::strerror(error) : std::string()) << '\n';
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"covsim: discrete-event simulation of multi-robot Voronoi coverage"};
  app.set_version_flag("--version", covsim::describe_build(covsim::this_build()));
  app.require_subcommand(1);
  covsim::app::add_cells_command(app);
  covsim::app::add_describe_command(app);
  covsim::app::add_kernel_demo_command(app);
  covsim::app::add_list_command(app);
  covsim::app::add_merge_command(app);
  covsim::app::add_planner_contract_command(app);
  covsim::app::add_plot_command(app);
  covsim::app::add_random_env_command(app);
  covsim::app::add_replay_command(app);
  covsim::app::add_run_command(app);
  covsim::app::add_sweep_command(app);
  covsim::install_interrupt_handlers();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    if (code != 0) {
      if (const auto hint = covsim::app::typo_hint(app, argc, argv))
        std::cerr << "covsim: " << *hint << '\n';
    }
    return code == 0 ? 0 : 2;
  } catch (const covsim::Interrupted& e) {
    std::cerr << "covsim: " << e.what() << "; partial outputs removed\n";
    return 128 + e.signal;
  } catch (const covsim::TraceFormatError& e) {
    std::cerr << "covsim: " << e.what() << '\n';
    return 2;
  } catch (const covsim::ScenarioError& e) {
    std::cerr << "covsim: " << e.what() << '\n';
    return 2;
  } catch (const covsim::app::InputError& e) {
    std::cerr << "covsim: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "covsim: " << e.what() << '\n';
    return 1;
  }
  return standard_output_written();
}
