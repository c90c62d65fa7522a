#!/usr/bin/env python3
"""Checks of bench/sympy/derive.py against closed forms and each other.

Usage: python3 bench/sympy/check_derive.py   (exit status 1 on a failure)

1. heavy-top frame: e3 = Q E3 = (sin psi sin theta, -cos psi sin theta,
   cos theta) for orient_body_fixed(..., '313').
2. pendulum-1: q'' = -(g/L) sin q.
3. pendulum-2: the double pendulum in relative angles, solved by hand.
4. lagrange and kane agree to 1e-10 (pendulum-1..6, heavy-top, rolling-disk).
5. heavy-top: Euler's equations about O, converted to Euler-angle rates.
6. rolling-disk: constraints hold at the acceleration level and the energy
   is conserved; energy is conserved for the pendulums and the top too.
"""

import math
import os
import random
import sys

import sympy as sp
from sympy.physics import mechanics as me

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import derive  # noqa: E402  (the script under test, next to this file)

TOL = 1e-10
FAILURES = []


def report(name, error, tol):
    """Print one check's largest error and record a failure."""
    ok = error <= tol
    print('%-44s max error %.3e (tol %.0e)  %s'
          % (name, error, tol, 'ok' if ok else 'FAIL'))
    if not ok:
        FAILURES.append(name)


def max_diff(a, b):
    """Largest |a_i - b_i| / max(1, |b_i|) over nested lists."""
    return max(abs(x - y) / max(1.0, abs(y))
               for row_a, row_b in zip(a, b) for x, y in zip(row_a, row_b))


_CACHE = {}


def accelerations(name, method):
    """q''(q, q') of `name` derived by `method` (derived once)."""
    if (name, method) not in _CACHE:
        model, mass, forcing, order = derive.derive(name, method)
        _CACHE[name, method] = derive.acceleration_function(
            model, mass, forcing, order)
    return _CACHE[name, method]


def qddot_at(name, method, states, n):
    """q'' at each state (2n numbers) by `method`."""
    f = accelerations(name, method)
    return [f(s[:n], s[n:]) for s in states]


def random_states(n, count, seed, spread=2.0):
    """Random states (q, q') of n coordinates."""
    rng = random.Random(seed)
    return [[rng.uniform(-spread, spread) for _ in range(2 * n)]
            for _ in range(count)]


# ---------------------------------------------------------------------------
# Closed forms written by hand
# ---------------------------------------------------------------------------

def double_pendulum(state, g=9.81):
    """Double pendulum (m = L = 1) in relative angles q1, q2.

    T = 1/2 (3 + 2 c2) q1'^2 + (1 + c2) q1' q2' + 1/2 q2'^2,
    V = -2 g cos q1 - g cos(q1 + q2), c2 = cos q2, s2 = sin q2; Lagrange:
      (3 + 2 c2) q1'' + (1 + c2) q2'' = s2 (2 q1' q2' + q2'^2)
                                        - 2 g sin q1 - g sin(q1 + q2)
      (1 + c2) q1'' + q2''            = -s2 q1'^2 - g sin(q1 + q2)
    solved by Cramer's rule (determinant 2 - c2^2).
    """
    q1, q2, w1, w2 = state
    c2, s2 = math.cos(q2), math.sin(q2)
    m11, m12, m22 = 3 + 2 * c2, 1 + c2, 1.0
    f1 = (s2 * (2 * w1 * w2 + w2 ** 2) - 2 * g * math.sin(q1)
          - g * math.sin(q1 + q2))
    f2 = -s2 * w1 ** 2 - g * math.sin(q1 + q2)
    det = m11 * m22 - m12 ** 2
    return [(f1 * m22 - m12 * f2) / det, (m11 * f2 - m12 * f1) / det]


def top_body_omega(q, qdot):
    """Body components of omega for 3-1-3 angles, and d/dt at q'' = 0."""
    _, th, ph = q
    dps, dth, dph = qdot
    st, ct, sp_, cp = math.sin(th), math.cos(th), math.sin(ph), math.cos(ph)
    omega = [dps * st * sp_ + dth * cp,
             dps * st * cp - dth * sp_,
             dps * ct + dph]
    # Time derivative of omega = W(theta, phi) q' with q'' = 0.
    wdot_q = [dps * (dth * ct * sp_ + dph * st * cp) - dth * dph * sp_,
              dps * (dth * ct * cp - dph * st * sp_) - dth * dph * cp,
              -dps * dth * st]
    return omega, wdot_q


