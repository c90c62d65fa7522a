// The sweep commands on the command line: options in, exit statuses out.
#include "sweep_command.hpp"

#include <filesystem>
#include <iostream>

#include "unidyn/model/system.hpp"

namespace unidyn::cli {

void add_sweep_command(CLI::App& app, SweepCommand& c) {
  commands::SweepOptions& o = c.options;
  c.sweep = app.add_subcommand("sweep", "Ensembles of runs: plan, run chunks, gather, launchers");
  c.sweep->require_subcommand(1);
  c.plan =
      c.sweep->add_subcommand("plan", "Write a manifest: one row per run, each with its values");
  c.plan->add_option("model", o.model, "MODEL file or bundled model name")->required();
  c.plan->add_option("--grid", o.grid, "NAME=FROM:TO:COUNT: a parameter, q or der(q) on a grid");
  c.plan->add_option("--random", o.random, "NAME=U(A,B) or NAME=N(MEAN,SD): drawn per run");
  c.plan->add_option("--samples", o.samples, "random draws per grid point")->capture_default_str();
  // checked as text, before the conversion that would take -1 for 2^64 - 1
  c.plan->add_option("--seed", o.seed, "the draws' seed")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  c.plan->add_option("--modes-at", o.modes_at,
                     "NAME=VALUE of an operating point (as `unidyn modes --at`): each run also "
                     "gives the stability and eigenvalues there with its parameters");
  c.plan
      ->add_option("--times", o.times,
                   "T1,T2,...: each run also keeps its rows at these times (rows' times: the "
                   "output step's multiples)")
      ->delimiter(',');
  c.plan->add_option("--t-end", o.t_end, "end time of every run")->check(CLI::PositiveNumber);
  c.plan->add_option("--output-step", o.output_step, "time between rows")
      ->check(CLI::PositiveNumber);
  c.plan->add_option("--method", o.method, integration_method_choices());
  c.plan->add_option("--rtol", o.rtol, "relative tolerance")->check(CLI::PositiveNumber);
  c.plan->add_option("-o,--output", o.output, "the manifest (default MODEL.sweep.yaml)");

  c.run = c.sweep->add_subcommand("run", "Run a chunk of a manifest's runs (done ones skipped)");
  c.run->add_option("manifest", o.model, "the manifest")->required();
  c.run->add_option("--rows", o.rows, "A:B: the runs A to B-1 (default all)");
  c.run->add_option("--chunk", o.chunk, "with --task: runs per task");
  c.run->add_option("--task", o.task, "with --chunk: the task (Slurm's SLURM_ARRAY_TASK_ID)");
  c.run->add_option("--results", o.results, "the results' directory (default MANIFEST.runs)");

  c.gather = c.sweep->add_subcommand("gather", "One table of the results, in the runs' order");
  c.gather->add_option("manifest", o.model, "the manifest")->required();
  c.gather->add_option("--results", o.results, "the results' directory (default MANIFEST.runs)");
  c.gather->add_flag("--times", o.rows_at_times,
                     "one row per run and planned time (tidy): its values, ok, its row there");
  c.gather->add_option("-o,--output", o.output, "the table (default standard output)");

  c.emit = c.sweep->add_subcommand("emit", "Write a launcher script for the manifest");
  c.emit->add_option("manifest", o.model, "the manifest")->required();
  c.emit->add_flag("--slurm", o.slurm, "a Slurm job array");
  c.emit->add_flag("--parallel", o.parallel, "GNU parallel");
  c.emit->add_option("--chunk", o.chunk, "runs per task (default 10)");
  c.emit->add_option("-o,--output", o.output, "the script (default standard output)");
}

int run_sweep_command(const SweepCommand& c) {
  if (c.plan->parsed()) {
    commands::plan_sweep_file(c.options, std::cout);
    return 0;
  }
  if (c.run->parsed()) {
    commands::run_sweep_chunk(c.options, std::cout);
    return 0;
  }
  if (c.gather->parsed()) return commands::gather_sweep_table(c.options, std::cout) ? 0 : 1;
  // the launchers run this very executable
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  commands::emit_sweep_script(c.options, error ? std::string("unidyn") : self.string(), std::cout);
  return 0;
}

}  // namespace unidyn::cli
