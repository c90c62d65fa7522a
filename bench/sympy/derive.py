#!/usr/bin/env python3
"""Derive the benchmark equations of motion with SymPy mechanics.

Usage:
    python3 bench/sympy/derive.py MODEL --method lagrange|kane
                                  [--states FILE] [--repeat K]

MODEL is pendulum-N (N = 1..20), heavy-top or rolling-disk, built exactly as
in bench/MODELS.md and models/heavy-top.yaml, models/rolling-disk.yaml (same
coordinates, parameters and constraints as unidyn). The script times the
derivation (building the system, forming the equations and obtaining
mass_matrix_full / forcing_full as symbolic matrices; no numeric work), then
evaluates the accelerations q'' at the given states and prints one JSON
object on stdout.

Parameters stay symbolic during the derivation (as in unidyn, whose
equations keep the model's parameters) and get their values at evaluation.
"""

import argparse
import json
import math
import random
import re
import sys
import time
from dataclasses import dataclass, field

import sympy as sp
from sympy.core.cache import clear_cache
from sympy.core.function import AppliedUndef
from sympy.physics import mechanics as me

T = me.dynamicsymbols._t

# Parameter values of bench/MODELS.md and models/*.yaml.
PENDULUM_PARAMS = {'m': 1.0, 'g': 9.81, 'L': 1.0}
TOP_PARAMS = {'m': 1.0, 'g': 9.81, 'l': 0.05, 'A': 0.004, 'C': 0.002}
DISK_PARAMS = {'m': 1.0, 'g': 9.81, 'R': 0.15}

METHODS = ('lagrange', 'kane')


@dataclass
class Model:
    """A mechanical system ready for either method.

    `rates` are the time derivatives q' for Lagrange and the generalized
    speeds u (with u_i = q'_i) for Kane; every velocity is written in them.
    """
    name: str
    frame: me.ReferenceFrame
    q: list
    rates: list
    bodies: list
    loads: list                  # gravity as (point, force), for Kane
    potential: sp.Expr           # gravity potential, for Lagrange
    params: dict                 # parameter Symbol -> value
    hol: list = field(default_factory=list)     # position constraints
    nonhol: list = field(default_factory=list)  # velocity constraints
    q_dep: list = field(default_factory=list)   # Kane: dependent coordinates
    u_dep: list = field(default_factory=list)   # Kane: dependent speeds


# ---------------------------------------------------------------------------
# Models
# ---------------------------------------------------------------------------

def coordinates(names, kane):
    """Coordinates q and their rates: q' (Lagrange) or speeds u (Kane)."""
    q = [me.dynamicsymbols(name) for name in names]
    if kane:
        rates = [me.dynamicsymbols('u_' + name) for name in names]
    else:
        rates = [qi.diff(T) for qi in q]
    return q, rates


def parameters(values):
    """Positive parameter symbols, in the order of `values`."""
    return {sp.Symbol(name, positive=True): value
            for name, value in values.items()}


def pendulum(n, kane):
    """Planar chain of n point masses, relative hinge angles q1..qn."""
    params = parameters(PENDULUM_PARAMS)
    m, g, L = params
    q, rates = coordinates([f'q{k}' for k in range(1, n + 1)], kane)
    N = me.ReferenceFrame('N')
    O = me.Point('O')
    O.set_vel(N, 0)

    # Link k is frame A_k, turned by q_k about E3 from link k-1 (from N for
    # the first link); particle k sits at -L A_k.y from particle k-1, i.e.
    # L (sin th_k, -cos th_k, 0) with th_k = q_1 + ... + q_k.
    bodies, loads, potential = [], [], 0
    parent, joint = N, O
    for k in range(n):
        A = me.ReferenceFrame(f'A{k + 1}')
        A.orient_axis(parent, parent.z, q[k])
        A.set_ang_vel(parent, rates[k] * parent.z)
        P = joint.locatenew(f'P{k + 1}', -L * A.y)
        P.v2pt_theory(joint, N, A)
        bodies.append(me.Particle(f'p{k + 1}', P, m))
        loads.append((P, -m * g * N.y))
        potential += m * g * P.pos_from(O).dot(N.y)
        parent, joint = A, P
    return Model(f'pendulum-{n}', N, q, rates, bodies, loads, potential,
                 params)