def heavy_top_euler(state, m=1.0, g=9.81, l=0.05, a=0.004, c=0.002):
    """Heavy top q'' from Euler's equations about the fixed point O.

    J_O w' + w x J_O w = M, J_O = diag(A + m l^2, A + m l^2, C) and
    M = l e3 x (-m g E3) in body components, E3 = (st sp, st cp, ct); then
    w' = W q'' + W' q' with W = [[st sp, cp, 0], [st cp, -sp, 0], [ct, 0, 1]]
    inverted by hand.
    """
    q, qdot = state[:3], state[3:]
    _, th, ph = q
    st, ct, sp_, cp = math.sin(th), math.cos(th), math.sin(ph), math.cos(ph)
    w, wdot_q = top_body_omega(q, qdot)
    j = [a + m * l ** 2, a + m * l ** 2, c]
    hw = [j[i] * w[i] for i in range(3)]
    gyro = [w[1] * hw[2] - w[2] * hw[1],
            w[2] * hw[0] - w[0] * hw[2],
            w[0] * hw[1] - w[1] * hw[0]]
    e3_space = [st * sp_, st * cp, ct]
    moment = [-m * g * l * (0.0 * e3_space[2] - 1.0 * e3_space[1]),
              -m * g * l * (1.0 * e3_space[0] - 0.0 * e3_space[2]),
              0.0]
    wdot = [(moment[i] - gyro[i]) / j[i] for i in range(3)]
    b = [wdot[i] - wdot_q[i] for i in range(3)]
    ddpsi = (b[0] * sp_ + b[1] * cp) / st
    ddtheta = b[0] * cp - b[1] * sp_
    ddphi = b[2] - ct * ddpsi
    return [ddpsi, ddtheta, ddphi]


# ---------------------------------------------------------------------------
# Energies written by hand (for dE/dt = 0 along the computed motion)
# ---------------------------------------------------------------------------

def pendulum_energy(state, g=9.81):
    """Chain of unit masses on unit links, relative angles."""
    n = len(state) // 2
    th = w = x = y = vx = vy = 0.0
    energy = 0.0
    for k in range(n):
        th += state[k]
        w += state[n + k]
        x, y = x + math.sin(th), y - math.cos(th)
        vx, vy = vx + w * math.cos(th), vy + w * math.sin(th)
        energy += 0.5 * (vx ** 2 + vy ** 2) + g * y
    return energy


def top_energy(state, m=1.0, g=9.81, l=0.05, a=0.004, c=0.002):
    """1/2 w.J_O w + m g l cos theta."""
    w, _ = top_body_omega(state[:3], state[3:])
    ao = a + m * l ** 2
    return (0.5 * (ao * (w[0] ** 2 + w[1] ** 2) + c * w[2] ** 2)
            + m * g * l * math.cos(state[1]))


def disk_energy(state, m=1.0, g=9.81, r=0.15):
    """1/2 m v^2 + 1/2 w.J w + m g x3, J = (m R^2/4)(1, 1, 2)."""
    w, _ = top_body_omega(state[3:6], state[9:12])
    lam = m * r ** 2 / 4
    v2 = sum(v ** 2 for v in state[6:9])
    return (0.5 * m * v2 + 0.5 * lam * (w[0] ** 2 + w[1] ** 2
                                        + 2 * w[2] ** 2) + m * g * state[2])


def path_rate(func, state, qddot):
    """d/dt func(state) along (q', q''), by a central difference."""
    n = len(qddot)
    rate = state[n:] + list(qddot)
    h = 1e-6 / max(1.0, max(abs(v) for v in rate))
    plus = [s + h * v for s, v in zip(state, rate)]
    minus = [s - h * v for s, v in zip(state, rate)]
    fp, fm = func(plus), func(minus)
    if isinstance(fp, list):
        return [(a - b) / (2 * h) for a, b in zip(fp, fm)], h
    return (fp - fm) / (2 * h), h


def energy_check(name, energy, states, qddots):
    """Relative dE/dt: |dE/dt| / (|E| scale x fastest rate)."""
    worst = 0.0
    for state, qdd in zip(states, qddots):
        rate, h = path_rate(energy, state, qdd)
        scale = max(1.0, abs(energy(state))) * (1e-6 / h)
        worst = max(worst, abs(rate) / scale)
    report(name + ': energy rate (relative)', worst, 1e-6)


# ---------------------------------------------------------------------------
# The checks
# ---------------------------------------------------------------------------

