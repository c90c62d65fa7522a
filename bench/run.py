#!/usr/bin/env python3
"""Side-by-side benchmarks of unidyn against SymPy mechanics, MuJoCo, Simbody and DART.

Usage: python3 bench/run.py BUILD_DIR [--quick]

BUILD_DIR holds the built benchmark programs (bench/unidyn_bench, bench/peers/peer_mujoco,
bench/peers/peer_simbody, bench/peers/peer_dart). Every figure below is measured in this one run; the tables go to
standard output and to bench/RESULTS.md. --quick shrinks the sweeps and the models (a smoke test
of every part, about a minute; CI runs it) and leaves bench/RESULTS.md alone. A part that fails is reported and the run goes on; the exit
status is then 1.

The models are those of bench/MODELS.md. Each comparison first checks that the tools compute the
same thing (accelerations at random states, final states against a tight reference) and prints
the largest disagreement next to the timing.
"""

import argparse
import datetime
import json
import math
import os
import platform
import random
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


# ---------------------------------------------------------------------------------------------
# Running the programs

def run(command, stdin=None, timeout=1800, env=None):
    """Run a command; its standard output (raises on a non-zero exit)."""
    # in a scratch directory: MuJoCo writes MUJOCO_LOG.TXT where it runs
    result = subprocess.run(command, input=stdin, capture_output=True, text=True, timeout=timeout,
                            cwd=tempfile.gettempdir(), env=env)
    if result.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed ({result.returncode}): "
                           f"{result.stderr.strip()[:500]}")
    return result.stdout


def fastest(command, runs=3, timeout=300):
    """The shortest wall time of `runs` runs of a command, and the last run's result (raises on a
    non-zero exit)."""
    best, out = None, None
    for _ in range(runs):
        start = time.perf_counter()
        out = subprocess.run(command, capture_output=True, text=True, timeout=timeout, check=True)
        elapsed = time.perf_counter() - start
        best = elapsed if best is None else min(best, elapsed)
    return best, out


def run_json(command, stdin=None, timeout=1800):
    """The last line of a command's output, read as JSON."""
    return json.loads(run(command, stdin, timeout).strip().splitlines()[-1])


def rhs_output(text):
    """Accelerations (one list per state) and ns_per_eval from a `rhs` run."""
    rows, ns = [], None
    for line in text.splitlines():
        fields = line.split()
        if not fields:
            continue
        if fields[0] == "ns_per_eval":
            ns = float(fields[1])
        elif fields[0] != "evaluation":
            rows.append([float(x) for x in fields])
    return rows, ns


def canonical(state):
    """A peer state with its quaternion's sign fixed (w ≥ 0): q and −q are one rotation."""
    if len(state) == 7 and state[0] < 0:
        return [-x for x in state[:4]] + list(state[4:])
    return list(state)


def max_relative_difference(a_rows, b_rows):
    """Largest |a − b| / (1 + |b|) over matching rows."""
    worst = 0.0
    for a, b in zip(a_rows, b_rows):
        for x, y in zip(a, b):
            worst = max(worst, abs(x - y) / (1.0 + abs(y)))
    return worst


# ---------------------------------------------------------------------------------------------
# States

def pendulum_states(n, count, rng):
    """Random (q, q̇) of pendulum-n."""
    return [[rng.uniform(-1, 1) for _ in range(n)] + [rng.uniform(-1, 1) for _ in range(n)]
            for _ in range(count)]


def top_euler_states(count, rng):
    """Random 3-1-3 angles and rates of the heavy top, away from θ = 0."""
    return [[rng.uniform(-3, 3), rng.uniform(0.3, 2.8), rng.uniform(-3, 3),
             rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(20, 60)] for _ in range(count)]


def disk_states(count, rng):
    """Random states of the rolling disk that satisfy its three constraints."""
    R = 0.15
    states = []
    for _ in range(count):
        psi, theta, phi = rng.uniform(-3, 3), rng.uniform(0.5, 2.6), rng.uniform(-3, 3)
        dpsi, dtheta, dphi = rng.uniform(-2, 2), rng.uniform(-1, 1), rng.uniform(5, 15)
        # ω = ψ̇ E3 + θ̇ (line of nodes) + φ̇ e3 for 3-1-3 angles
        nodes = (math.cos(psi), math.sin(psi), 0.0)
        e3 = (math.sin(psi) * math.sin(theta), -math.cos(psi) * math.sin(theta), math.cos(theta))
        w = [dpsi * (0, 0, 1)[k] + dtheta * nodes[k] + dphi * e3[k] for k in range(3)]
        # contact point π = R (cos θ sin ψ, −cos θ cos ψ, −sin θ); v̄ = −ω × π
        p = (R * math.cos(theta) * math.sin(psi), -R * math.cos(theta) * math.cos(psi),
             -R * math.sin(theta))
        cross = (w[1] * p[2] - w[2] * p[1], w[2] * p[0] - w[0] * p[2], w[0] * p[1] - w[1] * p[0])
        v = [-c for c in cross]
        states.append([rng.uniform(-1, 1), rng.uniform(-1, 1), R * math.sin(theta), psi, theta,
                       phi, v[0], v[1], v[2], dpsi, dtheta, dphi])
    return states


def quaternion_states(count, rng, spin):
    """Random unit quaternions (w ≥ 0) and body angular velocities."""
    states = []
    for _ in range(count):
        q = [rng.gauss(0, 1) for _ in range(4)]
        norm = math.sqrt(sum(x * x for x in q))
        q = [x / norm * (1 if q[0] >= 0 else -1) for x in q]
        states.append(q + [rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-spin, spin)])
    return states


def write_states(states):
    """States as text, one per line."""
    return "".join(" ".join(repr(x) for x in s) + "\n" for s in states)


# ---------------------------------------------------------------------------------------------
# The comparisons

