#!/usr/bin/env python3
"""Linearise the rolling disk about upright rolling with SymPy's Linearizer.

Usage:
    python3 bench/sympy/linearize.py [--spin OMEGA]

The disk of bench/sympy/derive.py (models/rolling-disk.yaml: coordinates x1, x2, x3, psi, theta,
phi, the height constraint x3 = R sin(theta) and two rolling constraints), derived by KanesMethod
with x3 and the speeds of x1, x2, x3 dependent, then linearised by KanesMethod.linearize about
upright rolling at spin OMEGA (theta = pi/2, phi' = OMEGA, x1' = -R OMEGA, the rest 0). The time of
the derivation and of the linearisation (A and B, with the operating point substituted) are
reported separately, and the eigenvalues of A (evaluated with the parameters' values), as one JSON
object on stdout.
"""

import argparse
import json
import os
import sys
import time

import sympy as sp
from sympy.physics import mechanics as me

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import derive  # noqa: E402  (the models of the derivation benchmark)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--spin', type=float, default=10.0)
    args = parser.parse_args(argv)

    start = time.perf_counter()
    model = derive.rolling_disk(kane=True)
    qdots = [qi.diff(derive.T) for qi in model.q]
    kd_eqs = [qd - u for qd, u in zip(qdots, model.rates)]
    q_ind = [qi for qi in model.q if qi not in model.q_dep]
    u_ind = [u for u in model.rates if u not in model.u_dep]
    qdot_to_u = dict(zip(qdots, model.rates))
    vel_cons = [h.diff(derive.T).xreplace(qdot_to_u) for h in model.hol] + model.nonhol
    method = me.KanesMethod(model.frame, q_ind, u_ind, kd_eqs=kd_eqs,
                            q_dependent=model.q_dep, configuration_constraints=model.hol,
                            u_dependent=model.u_dep, velocity_constraints=vel_cons)
    method.kanes_equations(model.bodies, model.loads)
    derived = time.perf_counter()

    m, g, R = model.params
    x1, x2, x3, psi, theta, phi = model.q
    u = dict(zip(['x1', 'x2', 'x3', 'psi', 'theta', 'phi'], model.rates))
    spin = sp.Float(args.spin)
    op_point = {x1: 0, x2: 0, x3: R, psi: 0, theta: sp.pi / 2, phi: 0,
                u['x1']: -R * spin, u['x2']: 0, u['x3']: 0, u['psi']: 0, u['theta']: 0,
                u['phi']: spin}
    # the accelerations at the operating point: all 0 (steady upright rolling)
    op_point.update({r.diff(derive.T): 0 for r in model.rates})
    A, _, _ = method.linearize(op_point=op_point, A_and_B=True)
    linearised = time.perf_counter()

    values = {symbol: value for symbol, value in model.params.items()}
    A_numeric = sp.Matrix(A).subs(values).evalf()
    eigenvalues = [complex(sp.N(lam)) for lam, count in A_numeric.eigenvals().items()
                   for _ in range(count)]
    json.dump({'derive_seconds': derived - start, 'linearize_seconds': linearised - derived,
               'size': A.shape[0],
               'eigenvalues': [[e.real, e.imag] for e in eigenvalues]}, sys.stdout)
    sys.stdout.write('\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