def heavy_top(kane):
    """Symmetric top on a fixed point, 3-1-3 angles (psi, theta, phi)."""
    params = parameters(TOP_PARAMS)
    m, g, l, A, C = params
    q, rates = coordinates(['psi', 'theta', 'phi'], kane)
    qdot_to_rates = {qi.diff(T): ri for qi, ri in zip(q, rates)}
    N = me.ReferenceFrame('N')

    # Q = R3(psi) R1(theta) R3(phi): body-fixed 3-1-3 rotations; the
    # angular velocity is SymPy's, written in the rates.
    B = me.ReferenceFrame('B')
    B.orient_body_fixed(N, q, '313')
    B.set_ang_vel(N, B.ang_vel_in(N).xreplace(qdot_to_rates))

    # Fixed point O, centre of mass G at l e3, inertia (A, A, C) about G.
    O = me.Point('O')
    O.set_vel(N, 0)
    G = O.locatenew('G', l * B.z)
    G.v2pt_theory(O, N, B)
    top = me.RigidBody('top', G, B, m, (me.inertia(B, A, A, C), G))
    potential = m * g * G.pos_from(O).dot(N.z)
    return Model('heavy-top', N, q, rates, [top], [(G, -m * g * N.z)],
                 potential, params)


def rolling_disk(kane):
    """Thin disk rolling on x3 = 0: coordinates x1, x2, x3, psi, theta, phi."""
    params = parameters(DISK_PARAMS)
    m, g, R = params
    q, rates = coordinates(['x1', 'x2', 'x3', 'psi', 'theta', 'phi'], kane)
    x1, x2, x3, psi, theta, phi = q
    qdot_to_rates = {qi.diff(T): ri for qi, ri in zip(q, rates)}
    N = me.ReferenceFrame('N')

    # Disk frame by the 3-1-3 rotation (disk axis e3), centre at (x1, x2, x3).
    B = me.ReferenceFrame('B')
    B.orient_body_fixed(N, (psi, theta, phi), '313')
    B.set_ang_vel(N, B.ang_vel_in(N).xreplace(qdot_to_rates))
    O = me.Point('O')
    O.set_vel(N, 0)
    centre = O.locatenew('centre', x1 * N.x + x2 * N.y + x3 * N.z)
    centre.set_vel(N, rates[0] * N.x + rates[1] * N.y + rates[2] * N.z)
    inertia = me.inertia(B, m * R**2 / 4, m * R**2 / 4, m * R**2 / 2)
    disk = me.RigidBody('disk', centre, B, m, (inertia, centre))

    # Constraints of rolling-disk.yaml: height x3 - R sin(theta) and the E1,
    # E2 components of the contact point's velocity v + omega x pi_P.
    pi_p = R * (sp.cos(theta) * sp.sin(psi) * N.x
                - sp.cos(theta) * sp.cos(psi) * N.y
                - sp.sin(theta) * N.z)
    v_contact = centre.vel(N) + B.ang_vel_in(N).cross(pi_p)
    hol = [x3 - R * sp.sin(theta)]
    nonhol = [v_contact.dot(N.x), v_contact.dot(N.y)]

    potential = m * g * x3
    return Model('rolling-disk', N, q, rates, [disk],
                 [(centre, -m * g * N.z)], potential, params,
                 hol=hol, nonhol=nonhol, q_dep=[x3], u_dep=rates[:3])


def build_model(name, kane):
    """The model named `name` (validated by parse_model_name)."""
    if name == 'heavy-top':
        return heavy_top(kane)
    if name == 'rolling-disk':
        return rolling_disk(kane)
    return pendulum(int(name.split('-')[1]), kane)


# ---------------------------------------------------------------------------
# Derivation
# ---------------------------------------------------------------------------

def derive_lagrange(model):
    """Lagrange's equations with a multiplier per constraint.

    Returns mass_matrix_full, forcing_full and the positions of q'' among
    the unknowns of the acceleration block (q'' first, then multipliers).
    """
    lagrangian = (sum(body.kinetic_energy(model.frame)
                      for body in model.bodies) - model.potential)
    method = me.LagrangesMethod(lagrangian, model.q,
                                hol_coneqs=model.hol or None,
                                nonhol_coneqs=model.nonhol or None)
    method.form_lagranges_equations()
    mass, forcing = method.mass_matrix_full, method.forcing_full
    return mass, forcing, list(range(len(model.q)))


