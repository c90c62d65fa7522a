// `unidyn sweep` as a user runs it: plan, the Slurm script run task by task as a job array would
// (SLURM_ARRAY_TASK_ID set), gather — the table the same as one serial `sweep run` makes — and
// bad input refused with status 2, missing results with 1.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <filesystem>

#include "cli/cli_support.hpp"

extern char** environ;
#include "unidyn/numeric/shell_quoting.hpp"

namespace unidyn::cli_test {
namespace {

namespace fs = std::filesystem;

// The peak resident memory (kB) of `unidyn ARGS...` run to its end, its output to /dev/null, or -1.
long peak_kilobytes(std::vector<std::string> words) {
  words.insert(words.begin(), UNIDYN_EXECUTABLE);
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) return -1;
  int status = 0;
  struct rusage usage {};
  if (::wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return -1;
  }
  return usage.ru_maxrss;
}

// A task of a manifest of 2·10^5 runs reads only its runs: it needed 509 MB (and 3.5 s) when each
// task parsed the whole manifest; one run now needs what a run of a small manifest needs, within
// 20 MB (the streamed lines and the manifest's SHA-256 read in blocks).
TEST(Sweep, ATaskOfAHugeManifestHoldsOnlyItsRuns) {
  const fs::path dir = temp_path("huge");
  fs::create_directories(dir);
  const std::string small = (dir / "small.yaml").string(), huge = (dir / "huge.yaml").string();
  ASSERT_EQ(
      run("sweep plan double-pendulum --grid theta1=0.1:1.2:2 --t-end 0.01 -o '" + small + "'")
          .status,
      0);
  ASSERT_EQ(
      run("sweep plan double-pendulum --grid theta1=0.1:1.2:200000 --t-end 0.01 -o '" + huge + "'")
          .status,
      0);
  EXPECT_GT(fs::file_size(huge), 5'000'000u);
  const long small_kb = peak_kilobytes({"sweep", "run", small, "--chunk", "1", "--task", "1"});
  const long huge_kb = peak_kilobytes({"sweep", "run", huge, "--chunk", "1", "--task", "123456"});
  ASSERT_GT(small_kb, 0);
  ASSERT_GT(huge_kb, 0);
  EXPECT_LT(huge_kb, small_kb + 20'000) << "small " << small_kb << " kB, huge " << huge_kb << " kB";
  // the task's run is the manifest's run 123456, with its own value
  const std::string result = read_file(huge + ".runs/run-0123456.csv");
  EXPECT_TRUE(contains(result, ", run 123456, seed ")) << result;
  fs::remove_all(dir);
}

TEST(Sweep, SlurmTasksMakeTheSerialTable) {
  const fs::path dir = temp_path("sweep");
  fs::create_directories(dir);
  const std::string manifest = (dir / "dp.sweep.yaml").string();
  const Outcome planned =
      run("sweep plan double-pendulum --grid theta1=0.1:1.2:5 --random "
          "'m2=U(0.5,2)' --samples 2 --seed 3 --t-end 0.5 -o '" +
          manifest + "'");
  ASSERT_EQ(planned.status, 0) << planned.err;
  EXPECT_TRUE(contains(planned.out, "10 runs of theta1, m2 planned")) << planned.out;
  // before any run: all ten missing
  EXPECT_EQ(run("sweep gather '" + manifest + "'").status, 1);

  // the job array: 3 tasks of 4, the second one twice (a requeued task)
  const std::string script = (dir / "job.sh").string();
  ASSERT_EQ(run("sweep emit '" + manifest + "' --slurm --chunk 4 -o '" + script + "'").status, 0);
  EXPECT_TRUE(contains(read_file(script), "#SBATCH --array=0-2\n"));
  for (const char* task : {"0", "1", "2", "1"}) {
    const int status = std::system(
        ("SLURM_ARRAY_TASK_ID=" + std::string(task) + " bash '" + script + "' >/dev/null 2>&1")
            .c_str());
    EXPECT_EQ(status, 0) << "task " << task;
  }
  const Outcome gathered = run("sweep gather '" + manifest + "'");
  ASSERT_EQ(gathered.status, 0) << gathered.err;

  // the same plan run serially in another directory of results
  const Outcome serial =
      run("sweep run '" + manifest + "' --results '" + (dir / "serial").string() + "'");
  ASSERT_EQ(serial.status, 0) << serial.err;
  EXPECT_TRUE(contains(
      serial.out, "10 made (0 of them failed, 0 made again over a stale result), 0 already done"))
      << serial.out;
  const Outcome serial_table =
      run("sweep gather '" + manifest + "' --results '" + (dir / "serial").string() + "'");
  EXPECT_EQ(serial_table.out, gathered.out);
  EXPECT_EQ(lines_of(gathered.out).size(), 12u);  // the comment, the header, ten runs
  fs::remove_all(dir);
}

TEST(Sweep, BadInputIsRefused) {
  const std::string manifest = temp_path("bad.sweep.yaml");
  EXPECT_EQ(run("sweep plan double-pendulum -o '" + manifest + "'").status, 2);  // nothing swept
  EXPECT_EQ(run("sweep plan double-pendulum --grid 'theta1=0:1' -o '" + manifest + "'").status, 2);
  const Outcome unknown =
      run("sweep plan double-pendulum --grid 'length=0:1:3' -o '" + manifest + "'");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_TRUE(contains(unknown.err, "length")) << unknown.err;
  EXPECT_EQ(run("sweep plan double-pendulum --random 'm2=U(2,1)' -o '" + manifest + "'").status, 2);
  EXPECT_EQ(
      run("sweep plan double-pendulum --grid theta1=0:1:3 --method euler -o '" + manifest + "'")
          .status,
      2);
  ASSERT_EQ(run("sweep plan double-pendulum --grid theta1=0:1:3 -o '" + manifest + "'").status, 0);
  EXPECT_EQ(run("sweep run '" + manifest + "' --rows 2:9").status, 2);
  EXPECT_EQ(run("sweep run '" + manifest + "' --chunk 2 --task 2").status, 2);
  EXPECT_EQ(run("sweep emit '" + manifest + "'").status, 2);  // neither --slurm nor --parallel
  write_file(manifest, "unidyn_sweep: 1\nmodel: [\n");
  const Outcome damaged = run("sweep run '" + manifest + "'");
  EXPECT_EQ(damaged.status, 2);
  EXPECT_TRUE(contains(damaged.err, manifest + ":")) << damaged.err;
  std::remove(manifest.c_str());
}

// A manifest in a directory whose name holds quotes, $(), backticks, spaces and a newline: the
// launchers run the sweep there and run nothing the name says (it used to run `touch PWNED`).
TEST(Sweep, LaunchersRunNothingAPathSays) {
  const fs::path base = fs::path(temp_path("hostile-sweep"));
  fs::remove_all(base);
  const fs::path dir = base / "inj'$(touch PWNED)'`touch TICKED` a\nb";
  fs::create_directories(dir);
  const std::string manifest = (dir / "hoop.sweep.yaml").string();
  const std::string here = "cd " + shell_quoted(base.string()) + " && ";
  ASSERT_EQ(
      run("sweep plan rotating-hoop --grid Omega=1:2:2 --t-end 0.1 -o " + shell_quoted(manifest))
          .status,
      0);
  const std::string slurm = (base / "job.sh").string(), parallel = (base / "par.sh").string();
  ASSERT_EQ(
      run("sweep emit " + shell_quoted(manifest) + " --slurm --chunk 1 -o " + shell_quoted(slurm))
          .status,
      0);
  ASSERT_EQ(run("sweep emit " + shell_quoted(manifest) + " --parallel --chunk 1 -o " +
                shell_quoted(parallel))
                .status,
            0);
  EXPECT_EQ(std::system((here + "SLURM_ARRAY_TASK_ID=0 bash job.sh >/dev/null 2>&1").c_str()), 0);
  if (std::system("command -v parallel >/dev/null 2>&1") == 0) {
    EXPECT_EQ(std::system((here + "bash par.sh >/dev/null 2>&1").c_str()), 0);
    EXPECT_EQ(run("sweep gather " + shell_quoted(manifest)).status, 0);
  }
  for (const char* planted : {"PWNED", "TICKED"}) {
    EXPECT_FALSE(fs::exists(base / planted)) << planted;
    EXPECT_FALSE(fs::exists(dir / planted)) << planted;
    EXPECT_FALSE(fs::exists(fs::current_path() / planted)) << planted;
  }
  fs::remove_all(base);
}

}  // namespace
}  // namespace unidyn::cli_test