def check_top_frame():
    """e3 = Q E3 for the body-fixed 3-1-3 orientation used by derive.py."""
    model = derive.heavy_top(kane=False)
    psi, theta, _ = model.q
    body = model.bodies[0].frame
    e3 = body.z.to_matrix(model.frame)
    expected = sp.Matrix([sp.sin(psi) * sp.sin(theta),
                          -sp.cos(psi) * sp.sin(theta), sp.cos(theta)])
    error = 0.0 if sp.simplify(e3 - expected) == sp.zeros(3, 1) else 1.0
    report('heavy-top: e3 = (s psi s th, -c psi s th, c th)', error, 0.0)


def check_pendulum_1():
    states = random_states(1, 20, seed=1, spread=3.0)
    states += derive.builtin_states('pendulum-1', 1)
    exact = [[-9.81 * math.sin(s[0])] for s in states]
    for method in derive.METHODS:
        got = qddot_at('pendulum-1', method, states, 1)
        report(f'pendulum-1 {method}: -(g/L) sin q', max_diff(got, exact),
               TOL)


def check_pendulum_2():
    states = random_states(2, 20, seed=2, spread=3.0)
    states += derive.builtin_states('pendulum-2', 2)
    states.append([1.0, 1.0, 0.0, 0.0])
    exact = [double_pendulum(s) for s in states]
    for method in derive.METHODS:
        got = qddot_at('pendulum-2', method, states, 2)
        report(f'pendulum-2 {method}: closed form', max_diff(got, exact),
               TOL)


def check_agreement():
    """Lagrange and Kane at the built-in and at random states."""
    models = [f'pendulum-{n}' for n in range(1, 7)]
    models += ['heavy-top', 'rolling-disk']
    results = {}
    for name in models:
        n = derive.parse_model_name(name)
        states = derive.builtin_states(name, n)
        if name == 'rolling-disk':
            rng = random.Random(6)
            for _ in range(10):
                states.append(derive.disk_state(
                    *[rng.uniform(-2, 2) for _ in range(3)],
                    rng.uniform(0.4, 2.7), rng.uniform(-3, 3),
                    *[rng.uniform(-5, 5) for _ in range(3)]))
        else:
            states += random_states(n, 10, seed=n)
            if name == 'heavy-top':
                # Keep theta away from the 3-1-3 singularity theta = 0.
                for s in states[3:]:
                    s[1] = 0.3 + abs(s[1])
        lag = qddot_at(name, 'lagrange', states, n)
        kane = qddot_at(name, 'kane', states, n)
        report(f'{name}: lagrange vs kane', max_diff(lag, kane), TOL)
        results[name] = (states, lag)
    return results


def check_heavy_top(states, qddots):
    """Euler's equations: the brief's state, then the other states."""
    state = [0.0, 0.3, 0.0, 0.0, 0.0, 60.0]
    for method in derive.METHODS:
        got = qddot_at('heavy-top', method, [state], 3)
        exact = [heavy_top_euler(state)]
        print('  heavy-top %s at (0, 0.3, 0; 0, 0, 60): %r (Euler: %r)'
              % (method, got[0], exact[0]))
        report(f'heavy-top {method}: Euler eqs, given state',
               max_diff(got, exact), TOL)
    exact = [heavy_top_euler(s) for s in states]
    report('heavy-top: Euler eqs, all states', max_diff(qddots, exact), TOL)


def check_rolling_disk(states, qddots):
    """Second derivatives of the constraints vanish along the motion."""
    r = derive.DISK_PARAMS['R']
    worst = 0.0
    for s, qdd in zip(states, qddots):
        theta, dtheta = s[4], s[10]
        height = qdd[2] - r * (math.cos(theta) * qdd[4]
                               - math.sin(theta) * dtheta ** 2)
        rate, h = path_rate(
            lambda x: derive.disk_contact_velocity(x[:6], x[6:]), s, qdd)
        scale = max(1.0, max(abs(v) for v in s[6:])) * (1e-6 / h)
        worst = max(worst, abs(height), abs(rate[0]) / scale,
                    abs(rate[1]) / scale)
    report('rolling-disk: constraint accelerations', worst, 1e-6)
    energy_check('rolling-disk', disk_energy, states, qddots)


def main():
    check_top_frame()
    check_pendulum_1()
    check_pendulum_2()
    results = check_agreement()
    check_heavy_top(*results['heavy-top'])
    check_rolling_disk(*results['rolling-disk'])
    energy_check('heavy-top', top_energy, *results['heavy-top'])
    for n in range(1, 7):
        energy_check(f'pendulum-{n}', pendulum_energy,
                     *results[f'pendulum-{n}'])
    if FAILURES:
        print('FAILED: ' + ', '.join(FAILURES))
        return 1
    print('all checks passed')
    return 0


if __name__ == '__main__':
    sys.exit(main())