def derive_kane(model):
    """Kane's equations with u_i = q'_i and dependent speeds if constrained.

    Returns mass_matrix_full, forcing_full and the positions of u'_i = q''_i
    among the unknowns of the acceleration block (independent speeds first).
    The block holds the differentiated velocity constraints, so its solution
    gives the dependent accelerations too.
    """
    qdots = [qi.diff(T) for qi in model.q]
    kd_eqs = [qd - u for qd, u in zip(qdots, model.rates)]
    q_ind = [qi for qi in model.q if qi not in model.q_dep]
    u_ind = [u for u in model.rates if u not in model.u_dep]

    # Velocity constraints: the derivative of each position constraint,
    # then the velocity constraints, all in the speeds.
    qdot_to_u = dict(zip(qdots, model.rates))
    vel_cons = [h.diff(T).xreplace(qdot_to_u) for h in model.hol]
    vel_cons += model.nonhol

    method = me.KanesMethod(model.frame, q_ind, u_ind, kd_eqs=kd_eqs,
                            q_dependent=model.q_dep or None,
                            configuration_constraints=model.hol or None,
                            u_dependent=model.u_dep or None,
                            velocity_constraints=vel_cons or None)
    method.kanes_equations(model.bodies, model.loads)
    mass, forcing = method.mass_matrix_full, method.forcing_full
    speeds = list(method.u)
    return mass, forcing, [speeds.index(u) for u in model.rates]


def derive(name, method):
    """Build the model and derive its equations by `method`."""
    model = build_model(name, kane=(method == 'kane'))
    if method == 'lagrange':
        mass, forcing, order = derive_lagrange(model)
    else:
        mass, forcing, order = derive_kane(model)
    return model, mass, forcing, order


def timed_derivation(name, method, repeat):
    """Derive `repeat` times from a cleared SymPy cache; the minimum time."""
    best = math.inf
    for _ in range(repeat):
        clear_cache()
        start = time.perf_counter()
        result = derive(name, method)
        best = min(best, time.perf_counter() - start)
    return best, result


# ---------------------------------------------------------------------------
# Numeric evaluation
# ---------------------------------------------------------------------------

def solve_linear(a, b):
    """Solve a x = b by Gaussian elimination with partial pivoting."""
    n = len(b)
    rows = [list(map(float, a[i])) + [float(b[i])] for i in range(n)]
    for col in range(n):
        pivot = max(range(col, n), key=lambda r: abs(rows[r][col]))
        if rows[pivot][col] == 0.0:
            raise ZeroDivisionError('singular mass matrix at this state')
        rows[col], rows[pivot] = rows[pivot], rows[col]
        for r in range(col + 1, n):
            factor = rows[r][col] / rows[col][col]
            if factor != 0.0:
                for c in range(col, n + 1):
                    rows[r][c] -= factor * rows[col][c]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        s = rows[r][n] - sum(rows[r][c] * x[c] for c in range(r + 1, n))
        x[r] = s / rows[r][r]
    return x


def acceleration_function(model, mass_full, forcing_full, order):
    """A function (q, q') -> q'' from the acceleration block of the system.

    The first len(q) rows and columns of mass_matrix_full are the kinematic
    equations q' = rates; the remaining block gives q'' (Lagrange: with the
    multipliers; Kane: u' in KanesMethod's speed order).
    """
    n = len(model.q)
    mass = mass_full[n:, n:]
    forcing = forcing_full[n:, :]

    # Plain symbols for q, q' (= u) and the parameters.
    q_syms = sp.symbols(f'q0:{n}')
    r_syms = sp.symbols(f'r0:{n}')
    replace = {}
    for qi, ri, qs, rs in zip(model.q, model.rates, q_syms, r_syms):
        replace[qi.diff(T)] = rs
        replace[ri] = rs
        replace[qi] = qs
    mass = mass.xreplace(replace)
    forcing = forcing.xreplace(replace)
    for expr in (mass, forcing):
        if expr.atoms(AppliedUndef, sp.Derivative):
            raise RuntimeError('unexpected time functions left in the '
                               'equations: %s' % expr.atoms(AppliedUndef))

    # One lambdified function returning the flattened block and forcing.
    size = mass.shape[0]
    args = list(q_syms) + list(r_syms) + list(model.params)
    func = sp.lambdify(args, list(mass) + list(forcing), modules='math',
                       cse=True)
    values = list(model.params.values())

    def accelerations(q, qdot):
        flat = func(*q, *qdot, *values)
        a = [flat[i * size:(i + 1) * size] for i in range(size)]
        x = solve_linear(a, flat[size * size:])
        return [x[i] for i in order]

    return accelerations