class Bench:
    def __init__(self, build, quick):
        self.build = os.path.abspath(build)
        self.quick = quick
        self.rng = random.Random(2026)
        self.unidyn = os.path.join(self.build, "bench", "unidyn_bench")
        self.mujoco = os.path.join(self.build, "bench", "peers", "peer_mujoco")
        self.simbody = os.path.join(self.build, "bench", "peers", "peer_simbody")
        self.dart = os.path.join(self.build, "bench", "peers", "peer_dart")
        self.sympy = [sys.executable, os.path.join(HERE, "sympy", "derive.py")]
        self.lines = []

    def say(self, text=""):
        print(text, flush=True)
        self.lines.append(text)

    def have(self, program):
        return os.path.exists(program)

    def sympy_version(self):
        """The version of the SymPy the comparisons run (that of this interpreter)."""
        return run([sys.executable, "-c", "import sympy; print(sympy.__version__)"]).strip()

    # 1. Derivation against SymPy ---------------------------------------------------------------
    def derivation(self):
        self.say(f"## 1. Derivation: unidyn against SymPy {self.sympy_version()} mechanics\n")
        self.say("Time to derive the equations of motion, best of 3 for unidyn, one run for SymPy "
                 "(unidyn: read the model and form M q̈ = f, by Lagrange's equations and by Kane's "
                 "form through partial velocities; SymPy: build the system and form the equations "
                 "with their mass matrix and forcing, by LagrangesMethod and KanesMethod). q̈ of "
                 "all four compared at 3 random states.\n")
        self.say("| model | unidyn Lagrange | SymPy Lagrange | ratio | unidyn Kane | SymPy Kane "
                 "| ratio | max q̈ difference |")
        self.say("|---|---|---|---|---|---|---|---|")
        links = [1, 2, 3] if self.quick else list(range(1, 11))
        models = [f"pendulum-{n}" for n in links] + ["heavy-top", "rolling-disk"]
        limit = {"lagrange": 900, "kane": 900}
        for model in models:
            if model.startswith("pendulum-"):
                states = pendulum_states(int(model.split("-")[1]), 3, self.rng)
            elif model == "heavy-top":
                states = top_euler_states(3, self.rng)
            else:
                states = disk_states(3, self.rng)
            with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
                f.write(write_states(states))
                path = f.name
            cells, worst, reference = [], 0.0, None
            for method in ("lagrange", "kane"):
                ours = run_json([self.unidyn, "derive", model, "--method", method, "--repeat",
                                 "3", "--states", path])
                reference = reference or ours["qddot"]
                worst = max(worst, max_relative_difference(ours["qddot"], reference))
                cells.append(f"{ours['derive_seconds'] * 1e3:.3g} ms")
                if limit[method] is None:
                    cells += ["not run", ""]
                    continue
                try:
                    theirs = run_json(self.sympy + [model, "--method", method, "--states", path],
                                      timeout=limit[method])
                except subprocess.TimeoutExpired:
                    cells += [f"> {limit[method]} s", ""]
                    limit[method] = None  # larger models would take longer still
                    continue
                except RuntimeError:
                    cells += ["failed", ""]
                    continue
                worst = max(worst, max_relative_difference(theirs["qddot"], reference))
                cells += [f"{theirs['derive_seconds']:.3g} s",
                          f"{theirs['derive_seconds'] / ours['derive_seconds']:.0f}×"]
            os.unlink(path)
            self.say(f"| {model} | " + " | ".join(cells) + f" | {worst:.1e} |")
        self.say()

    # 8. Analysis against SymPy's Linearizer ------------------------------------------------------
    def analysis(self):
        self.say("## 8. Analysis: linearisation and modes against SymPy's Linearizer\n")
        self.say("Whole `unidyn` processes (read, derive, compile, complete the operating point, "
                 "linearise with exact derivatives, eigenvalues), best of 3; SymPy "
                 f"{self.sympy_version()}: `KanesMethod` with the constraints' dependent coordinate and speeds, then "
                 "`linearize(A_and_B=True)` at the operating point (bench/sympy/linearize.py), one "
                 "run, derivation and linearisation timed apart. The rolling disk upright at "
                 "spin 10 rad/s; the benchmark bicycle upright at 4.6 m/s, and a sweep of 1000 "
                 "speeds with the weave and capsize speeds (SymPy's derivation and linearisation "
                 "of the bicycle takes minutes and is not run). Goals of issue 14: the disk ≤ 50 "
                 "ms, the bicycle ≤ 1 s, the sweep ≤ 2 s.\n")
        self.say("| model | unidyn | SymPy derive | SymPy linearize | ratio | eigenvalues |")
        self.say("|---|---|---|---|---|---|")
        cli = os.path.join(self.build, "unidyn")
        disk = ["modes", "rolling-disk", "--at", "theta=pi/2", "der(phi)=10", "der(psi)=0",
                "der(theta)=0", "--format", "json"]
        bicycle_at = ["--at", "der(thR)=v/rR", "der(phi)=0", "der(delta)=0", "der(psi)=0"]

        def best_of_three(arguments):
            return fastest([cli] + arguments)

        seconds, out = best_of_three(disk)
        ours = json.loads(out.stdout)
        ours_lambda = sorted(abs(m["im"]) for m in ours["modes"] if m["im"] != 0)
        theirs = run_json([sys.executable, os.path.join(HERE, "sympy", "linearize.py")],
                          timeout=600)
        theirs_lambda = sorted(abs(i) for r, i in theirs["eigenvalues"] if i > 0)
        difference = max((abs(a - b) for a, b in zip(ours_lambda, theirs_lambda)), default=0.0)
        total = theirs["derive_seconds"] + theirs["linearize_seconds"]
        self.say(f"| rolling disk | {seconds * 1e3:.0f} ms | {theirs['derive_seconds']:.2f} s "
                 f"| {theirs['linearize_seconds']:.2f} s | {total / seconds:.0f}× | "
                 f"±{ours_lambda[0]:.10f}i (SymPy ±{theirs_lambda[0]:.10f}i, difference "
                 f"{difference:.1e}) |")
        seconds, out = best_of_three(["modes", "bicycle"] + bicycle_at)
        stability = out.stdout.strip().splitlines()[-1].split(":")[1].strip()
        self.say(f"| bicycle at 4.6 m/s | {seconds:.2f} s | not run | not run | | {stability} |")
        seconds, out = best_of_three(["modes", "bicycle"] + bicycle_at +
                                     ["--sweep", "v=0:10:1000"])
        speeds = [line.split("=")[1].split(":")[0].strip()
                  for line in out.stderr.splitlines() if line.startswith("stability changes")]
        self.say(f"| bicycle, 1000 speeds | {seconds:.2f} s | not run | not run | | weave and "
                 f"capsize at {' and '.join(speeds)} m/s (Meijaard et al.: 4.29238253634111 and "
                 f"6.02426201538837) |")
        self.say()

    # 9. Ensembles: the overhead of a sweep --------------------------------------------------------
    def batched_rhs(self, package, cli):
        """`Model.rhs` over many states in one call against one call per state (Python): the
        per-call throughput and the batch's, and whether the accelerations are the same bits."""
        if not os.path.isdir(os.path.join(package, "unidyn")):
            return "Batched right-hand side: the Python module is not built."
        count = 2000 if self.quick else 20000
        script = f"""
import json, time, numpy, unidyn
model = unidyn.load("double-pendulum")
rng = numpy.random.default_rng(3)
q, qd = rng.uniform(-1, 1, ({count}, 2)), rng.uniform(-1, 1, ({count}, 2))
model.rhs(q[0], qd[0])  # compiled before either is timed
start = time.perf_counter()
single = numpy.array([model.rhs(q[k], qd[k])[0] for k in range({count})])
per_call = time.perf_counter() - start
start = time.perf_counter()
batch = model.rhs(q, qd)[0]
batched = time.perf_counter() - start
print(json.dumps({{"per_call": per_call, "batched": batched,
                  "same": bool((single == batch).all())}}))
"""
        env = dict(os.environ, PYTHONPATH=package, UNIDYN_EXECUTABLE=cli)
        r = json.loads(run(["/usr/bin/python3", "-c", script], env=env).splitlines()[-1])
        return (f"Batched right-hand side (goal of issue 17: ≥ 1.5× the per-call throughput): "
                f"`Model.rhs` of the double pendulum at {count} random states, one call per state "
                f"{r['per_call'] / count * 1e6:.2f} µs a state, one call with the {count} × 2 "
                f"arrays {r['batched'] / count * 1e6:.3f} µs a state "
                f"({r['per_call'] / r['batched']:.0f}×); accelerations "
                f"{'identical bit for bit' if r['same'] else 'DIFFERENT'}. The batch is a loop of "
                f"the compiled solve in C++ (no vectorisation across states).\n")

    def ensembles(self):
        runs = 6 if self.quick else 40
        self.say("## 9. Ensembles: a sweep against plain `simulate` calls\n")
        self.say(f"{runs} runs of the double pendulum, m1 on a grid from 1 to 2, 1000 s each at "
                 "rtol 1e-10 (about 0.15 s a run). From Python, in one process: `unidyn.sweep` "
                 "(serial) against a loop of `Model.simulate` with the same settings, the model "
                 "compiled before either is timed — the sweep's overhead, goal of issue 16: ≤ 5 %. "
                 "From the command line: `unidyn sweep run` over the manifest of `sweep plan` (one "
                 "process, the model read and compiled once, a result file per run) against one "
                 "`unidyn simulate` process per run writing its CSV of 100 001 rows. The final "
                 "states of the sweep and of `simulate` are compared.\n")
        cli = os.path.join(self.build, "unidyn")
        common = ["--t-end", "1000", "--rtol", "1e-10"]
        cells = ["not built", "", ""]
        package = os.path.join(self.build, "python")
        if os.path.isdir(os.path.join(package, "unidyn")):
            script = f"""
import json, time, unidyn
model = unidyn.load("double-pendulum")
settings = [{{"m1": 1 + i / ({runs} - 1)}} for i in range({runs})]
options = dict(t_end=1000.0, rtol=1e-10)
model.simulate(t_end=1.0)  # compiled before either is timed
start = time.perf_counter()
loop = [model.simulate(set=s, **options) for s in settings]
looped = time.perf_counter() - start
start = time.perf_counter()
swept = unidyn.sweep(model, settings, **options)
print(json.dumps({{"loop": looped, "sweep": time.perf_counter() - start}}))
"""
            env = dict(os.environ, PYTHONPATH=package, UNIDYN_EXECUTABLE=cli)
            python = json.loads(run(["/usr/bin/python3", "-c", script], env=env).splitlines()[-1])
            cells = [f"{python['loop']:.2f} s", f"{python['sweep']:.2f} s",
                     f"{(python['sweep'] / python['loop'] - 1) * 100:+.1f} %"]
        with tempfile.TemporaryDirectory() as scratch:
            manifest = os.path.join(scratch, "m.yaml")
            run([cli, "sweep", "plan", "double-pendulum", "--grid", f"m1=1:2:{runs}", "-o",
                 manifest] + common)
            # one process per run
            finals = []
            start = time.perf_counter()
            for i in range(runs):
                csv = os.path.join(scratch, "run.csv")
                run([cli, "simulate", "double-pendulum", "--set", f"m1={1 + i / (runs - 1)!r}",
                     "-o", csv] + common)
                with open(csv) as f:
                    finals.append([float(x) for x in f.read().strip().splitlines()[-1].split(",")])
            processes = time.perf_counter() - start
            # the sweep: one process
            start = time.perf_counter()
            run([cli, "sweep", "run", manifest])
            swept = time.perf_counter() - start
            table = run([cli, "sweep", "gather", manifest]).strip().splitlines()
            first = table[1].split(",").index("final.t")
            rows = [[float(x) for x in line.split(",")[first:]] for line in table[2:]]
            difference = max_relative_difference(rows, finals)
        self.say("| runs | Python: loop of `simulate` | `unidyn.sweep` | sweep's overhead | "
                 "one `unidyn simulate` per run | `unidyn sweep run` | ratio | largest "
                 "final-state difference |")
        self.say("|---|---|---|---|---|---|---|---|")
        self.say(f"| {runs} | " + " | ".join(cells) + f" | {processes:.2f} s | {swept:.2f} s | "
                 f"{processes / swept:.2f}× | {difference:.1e} |")
        self.say()
        if os.path.isdir(os.path.join(package, "unidyn")):
            self.say(self.parallel_sweeps(package, cli))
            self.say()
        self.say(self.batched_rhs(package, cli))
        self.say()

    def parallel_sweeps(self, package, cli):
        """unidyn.sweep on 2 worker processes (a process pool, a Dask LocalCluster) against the
        same runs as a plain map of simulate on the same workers (its overhead), and against a
        loop in one process (the speed-up the machine gives), at ~0.1 s and ~10 ms a run; the
        throughput of tiny runs."""
        runs = 8 if self.quick else 40
        tiny = 200 if self.quick else 4000
        script = f"""
import functools, json, time, unidyn
from concurrent.futures import ProcessPoolExecutor
from distributed import Client, LocalCluster

@functools.lru_cache(maxsize=1)
def model():
    return unidyn.load("double-pendulum")

def plain(text, settings, t_end):
    # the same runs without unidyn.sweep's bookkeeping: a loop of simulate on the worker, the
    # model loaded once per process as the sweep loads it, last rows back
    import unidyn
    model = unidyn._loaded(text)
    return [model.simulate(set=s, t_end=t_end).data[-1] for s in settings]

def timed(f):
    start = time.perf_counter(); f(); return time.perf_counter() - start

model().simulate(t_end=1.0)  # compiled before anything is timed
text = model().text
out = {{}}
with ProcessPoolExecutor(2) as pool, LocalCluster(n_workers=2, threads_per_worker=1,
        processes=True, dashboard_address=None) as cluster, Client(cluster) as client:
    for kind, t_end, count, chunk in (("slow", 200.0, {runs}, 2), ("fast", 20.0, {runs}, 2),
                                      ("tiny", 0.01, {tiny}, 50)):
        settings = [{{"m1": 1 + i / count}} for i in range(count)]
        pieces = [settings[k:k + chunk] for k in range(0, count, chunk)]
        for executor in (pool, client):  # the workers load and compile the model first
            [f.result() for f in [executor.submit(plain, text, settings[:1], 0.01)
                                  for _ in range(4)]]
            unidyn.sweep(model(), settings[:4], executor=executor, chunk=1, t_end=0.01)
        row = {{"count": count,
                "loop": timed(lambda: [model().simulate(set=s, t_end=t_end) for s in settings])}}
        for name, executor in (("pool", pool), ("dask", client)):
            row[name + "_plain"] = timed(lambda: [f.result() for f in [
                executor.submit(plain, text, piece, t_end) for piece in pieces]])
            row[name] = timed(lambda: unidyn.sweep(model(), settings, executor=executor,
                                                   chunk=chunk, t_end=t_end))
        out[kind] = row
print(json.dumps(out))
"""
        env = dict(os.environ, PYTHONPATH=package, UNIDYN_EXECUTABLE=cli)
        r = json.loads(run(["/usr/bin/python3", "-c", script], env=env,
                           timeout=3600).splitlines()[-1])
        lines = ["Parallel sweeps: `unidyn.sweep` of the double pendulum on 2 worker processes — a "
                 "`concurrent.futures` process pool and a Dask `LocalCluster`, each worker having "
                 "loaded and compiled the model before the timing — against the same runs as a "
                 "plain map of `simulate` over the same chunks on the same workers (the sweep's "
                 "overhead; goal of issue 39: ≤ 5 % at 0.1 s a run) and against a loop in one "
                 "process (the speed-up the 2 cores give). Tiny runs (t_end = 0.01 s): runs per "
                 "second.\n",
                 "| runs | a run (loop) | loop | pool: plain map | pool: `sweep` | overhead | "
                 "Dask: plain map | Dask: `sweep` | overhead | speed-up (pool) |",
                 "|---|---|---|---|---|---|---|---|---|---|"]
        for kind in ("slow", "fast"):
            x = r[kind]
            lines.append(f"| {x['count']} | {x['loop'] / x['count'] * 1e3:.0f} ms | "
                         f"{x['loop']:.2f} s | {x['pool_plain']:.2f} s | {x['pool']:.2f} s | "
                         f"{(x['pool'] / x['pool_plain'] - 1) * 100:+.1f} % | "
                         f"{x['dask_plain']:.2f} s | {x['dask']:.2f} s | "
                         f"{(x['dask'] / x['dask_plain'] - 1) * 100:+.1f} % | "
                         f"{x['loop'] / x['pool']:.2f}× |")
        x = r["tiny"]
        lines.append(f"\nTiny runs: {x['count']} of {x['loop'] / x['count'] * 1e3:.2f} ms each "
                     f"(chunks of 50) — loop {x['count'] / x['loop']:.0f} runs/s; process pool "
                     f"{x['count'] / x['pool']:.0f} runs/s with `sweep` "
                     f"({x['count'] / x['pool_plain']:.0f} as a plain map); Dask "
                     f"{x['count'] / x['dask']:.0f} runs/s ({x['count'] / x['dask_plain']:.0f}).")
        return "\n".join(lines)

    # 7. Micro benchmarks -------------------------------------------------------------------------
    def micro(self):
        self.say("## 7. Micro benchmarks (Google Benchmark)\n")
        self.say("```")
        for name in ("bench_tape", "bench_rotation", "bench_integrate"):
            program = os.path.join(self.build, "bench", name)
            if not self.have(program):
                continue
            text = run([program, "--benchmark_min_time=0.05"])
            for line in text.splitlines():
                if line.startswith("BM_"):
                    self.say(line)
        self.say("```\n")

    # 2. Right-hand side against MuJoCo and Simbody ----------------------------------------------
    def right_hand_side(self):
        self.say("## 2. Right-hand side: (q, q̇) → q̈\n")
        self.say("Time of one evaluation at a state (unidyn: compiled equations and the "
                 "constrained solve; MuJoCo: mj_forward; Simbody: realize to Acceleration). "
                 "Accelerations compared at 3 random states (pendulums: q̈; bodies: ω̇ in body "
                 "components).\n")
        self.say("| model | unidyn native | unidyn tape | MuJoCo | MuJoCo / unidyn | Simbody "
                 "| Simbody / unidyn | max difference |")
        self.say("|---|---|---|---|---|---|---|---|")
        links = (1, 2, 5, 10) if self.quick else (1, 2, 5, 10, 20)
        models = [f"pendulum-{n}" for n in links] + ["heavy-top", "torque-free"]
        for model in models:
            if model.startswith("pendulum-"):
                states = pendulum_states(int(model.split("-")[1]), 3, self.rng)
            else:
                states = quaternion_states(3, self.rng, 60 if model == "heavy-top" else 5)
            text = write_states(states)
            native, ns_native = rhs_output(run([self.unidyn, "rhs", model], text))
            _, ns_tape = rhs_output(run([self.unidyn, "rhs", model, "--evaluation", "tape"], text))
            cells, worst = [], 0.0
            for peer in (self.mujoco, self.simbody):
                if not self.have(peer):
                    cells += ["not built", ""]
                    continue
                rows, ns = rhs_output(run([peer, "rhs", model], text))
                worst = max(worst, max_relative_difference(native, rows))
                cells += [f"{ns:.0f} ns", f"{ns / ns_native:.1f}×"]
            self.say(f"| {model} | {ns_native:.0f} ns | {ns_tape:.0f} ns | {cells[0]} | {cells[1]} "
                     f"| {cells[2]} | {cells[3]} | {worst:.1e} |")
        self.say()

    # 3. Time to accuracy -------------------------------------------------------------------------
    def time_to_accuracy(self):
        self.say("## 3. Time to accuracy: 100 s with relative energy error ≤ 1e-8\n")
        self.say("Each tool's setting (tolerance or step) is swept; the fastest run whose largest "
                 "relative energy error is at most 1e-8 and whose final state is within 1e-6 "
                 "(relative to 1 + |x|) of a reference (unidyn, Dormand–Prince at rtol 1e-13) "
                 "counts. Wall time of the integration alone.\n")
        self.say("| model | tool | method | setting | wall time | energy error | final-state "
                 "error | ratio to unidyn |")
        self.say("|---|---|---|---|---|---|---|---|")
        t_end = "2" if self.quick else "100"
        whole = ""
        for model in ("heavy-top", "pendulum-2"):
            reference = run_json([self.unidyn, "simulate", model, "--t-end", t_end, "--method",
                                  "dopri5", "--rtol", "1e-13"])["final_state"]
            candidates = []
            for method in ("dopri5", "dop853"):
                for rtol in ("1e-6", "1e-7", "3e-8", "1e-8", "1e-9", "1e-10", "1e-11", "1e-12"):
                    candidates.append(("unidyn", method, f"rtol {rtol}", [
                        self.unidyn, "simulate", model, "--t-end", t_end, "--method", method,
                        "--rtol", rtol]))
            for method, steps in (("rattle", ("1e-3", "3e-4", "1e-4")),
                                  ("rattle4", ("1e-2", "5e-3", "2e-3", "1e-3")),
                                  ("rattle6", ("2e-2", "1e-2", "5e-3", "2e-3"))):
                for step in steps:
                    candidates.append(("unidyn", method, f"h {step}", [
                        self.unidyn, "simulate", model, "--t-end", t_end, "--method", method,
                        "--step", step]))
            if self.have(self.mujoco):
                for integrator in ("rk4", "euler"):
                    for dt in ("1e-3", "3e-4", "1e-4", "3e-5", "1e-5"):
                        candidates.append(("MuJoCo", integrator, f"dt {dt}", [
                            self.mujoco, "simulate", model, "--t-end", t_end, "--integrator",
                            integrator, "--dt", dt]))
            if self.have(self.simbody):
                for accuracy in ("1e-8", "1e-9", "1e-10", "1e-11", "1e-12"):
                    candidates.append(("Simbody", "rkmerson", f"accuracy {accuracy}", [
                        self.simbody, "simulate", model, "--t-end", t_end, "--integrator",
                        "rkmerson", "--accuracy", accuracy]))
            best = {}
            for tool, method, setting, command in candidates:
                try:
                    result = run_json(command, timeout=600)
                except (RuntimeError, subprocess.TimeoutExpired) as error:
                    self.say(f"<!-- {tool} {method} {setting}: {str(error)[:200]} -->")
                    continue
                state_error = max_relative_difference([canonical(result["final_state"])],
                                                      [canonical(reference)])
                ok = result["max_relative_energy_error"] <= 1e-8 and state_error <= 1e-6
                key = (tool, method)
                if ok and (key not in best or result["wall_seconds"] < best[key][1]["wall_seconds"]):
                    best[key] = (setting, result, state_error)
            ours = min((v[1]["wall_seconds"] for k, v in best.items() if k[0] == "unidyn"),
                       default=None)
            for (tool, method), (setting, result, state_error) in sorted(
                    best.items(), key=lambda kv: kv[1][1]["wall_seconds"]):
                ratio = f"{result['wall_seconds'] / ours:.1f}×" if ours else ""
                self.say(f"| {model} | {tool} | {method} | {setting} | "
                         f"{result['wall_seconds'] * 1e3:.3g} ms | "
                         f"{result['max_relative_energy_error']:.1e} | {state_error:.1e} | {ratio} |")
            for tool, method in sorted({(c[0], c[1]) for c in candidates} - set(best)):
                self.say(f"| {model} | {tool} | {method} | none met the accuracy in the sweep | | "
                         f"| | |")
            if model == "pendulum-2":
                whole = self.whole_simulate(t_end, best)
        self.say()
        if whole:
            self.say(whole + "\n")

    def whole_simulate(self, t_end, best):
        """The double pendulum's run at the fastest Dormand–Prince setting found above as a whole
        `unidyn simulate` process (model read, cached native code, integration, CSV of a row every
        0.01 s), best of 3, against MuJoCo RK4's bare loop at the accuracy."""
        pairs = [k for k in (("unidyn", "dopri5"), ("unidyn", "dop853")) if k in best]
        if not pairs or ("MuJoCo", "rk4") not in best:
            return ""
        fastest_pair = min(pairs, key=lambda k: best[k][1]["wall_seconds"])
        method = fastest_pair[1]
        rtol = best[fastest_pair][0].split()[1]
        mujoco = best[("MuJoCo", "rk4")][1]["wall_seconds"]
        cli = os.path.join(self.build, "unidyn")
        with tempfile.TemporaryDirectory() as scratch:
            model = os.path.join(scratch, "pendulum-2.yaml")
            with open(model, "w") as f:
                f.write(pendulum_model(2))
            command = [cli, "simulate", model, "--t-end", t_end, "--method", method, "--rtol",
                       rtol, "--output-step", "0.01", "-o", os.path.join(scratch, "run.csv")]
            run(command)  # the native code compiled and cached before the timed runs
            seconds, _ = fastest(command)
            with open(os.path.join(scratch, "run.csv")) as f:
                rows = sum(1 for _ in f) - 1
        return (f"The double pendulum's run as a whole `unidyn simulate` process (model read, "
                f"cached native code, {method} at rtol {rtol}, CSV of {rows} rows), best of 3: "
                f"{seconds * 1e3:.1f} ms; MuJoCo RK4's bare loop at the same accuracy (no "
                f"output): {mujoco * 1e3:.0f} ms, ratio {mujoco / seconds:.1f}×. Goal of issue 17: "
                f"≥ 10×.")

    # 4. Growth with the number of links ---------------------------------------------------------
    def growth(self):
        self.say("## 4. Growth: the n-link pendulum and the bicycle\n")
        self.say("Derivation by Lagrange's equations and by Kane's form; the compiled equations "
                 "(Kane's, as simulate uses them): tape size, native source size and compile time "
                 "(empty cache), one right-hand side, and a 10 s run (dop853 at rtol 1e-8, "
                 "integration alone). Lagrange's derivation is not run past n = 20 (its cost grows "
                 "like n⁴; simulate uses Kane's). The bicycle (models/bicycle.yaml, 8 coordinates, "
                 "rolling constraints) at its initial state.\n")
        self.say("| model | derive (Lagrange) | derive (Kane) | compile to tape | compile native | "
                 "tape instructions | native source | evaluation (native) | evaluation (tape) | "
                 "10 s run |")
        self.say("|---|---|---|---|---|---|---|---|---|---|")
        links = [1, 2, 5, 10] if self.quick else [1, 2, 4, 6, 8, 10, 12, 15, 20, 30, 50]
        for model in [f"pendulum-{n}" for n in links] + ["bicycle"]:
            n = int(model.split("-")[1]) if model.startswith("pendulum-") else 0
            lagrange = run_json([self.unidyn, "derive", model]) if n <= 20 else None
            kane = run_json([self.unidyn, "derive", model, "--method", "kane"], timeout=900)
            if n:
                text, state = write_states(pendulum_states(n, 1, self.rng)), []
            else:
                text, state = "", ["--state", "initial"]
            _, native = rhs_output(run([self.unidyn, "rhs", model] + state, text))
            _, tape = rhs_output(run([self.unidyn, "rhs", model, "--evaluation", "tape"] + state,
                                     text))
            ten = run_json([self.unidyn, "simulate", model, "--t-end", "10", "--method", "dop853",
                            "--rtol", "1e-8"], timeout=900)
            derive_lagrange = f"{lagrange['derive_seconds'] * 1e3:.3g} ms" if lagrange else "—"
            self.say(f"| {model} | {derive_lagrange} | "
                     f"{kane['derive_seconds'] * 1e3:.3g} ms | {kane['tape_seconds'] * 1e3:.3g} ms | "
                     f"{kane['native_seconds']:.2f} s | {kane['instructions']} | "
                     f"{kane['source_bytes'] / 1024:.0f} KiB | {native:.0f} ns | {tape:.0f} ns | "
                     f"{ten['wall_seconds'] * 1e3:.3g} ms |")
        self.say()

    # 6. Whole commands on large systems ---------------------------------------------------------
    def large_systems(self):
        self.say("## 6. Whole commands on large systems: check, derive, code export\n")
        self.say("Wall time of the `unidyn` process (fixed layout re-exec, reading, deriving, "
                 "simplifying, printing), the best of three runs (this machine's speed drifts by "
                 "a fifth from minute to minute); the simplification shares its work among one "
                 "process per core (the column 'one process': `UNIDYN_PROCESSES=1`); "
                 "`derive --format c`: the operations of "
                 "M, f and the constraint rows after common factors are taken out of sums and "
                 "common subexpressions are shared (Kane's form). Goals of issue 13: check and derive of the bicycle ≤ 2 s, of the 10-link "
                 "pendulum ≤ 0.5 s, ≤ 2 400 operations for the bicycle. A command past its time "
                 "limit shows as '>'.\n")
        self.say("| model | check | derive --form matrix | derive (textbook) | derive, one process "
                 "| derive --format c --method kane | operations |")
        self.say("|---|---|---|---|---|---|---|")
        cli = os.path.join(self.build, "unidyn")
        limit = 20 if self.quick else 300
        with tempfile.TemporaryDirectory() as scratch:
            pendulum = os.path.join(scratch, "pendulum-10.yaml")
            with open(pendulum, "w") as f:
                f.write(pendulum_model(10))
            bicycle = os.path.join(ROOT, "models", "bicycle.yaml")
            systems = [("pendulum-10", pendulum), ("bicycle", bicycle)][:1 if self.quick else 2]
            for name, path in systems:
                cells, code = [], ""
                one = dict(os.environ, UNIDYN_PROCESSES="1")
                for extra, env in ((["check"], None), (["derive", "--form", "matrix"], None),
                                   (["derive"], None), (["derive"], one),
                                   (["derive", "--format", "c", "--method", "kane"], None)):
                    try:
                        best = None
                        for _ in range(1 if self.quick else 3):
                            start = time.perf_counter()
                            out = subprocess.run([cli] + extra + [path], capture_output=True,
                                                 text=True, timeout=limit, check=True,
                                                 env=env).stdout
                            elapsed = time.perf_counter() - start
                            best = elapsed if best is None else min(best, elapsed)
                        cells.append(f"{best:.2f} s")
                        code = out if "--format" in extra else code
                    except subprocess.TimeoutExpired:
                        cells.append(f"> {limit} s")
                self.say(f"| {name} | " + " | ".join(cells) + f" | {operations(code)} |")
            self.say()
            # where derive's time goes: the phases `derive --timings` reports
            self.say("Where `derive` (textbook form) spends its time, by `derive --timings`:\n")
            phases = {}
            for name, path in systems:
                try:
                    err = subprocess.run([cli, "derive", path, "--timings"], capture_output=True,
                                         text=True, timeout=limit, check=True).stderr
                except subprocess.TimeoutExpired:
                    continue
                for line in err.splitlines():
                    fields = line.rsplit(None, 2)
                    if line.startswith("  ") and len(fields) == 3 and fields[2] == "s":
                        phases.setdefault(fields[0].strip(), {})[name] = float(fields[1])
            self.say("| phase | pendulum-10 | bicycle |")
            self.say("|---|---|---|")
            for phase, seconds in phases.items():
                cells = [f"{seconds[m]:.2f} s" if m in seconds else "–"
                         for m in ("pendulum-10", "bicycle")]
                self.say(f"| {phase} | " + " | ".join(cells) + " |")
        self.say()

    # 10. Robots from files ----------------------------------------------------------------------
    def robots(self):
        self.say("## 10. Robots from URDF and MJCF files: the same file in unidyn, MuJoCo and DART\n")
        self.say("Each file is read by each engine (unidyn imports it as tree joints; MuJoCo by "
                 "mj_loadXML, contacts off): derive and compile (unidyn: Kane's equations, the "
                 "tape, then native code with an empty cache), the whole `unidyn simulate` "
                 "process to its first row (with an empty cache; from 5 coordinates no "
                 "equations are derived: the articulated-body algorithm), one right-hand side at "
                 "a random state (unidyn: the compiled equations below 5 coordinates, from 5 the "
                 "articulated-body algorithm over the tree recorded as generated code at the "
                 "model's numbers; MuJoCo: mj_forward; DART 6.12, URDF files only, by its own "
                 "URDF loader: setPositions, setVelocities, computeForwardDynamics), and "
                 "the largest relative difference of q̈ from either engine at 3 states (a free joint's through "
                 "MuJoCo's velocities: ω on the body frame). The n-link chains are URDF "
                 "files written here (links of 1 kg and 1 m about y); the floating quadruped (19 "
                 "coordinates) and humanoid (36) are tests/formats/models. Goals of issue 38: the "
                 "7-DoF arm ≤ 0.5 µs, a 30+-DoF floating humanoid ≤ 4 µs, chains ≥ 2× mj_forward "
                 "at n = 20 and 50, derive + compile of the arm ≤ 1 s, first right-hand side of "
                 "the 50-chain ≤ 0.3 s.\n")
        self.say("| file | n | derive | tape | native code | simulate, whole process | unidyn "
                 "| MuJoCo | MuJoCo / unidyn | DART | DART / unidyn | max difference |")
        self.say("|---|---|---|---|---|---|---|---|---|---|---|---|")
        with tempfile.TemporaryDirectory() as scratch:
            formats = os.path.join(ROOT, "tests", "formats", "models")
            files = [os.path.join(formats, "iiwa-like-arm.urdf"),
                     os.path.join(ROOT, "examples", "mjcf", "acrobot.xml"),
                     os.path.join(formats, "floating-quadruped.xml"),
                     os.path.join(formats, "humanoid.xml")]
            for links in (20,) if self.quick else (20, 50):
                path = os.path.join(scratch, f"chain-{links}.urdf")
                with open(path, "w") as f:
                    f.write(urdf_chain(links))
                files.append(path)
            for path in files:
                sizes = run_json([self.unidyn, "rhs", path, "--sizes", "1"])
                n = sizes["nq"]
                # a floating base's Kane's equations take minutes: the algorithm needs none
                derived = ({"derive_seconds": None} if sizes["quaternions"] else
                           run_json([self.unidyn, "derive", path, "--method", "kane"]))
                states = [random_robot_state(self.rng, sizes) for _ in range(3)]
                text = write_states(states)
                ours, ns = rhs_output(run([self.unidyn, "rhs", path], text))
                cells, difference = [], 0.0
                for peer, takes in ((self.mujoco, True), (self.dart, path.endswith(".urdf"))):
                    if not takes or not self.have(peer):
                        cells += ["–" if not takes else "not built", ""]
                        continue
                    theirs, ns_peer = rhs_output(run([peer, "rhs", path], text))
                    cells += [f"{ns_peer:.0f} ns", f"{ns_peer / ns:.1f}×"]
                    difference = max(difference, max_relative_difference(ours, theirs))
                cells.append(f"{difference:.1e}")
                # the whole `simulate` process to its first row, the native-code cache empty
                cache = tempfile.mkdtemp(dir=scratch)
                start = time.perf_counter()
                run([self.unidyn, "simulate", path, "--t-end", "0.001", "-o",
                     os.path.join(scratch, "run.csv")],
                    env=dict(os.environ, UNIDYN_CACHE_DIR=cache))
                started = time.perf_counter() - start
                compiled = ("not derived | | " if derived["derive_seconds"] is None else
                            f"{derived['derive_seconds']:.3f} s | {derived['tape_seconds']:.3f} s "
                            f"| {derived['native_seconds']:.2f} s ")
                self.say(f"| {os.path.basename(path)} | {n} | {compiled}| {started:.2f} s "
                         f"| {ns:.0f} ns | " + " | ".join(cells) + " |")
        self.say()

    # 5. Long runs ---------------------------------------------------------------------------------
    def long_runs(self):
        steps = "1e5" if self.quick else "1e7"
        self.say(f"## 5. Long runs: RATTLE over {steps} steps\n")
        self.say("Largest relative energy error over the first tenth of the run and over all of "
                 "it (sampled 1000 times): bounded for RATTLE; Dormand–Prince over the same span "
                 "for contrast.\n")
        self.say("| model | method | steps / step | span | wall time | error, first tenth "
                 "| error, whole run |")
        self.say("|---|---|---|---|---|---|---|")
        for model, step in (("kepler", "1e-2"), ("heavy-top", "1e-3")):
            for extra in (["--method", "rattle"], ["--method", "dopri5", "--rtol", "1e-8"]):
                r = run_json([self.unidyn, "longrun", model, "--steps", steps, "--step", step] +
                             extra, timeout=3600)
                what = f"{r['steps']:.0e} × {r['step']}" if r["method"] == "rattle" else "adaptive"
                self.say(f"| {model} | {r['method']} | {what} | {r['t_end']:.0f} s | "
                         f"{r['wall_seconds']:.1f} s | {r['energy_error_first_tenth']:.1e} | "
                         f"{r['energy_error_whole']:.1e} |")
        self.say()

    # 11. Mechanisms: the IFToMM benchmark problems ------------------------------------------
    def mechanisms(self):
        """A02 (N four-bar, through singular positions) and A04 (Bricard's mechanism, redundant
        rows) as whole `unidyn simulate` processes with the default method, best of 3, their
        accuracy measured, beside OpenSim 3.2's published times."""
        self.say("## 11. Mechanisms: the IFToMM benchmark problems\n")
        self.say("Whole `unidyn simulate` processes (model read, cached native code, the default "
                 "method — dopri5, alf through each singular position —, CSV of a row every "
                 "0.01 s), best of 3. Error: the crank tip's largest error (position, velocity) "
                 "against the exact parallelogram motion (RK4 here), and P3's against the "
                 "benchmark's reference curve points (x = −1 at 2.5 s, y = −√3/2 and z = −1/2 at "
                 "1.25 s). OpenSim 3.2 (Simbody RK-Feldberg, accuracy 1e-6), as published by "
                 "RehabEngGroup/MBSbenchmarksInOpenSim on an i5-4570 at 3.2 GHz: A02 with N = 2 "
                 "over 10 s 0.455 s, A04 over 10 s 0.258 s. Goal of issue 40: ≤ 0.05 s each.\n")
        self.say("| problem | span | wall time | error | OpenSim 3.2 |")
        self.say("|---|---|---|---|---|")
        cli = os.path.join(self.build, "unidyn")
        runs = 1 if self.quick else 3
        cases = [("A02, N = 2", 2, 10, "0.455 s"), ("A02, N = 40", 40, 2 if self.quick else 20, "")]
        with tempfile.TemporaryDirectory() as scratch:
            csv = os.path.join(scratch, "run.csv")
            for name, n, t_end, opensim in cases:
                model = os.path.join(scratch, f"a02-{n}.yaml")
                with open(model, "w") as f:
                    f.write(four_bar_model(n, t_end))
                command = [cli, "simulate", model, "-o", csv]
                run(command, timeout=3600)  # the native code compiled and cached first
                seconds, _ = fastest(command, runs=runs, timeout=3600)
                position, velocity = parallelogram_error(
                    n, csv_columns(csv, ["t", "th0", "der(th0)"]))
                self.say(f"| {name} | {t_end} s | {seconds:.3f} s | {position:.1e}, "
                         f"{velocity:.1e} | {opensim or '—'} |")
            command = [cli, "simulate", "a04-bricard", "-o", csv]
            run(command)
            seconds, _ = fastest(command, runs=runs)
            rows = csv_columns(csv, ["t", "P3x", "P3y", "P3z"])
            at = lambda t: min(rows, key=lambda r: abs(r[0] - t))
            error = max(abs(at(2.5)[1] + 1), abs(at(1.25)[2] + math.sqrt(3) / 2),
                        abs(at(1.25)[3] + 0.5))
            self.say(f"| A04 (Bricard) | 10 s | {seconds:.3f} s | {error:.1e} | 0.258 s |")
        self.say()


