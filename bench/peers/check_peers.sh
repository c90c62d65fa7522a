#!/usr/bin/env bash
# Validates peer_mujoco and peer_simbody (bench/peers) against closed forms and against each other.
# Builds nothing: pass the build directory that holds both executables.
#
#   bench/peers/check_peers.sh /tmp/peers-build
#
# Checks (errors are row-wise relative: max_i |a_i − b_i| / max_i |b_i|):
#  (a) pendulum-1: q̈ = −g sin q, both peers, to 1e-9;
#  (b) pendulum-2 and pendulum-5: MuJoCo and Simbody q̈ agree to 1e-8 at three states;
#  (c) heavy-top: ω̇_b from J_O ω̇ + ω × (J_O ω) = l e3 × Rᵀ(−m g E3), both peers, to 1e-9;
#  (d) torque-free: J ω̇ + ω × J ω = 0, both peers, to 1e-9;
#  (e) simulate: well-formed JSON, E0 equal to the MODELS.md formula, small energy drift, and the
#      MuJoCo rk4 and Simbody rkmerson final states agree over a short run.
# Every `rhs` run must also end with a positive `ns_per_eval` line. Exit status: 0 when all pass.
set -uo pipefail  # no -e: a failed check is counted and the remaining checks still run

build=${1:?usage: check_peers.sh BUILD_DIR}
mujoco=$build/peer_mujoco
simbody=$build/peer_simbody
for exe in "$mujoco" "$simbody"; do
  [[ -x $exe ]] || { echo "check_peers: no executable $exe" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Closed forms and comparisons, in Python (standard library only).
read -r -d '' PY <<'EOF' || true
import json, math, sys

G = 9.81

def rot(w, x, y, z):
    n = math.sqrt(w*w + x*x + y*y + z*z)
    w, x, y, z = w/n, x/n, y/n, z/n
    return [[1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)],
            [2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)],
            [2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)]]

def cross(a, b):
    return [a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2], a[0]*b[1] - a[1]*b[0]]

def euler(J, w, M):
    # J ω̇ + ω × J ω = M with J diagonal
    Jw = [J[i]*w[i] for i in range(3)]
    c = cross(w, Jw)
    return [(M[i] - c[i])/J[i] for i in range(3)]

def expected(model, s):
    if model == "pendulum-1":
        return [-G*math.sin(s[0])]
    R, w = rot(*s[:4]), s[4:7]
    if model == "heavy-top":
        m, l, A, C = 1.0, 0.05, 0.004, 0.002
        J = [A + m*l*l, A + m*l*l, C]
        gravity_b = [R[2][i]*(-m*G) for i in range(3)]  # Rᵀ (0, 0, −m g)
        return euler(J, w, cross([0.0, 0.0, l], gravity_b))
    if model == "torque-free":
        return euler([2.0, 4.0, 5.0], w, [0.0, 0.0, 0.0])
    raise SystemExit("no closed form for " + model)

def rows(path):
    with open(path) as f:
        return [[float(v) for v in line.split()] for line in f if line.strip()]

def row_error(a, b):
    scale = max(abs(v) for v in b) or 1.0
    return max(abs(x - y) for x, y in zip(a, b)) / scale

cmd = sys.argv[1]
if cmd == "expect":  # expect MODEL STATES -> closed-form accelerations
    for s in rows(sys.argv[3]):
        print(" ".join("%.17g" % v for v in expected(sys.argv[2], s)))
elif cmd == "compare":  # compare LABEL TOL GOT REFERENCE
    label, tol, got, ref = sys.argv[2], float(sys.argv[3]), rows(sys.argv[4]), rows(sys.argv[5])
    ok = len(got) == len(ref) and all(len(a) == len(b) for a, b in zip(got, ref))
    worst = max(row_error(a, b) for a, b in zip(got, ref)) if ok else float("inf")
    ok = ok and worst <= tol
    print("%s %s: max relative error %.3g (tolerance %g)" % ("ok  " if ok else "FAIL", label, worst, tol))
    sys.exit(0 if ok else 1)
elif cmd == "energy0":  # energy0 MODEL -> E0 of the time-to-accuracy state (MODELS.md)
    if sys.argv[2] == "pendulum-2":
        print("%.17g" % (-3*G*math.cos(0.5)))  # q = (0.5, 0): both links at 0.5 rad
    else:
        print("%.17g" % (0.5*0.002*60.0**2 + 1.0*G*0.05*math.cos(0.3)))