# ---------------------------------------------------------------------------
# States
# ---------------------------------------------------------------------------

def euler313_omega(angles, rates):
    """Angular velocity in space components for the 3-1-3 angles.

    omega = psi' E3 + theta' e1' + phi' e3 with e1' = (cos psi, sin psi, 0)
    and e3 = Q E3 = (sin psi sin theta, -cos psi sin theta, cos theta).
    """
    psi, theta, _ = angles
    dpsi, dtheta, dphi = rates
    e3 = (math.sin(psi) * math.sin(theta), -math.cos(psi) * math.sin(theta),
          math.cos(theta))
    return [dtheta * math.cos(psi) + dphi * e3[0],
            dtheta * math.sin(psi) + dphi * e3[1],
            dpsi + dphi * e3[2]]


def disk_contact_velocity(q, qdot, radius=DISK_PARAMS['R']):
    """Velocity of the disk's contact point, v + omega x pi_P (space)."""
    _, _, _, psi, theta, _ = q
    w = euler313_omega(q[3:], qdot[3:])
    p = [radius * math.cos(theta) * math.sin(psi),
         -radius * math.cos(theta) * math.cos(psi),
         -radius * math.sin(theta)]
    cross = [w[1] * p[2] - w[2] * p[1],
             w[2] * p[0] - w[0] * p[2],
             w[0] * p[1] - w[1] * p[0]]
    return [qdot[i] + cross[i] for i in range(3)]


def disk_state(x1, x2, psi, theta, phi, dpsi, dtheta, dphi,
               radius=DISK_PARAMS['R']):
    """A rolling-disk state that satisfies the three constraints."""
    q = [x1, x2, radius * math.sin(theta), psi, theta, phi]
    qdot = [0.0, 0.0, 0.0, dpsi, dtheta, dphi]
    # With zero centre velocity, v_contact = omega x pi_P: cancel it.
    v = disk_contact_velocity(q, qdot, radius)
    qdot[0], qdot[1] = -v[0], -v[1]
    qdot[2] = radius * math.cos(theta) * dtheta
    return q + qdot


def disk_residual(state, radius=DISK_PARAMS['R']):
    """Largest violation of the height and rolling constraints."""
    q, qdot = state[:6], state[6:]
    v = disk_contact_velocity(q, qdot, radius)
    return max(abs(q[2] - radius * math.sin(q[4])), abs(v[0]), abs(v[1]))


def builtin_states(name, n):
    """Three fixed states (2n numbers each) for the model."""
    if name == 'heavy-top':
        return [[0.0, 0.3, 0.0, 0.0, 0.0, 60.0],
                [0.4, 0.7, -1.1, 1.3, -0.8, 40.0],
                [-2.0, 1.9, 2.5, -0.6, 0.9, -15.0]]
    if name == 'rolling-disk':
        # The yaml's initial state, then two generic ones.
        return [disk_state(0.0, 0.0, 0.0, 1.2, 0.0, 1.5, 0.0, 12.0),
                disk_state(0.3, -0.2, 0.7, 1.0, -0.4, 2.1, 0.6, 9.0),
                disk_state(-1.0, 0.5, -2.2, 1.9, 1.3, -0.7, -1.1, -6.5)]
    rng = random.Random(20240 + n)
    return [[rng.uniform(-1.5, 1.5) for _ in range(2 * n)]
            for _ in range(3)]