def four_bar_model(n, t_end):
    """The IFToMM N four-bar (problem A02) as models/iftomm/a02-four-bar-40.yaml writes it, for
    any N: crank and coupler angles, two closure rows per window."""
    lines = ["unidyn: 1", f"name: N four-bar (N = {n})", "parameters: {g: 9.81}",
             "coordinates: [" + ", ".join([f"th{i}" for i in range(n + 1)] +
                                          [f"ph{i}" for i in range(1, n + 1)]) + "]", "bodies:"]
    bar = "{mass: 1, inertia: [0, 1/12, 1/12], rotation: {axis: [0, 0, 1], angle: "
    for i in range(n + 1):
        lines.append(f"  c{i}: {bar}th{i}}}, center: '[{i}, 0, 0] + 0.5*c{i}.e1'}}")
    for i in range(1, n + 1):
        lines.append(f"  p{i}: {bar}ph{i}}}, center: '[{i - 1}, 0, 0] + c{i - 1}.e1 + 0.5*p{i}.e1'}}")
    lines += ["forces:", "  - gravity: -g*E2", "constraints:"]
    for i in range(1, n + 1):
        lines.append(f"  - {{name: x{i}, position: cos(th{i - 1}) + cos(ph{i}) - 1 - cos(th{i})}}")
        lines.append(f"  - {{name: y{i}, position: sin(th{i - 1}) + sin(ph{i}) - sin(th{i})}}")
    lines.append("initial: {" + ", ".join([f"th{i}: pi/2, der(th{i}): -1" for i in range(n + 1)] +
                                          [f"ph{i}: 0" for i in range(1, n + 1)]) + "}")
    lines.append(f"simulate: {{t_end: {t_end}, output_step: 0.01, step: 0.0005}}")
    return "\n".join(lines) + "\n"