elif cmd == "simulate":  # simulate LABEL E0 MAXDRIFT TOL MUJOCO_JSON SIMBODY_JSON
    label, e0, drift, tol = sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
    runs = [json.load(open(p)) for p in sys.argv[6:8]]
    problems = []
    for name, r in zip(("mujoco", "simbody"), runs):
        for key in ("wall_seconds", "steps", "max_relative_energy_error", "final_state"):
            if key not in r:
                problems.append("%s: no %s" % (name, key))
        if abs(r.get("initial_energy", float("nan")) - e0) > 1e-12*abs(e0):
            problems.append("%s: E0 %r, MODELS.md %r" % (name, r.get("initial_energy"), e0))
        if not r.get("max_relative_energy_error", float("inf")) <= drift:
            problems.append("%s: energy drift %r" % (name, r.get("max_relative_energy_error")))
    if not problems:
        err = row_error(runs[0]["final_state"], runs[1]["final_state"])
        if not err <= tol:
            problems.append("final states differ by %.3g" % err)
    print("%s %s%s" % ("FAIL" if problems else "ok  ", label, ": " + "; ".join(problems) if problems else ""))
    sys.exit(1 if problems else 0)
EOF
py() { python3 -c "$PY" "$@"; }

passed=0
failed=0
# record CMD...: runs one check, counts it, and returns its status.
record() {
  if "$@"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    return 1
  fi
}

# rhs PEER MODEL STATES OUT: accelerations to OUT; the run must succeed and end with ns_per_eval.
rhs() {
  local out
  if ! out=$("$1" rhs "$2" <"$3"); then
    echo "FAIL $(basename "$1") rhs $2 exited non-zero"
    return 1
  fi
  if ! tail -n 1 <<<"$out" | grep -Eq '^ns_per_eval [0-9.]+(e[-+]?[0-9]+)?$'; then
    echo "FAIL $(basename "$1") rhs $2: no ns_per_eval line"
    return 1
  fi
  sed '$d' <<<"$out" >"$4"
}

# closed_form MODEL STATES TOL: both peers against the Python closed form.
closed_form() {
  local model=$1 states=$2 tol=$3 peer
  py expect "$model" "$states" >"$work/$model.expected"
  for peer in "$mujoco" "$simbody"; do
    record rhs "$peer" "$model" "$states" "$work/$model.$(basename "$peer")" &&
      record py compare "$(basename "$peer") $model vs closed form" "$tol" \
        "$work/$model.$(basename "$peer")" "$work/$model.expected"
  done
}

# cross_peer MODEL STATES TOL: MuJoCo against Simbody.
cross_peer() {
  local model=$1 states=$2 tol=$3
  record rhs "$mujoco" "$model" "$states" "$work/$model.mj" &&
    record rhs "$simbody" "$model" "$states" "$work/$model.sb" &&
    record py compare "$model MuJoCo vs Simbody" "$tol" "$work/$model.mj" "$work/$model.sb"
}

# (a) pendulum-1
printf '%s\n' "0.3 0.7" "1.2 -0.5" "-2.5 3" "3.0 0" >"$work/p1"
closed_form pendulum-1 "$work/p1" 1e-9

# (b) pendulum-2, pendulum-5
printf '%s\n' "0.3 -0.2 0.7 1.1" "1 1 0 0" "-2 2.5 -1.5 3" >"$work/p2"
cross_peer pendulum-2 "$work/p2" 1e-8
printf '%s\n' "0.1 0.2 0.3 0.4 0.5 -0.3 0.2 -0.1 0.4 0.6" \
  "1 -0.5 0.8 -1.2 0.3 0.5 1.5 -2 0.7 0.1" \
  "-2.2 1.7 0.4 2.9 -1.1 3 -2.5 1 0.5 -1.8" >"$work/p5"
cross_peer pendulum-5 "$work/p5" 1e-8

# (c) heavy-top: the MODELS.md attitude with ω_b = (0, 0.5, 60), then a generic state
python3 -c 'import math; print("%.17g %.17g 0 0 0 0.5 60" % (math.cos(0.15), math.sin(0.15)))' \
  >"$work/top"
echo "0.7 0.2 -0.5 0.4 1.5 -2 30" >>"$work/top"
closed_form heavy-top "$work/top" 1e-9

# (d) torque-free
printf '%s\n' "0.9 0.1 -0.3 0.2 7 8 9" "0.3 -0.6 0.5 0.55 -1.2 0.4 2.2" >"$work/free"
closed_form torque-free "$work/free" 1e-9

# (e) simulate: short time-to-accuracy runs, MuJoCo rk4 against Simbody rkmerson
simulate_pair() {
  local model=$1 t_end=$2 dt=$3 drift=$4 tol=$5
  if "$mujoco" simulate "$model" --t-end "$t_end" --integrator rk4 --dt "$dt" >"$work/sim.mj" &&
    "$simbody" simulate "$model" --t-end "$t_end" --integrator rkmerson --accuracy 1e-10 \
      >"$work/sim.sb"; then
    record py simulate "simulate $model to t = $t_end" "$(py energy0 "$model")" "$drift" "$tol" \
      "$work/sim.mj" "$work/sim.sb"
  else
    echo "FAIL simulate $model exited non-zero"
    failed=$((failed + 1))
  fi
}
simulate_pair pendulum-2 1 1e-3 1e-8 1e-7
# MuJoCo 2.2.2's RK4 is only second order for the ball joint's quaternion: looser agreement.
simulate_pair heavy-top 0.2 1e-4 1e-7 1e-5

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