def read_states(path, n):
    """States from a text file: 2n numbers a line; '#' starts a comment."""
    states = []
    with open(path, encoding='utf-8') as f:
        for number, line in enumerate(f, 1):
            line = line.split('#', 1)[0].strip()
            if not line:
                continue
            values = [float(v) for v in line.split()]
            if len(values) != 2 * n:
                raise ValueError(f'{path}:{number}: expected {2 * n} '
                                 f'numbers, got {len(values)}')
            states.append(values)
    return states


# ---------------------------------------------------------------------------
# Command line
# ---------------------------------------------------------------------------

def parse_model_name(name):
    """Check MODEL and return its number of coordinates."""
    if name == 'heavy-top':
        return 3
    if name == 'rolling-disk':
        return 6
    match = re.fullmatch(r'pendulum-(\d+)', name)
    if match and 1 <= int(match.group(1)) <= 20:
        return int(match.group(1))
    raise argparse.ArgumentTypeError(
        f'unknown model {name!r}: pendulum-N (N = 1..20), heavy-top or '
        'rolling-disk')


def notes_for(name, method, repeat):
    """The 'notes' text of the output."""
    notes = [f'SymPy {sp.__version__}',
             'derive_seconds: min over %d run(s), SymPy cache cleared before '
             'each; covers building the system, forming the equations and '
             'mass_matrix_full/forcing_full (symbolic)' % repeat,
             'parameters symbolic during the derivation, substituted at '
             'evaluation (lambdify, math module, cse)']
    if method == 'lagrange':
        notes.append('LagrangesMethod with L = T - V (gravity in V)')
    else:
        notes.append('KanesMethod with u_i = q_i\' (kd_eqs q\' - u = 0), '
                     'gravity as loads')
    if name == 'rolling-disk':
        if method == 'lagrange':
            notes.append('constraints: hol_coneqs x3 - R sin(theta) and '
                         'nonhol_coneqs pi1, pi2 (no elimination of x3); '
                         'q\'\' from the system with the three multipliers')
        else:
            notes.append('x3 dependent coordinate (configuration constraint '
                         'x3 - R sin(theta)); dependent speeds u_x1, u_x2, '
                         'u_x3 from pi1, pi2 and x3\' - R cos(theta) theta\'; '
                         'dependent accelerations from the differentiated '
                         'velocity constraints in the mass matrix')
    if name == 'heavy-top' or name == 'rolling-disk':
        notes.append("3-1-3 angles via orient_body_fixed(N, (psi, theta, "
                     "phi), '313')")
    return '; '.join(notes)


def main(argv=None):
    parser = argparse.ArgumentParser(
        description='Derive benchmark equations of motion with SymPy.')
    parser.add_argument('model', help='pendulum-N, heavy-top or rolling-disk')
    parser.add_argument('--method', choices=METHODS, required=True)
    parser.add_argument('--states', metavar='FILE',
                        help='one state a line: q then q\' (2n numbers)')
    parser.add_argument('--repeat', type=int, default=1, metavar='K',
                        help='derive K times, report the minimum time')
    args = parser.parse_args(argv)
    try:
        n = parse_model_name(args.model)
    except argparse.ArgumentTypeError as err:
        parser.error(str(err))
    if args.repeat < 1:
        parser.error('--repeat must be at least 1')

    # States first, so that a bad file fails before the derivation.
    if args.states:
        try:
            states = read_states(args.states, n)
        except (OSError, ValueError) as err:
            parser.error(str(err))
    else:
        states = builtin_states(args.model, n)
    if args.model == 'rolling-disk':
        for state in states:
            if disk_residual(state) > 1e-8:
                print('warning: state violates the constraints by %.3g: %s'
                      % (disk_residual(state), state), file=sys.stderr)

    # Timed derivation, then the untimed numeric evaluation.
    seconds, (model, mass, forcing, order) = timed_derivation(
        args.model, args.method, args.repeat)
    accelerations = acceleration_function(model, mass, forcing, order)
    qddot = [accelerations(s[:n], s[n:]) for s in states]

    result = {'model': args.model, 'method': args.method, 'n': n,
              'derive_seconds': seconds,
              'notes': notes_for(args.model, args.method, args.repeat),
              'qddot': qddot}
    json.dump(result, sys.stdout)
    sys.stdout.write('\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