def parallelogram_error(n, rows):
    """The largest error of the N four-bar's crank tip (position, velocity) over CSV rows (t, th0,
    der(th0)) against its exact one-degree-of-freedom motion ((N+1)/3 + N) θ'' = −((N+1)/2 + N) g
    cos θ, by RK4 at h = 1e-4."""
    ratio = ((n + 1) / 2 + n) / ((n + 1) / 3 + n)
    accel = lambda th: -ratio * 9.81 * math.cos(th)
    theta, rate, t, position, velocity = math.pi / 2, -1.0, 0.0, 0.0, 0.0
    for row_t, th, w in rows:
        while t < row_t - 1e-12:
            h = min(1e-4, row_t - t)
            k1, l1 = rate, accel(theta)
            k2, l2 = rate + h / 2 * l1, accel(theta + h / 2 * k1)
            k3, l3 = rate + h / 2 * l2, accel(theta + h / 2 * k2)
            k4, l4 = rate + h * l3, accel(theta + h * k3)
            theta += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            rate += h / 6 * (l1 + 2 * l2 + 2 * l3 + l4)
            t += h
        position = max(position, abs(math.cos(th) - math.cos(theta)),
                       abs(math.sin(th) - math.sin(theta)))
        velocity = max(velocity, abs(math.sin(th) * w - math.sin(theta) * rate),
                       abs(math.cos(th) * w - math.cos(theta) * rate))
    return position, velocity


def csv_columns(path, names):
    """The named columns of a CSV file, row by row."""
    with open(path) as f:
        header = f.readline().strip().split(",")
        index = [header.index(name) for name in names]
        return [tuple(float(v) for v in (line.split(",")[i] for i in index)) for line in f]


def pendulum_model(n):
    """The n-link pendulum of MODELS.md as a model file's text."""
    angles = ", ".join(f"q{k}" for k in range(1, n + 1))
    text = (f"unidyn: 1\nname: pendulum-{n}\nparameters: {{m: 1.0, L: 1.0, g: 9.81}}\n"
            f"coordinates: [{angles}]\nparticles:\n")
    theta = ""
    for k in range(1, n + 1):
        theta += f" + q{k}" if k > 1 else "q1"
        before = f"P{k - 1}.position + " if k > 1 else ""
        text += (f"  P{k}: {{mass: m, position: \"{before}L*[sin({theta}), -cos({theta}), 0]\"}}"
                 "\n")
    return text + "forces:\n  - gravity: -g*E2\ninitial: {q1: 0.5}\n"


def random_robot_state(rng, sizes):
    """A robot file's peer state (qpos, qvel) at random: coordinates within ±1, each quaternion
    normalised, velocities within ±1."""
    q = [rng.uniform(-1, 1) for _ in range(sizes["nq"])]
    for k in sizes["quaternions"]:
        norm = sum(x * x for x in q[k:k + 4]) ** 0.5
        q[k:k + 4] = [x / norm for x in q[k:k + 4]]
    return q + [rng.uniform(-1, 1) for _ in range(sizes["nv"])]


def urdf_chain(links):
    """An n-link chain as a URDF file: links of 1 kg and 1 m turning about y, each centre of mass
    at the link's end, gravity along −z (as MuJoCo reads a URDF)."""
    text = ['<robot name="chain">',
            '  <mujoco><compiler fusestatic="false" discardvisual="true"/></mujoco>',
            '  <link name="base"/>']
    for k in range(1, links + 1):
        text.append(f'  <link name="link{k}"><inertial><origin xyz="0 0 -1"/><mass value="1"/>'
                    '<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.001"/>'
                    '</inertial></link>')
        parent, offset = ("base", "0 0 0") if k == 1 else (f"link{k - 1}", "0 0 -1")
        text.append(f'  <joint name="q{k}" type="continuous"><parent link="{parent}"/>'
                    f'<child link="link{k}"/><origin xyz="{offset}"/><axis xyz="0 1 0"/></joint>')
    text.append("</robot>")
    return "\n".join(text) + "\n"


def operations(code):
    """The arithmetic operations and function calls of `derive --format c` output (loads of
    q, qd, p, t and constants not counted)."""
    count = 0
    for line in code.splitlines():
        fields = line.strip().rstrip(";").split(" = ", 1)
        if len(fields) != 2 or not fields[0].startswith("r"):
            continue
        value = fields[1]
        if value.split("[")[0] in ("q", "qd", "p", "t") or is_literal(value):
            continue
        count += 1
    return count


def is_literal(text):
    """Whether text is a number as `derive --format c` writes one (decimal or hexadecimal)."""
    for parse in (float, float.fromhex):
        try:
            parse(text)
            return True
        except ValueError:
            pass
    return False


def machine():
    """A line about the machine and the commit."""
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return (f"Machine: {cpu}, {os.cpu_count()} cores; date {datetime.date.today()}; "
            f"commit {commit}; Python {platform.python_version()}.")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--part", help="run only this part (e.g. robots); RESULTS.md is not written")
    arguments = parser.parse_args()
    bench = Bench(arguments.build, arguments.quick)
    bench.say("# unidyn benchmarks\n")
    bench.say(machine())
    bench.say("Reproduce: `bash bench/run.sh` (builds into build-bench/ and runs "
              "`python3 bench/run.py build-bench`).\n")
    failed = []
    for part in (bench.derivation, bench.right_hand_side, bench.time_to_accuracy, bench.growth,
                 bench.long_runs, bench.large_systems, bench.analysis, bench.ensembles,
                 bench.robots, bench.micro, bench.mechanisms):
        if arguments.part and part.__name__ != arguments.part:
            continue
        start = time.perf_counter()
        try:
            part()
        except Exception as error:  # report and go on with the other comparisons
            bench.say(f"\n(this part failed: {error})\n")
            failed.append(part.__name__)
        print(f"bench: {part.__name__} took {time.perf_counter() - start:.1f} s", file=sys.stderr,
              flush=True)
    if not arguments.quick and not arguments.part:
        with open(os.path.join(HERE, "RESULTS.md"), "w") as f:
            f.write("\n".join(bench.lines) + "\n")
    # a broken comparison fails the run (CI runs --quick), after every other part has run
    if failed:
        print(f"bench: {len(failed)} part(s) failed: {', '.join(failed)}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
