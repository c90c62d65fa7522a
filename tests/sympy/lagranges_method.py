#!/usr/bin/env python3
"""unidyn's JSON (`derive --format json`) against SymPy's own LagrangesMethod.

Usage: lagranges_method.py MODEL JSON_FILE
Builds MODEL (one of the bundled models below) independently with sympy.physics.mechanics, forms
Lagrange's equations with LagrangesMethod, reads unidyn's mass matrix and forcing with sympify and
the names the JSON declares, and exits 0 when simplify(M_unidyn - M_sympy) and
simplify(f_unidyn - f_sympy) are 0 entry by entry; otherwise it prints the entries that differ and
exits 1.
"""
import json
import sys

import sympy as sp
from sympy.physics.mechanics import (LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)


def particle(name, frame, origin, position, mass, gravity):
    """A particle at `position` from `origin`, its potential m g·r for gravity g."""
    point = origin.locatenew(name, position)
    point.set_vel(frame, position.dt(frame))
    p = Particle(name, point, mass)
    p.potential_energy = -mass * gravity.dot(position)
    return p


def model(name):
    """(coordinates, Lagrangian) of a bundled model, as its file describes it."""
    N = ReferenceFrame('N')
    O = Point('O')
    O.set_vel(N, 0)
    t = dynamicsymbols._t
    if name == 'double-pendulum':
        th1, th2 = dynamicsymbols('theta1 theta2')
        m1, m2, l1, l2, g = sp.symbols('m1 m2 l1 l2 g')
        r1 = l1 * (sp.sin(th1) * N.x - sp.cos(th1) * N.y)
        r2 = r1 + l2 * (sp.sin(th2) * N.x - sp.cos(th2) * N.y)
        gravity = -g * N.y
        parts = [particle('P1', N, O, r1, m1, gravity), particle('P2', N, O, r2, m2, gravity)]
        return [th1, th2], Lagrangian(N, *parts)
    if name == 'spherical-pendulum':
        phi, theta = dynamicsymbols('phi theta')
        m, g, L = sp.symbols('m g L')
        r = L * (sp.sin(phi) * sp.cos(theta) * N.x + sp.sin(phi) * sp.sin(theta) * N.y +
                 sp.cos(phi) * N.z)
        return [phi, theta], Lagrangian(N, particle('P', N, O, r, m, -g * N.z))
    if name == 'rotating-hoop':
        phi = dynamicsymbols('phi')
        m, g, R0, Omega = sp.symbols('m g R0 Omega')
        r = R0 * (sp.sin(phi) * sp.cos(Omega * t) * N.x +
                  sp.sin(phi) * sp.sin(Omega * t) * N.y + sp.cos(phi) * N.z)
        return [phi], Lagrangian(N, particle('P', N, O, r, m, -g * N.z))
    raise SystemExit('no SymPy model for ' + name)


def plain(expr, coordinates):
    """q(t), q', q'' as the plain symbols q, q_d, q_dd that unidyn's JSON uses."""
    t = dynamicsymbols._t
    for q in coordinates:
        name = q.func.__name__
        expr = expr.subs(q.diff(t, 2), sp.Symbol(name + '_dd'))
        expr = expr.subs(q.diff(t), sp.Symbol(name + '_d'))
        expr = expr.subs(q, sp.Symbol(name))
    return expr


def main():
    name, path = sys.argv[1], sys.argv[2]
    with open(path, encoding='utf-8') as f:
        data = json.load(f)
    coordinates, lagrangian = model(name)
    method = LagrangesMethod(lagrangian, coordinates)
    method.form_lagranges_equations()
    mass, forcing = method.mass_matrix, method.forcing
    names = {'t': dynamicsymbols._t}
    for c in data['coordinates']:
        for key in ('name', 'rate', 'acceleration'):
            names[c[key]] = sp.Symbol(c[key])
    for p in data['parameters']:
        names[p['name']] = sp.Symbol(p['name'])
    n = len(coordinates)
    assert len(data['coordinates']) == n, 'coordinates'
    differ = []
    for i in range(n):
        for j in range(n):
            ours = sp.sympify(data['mass_matrix'][i][j], locals=names)
            if sp.simplify(ours - plain(mass[i, j], coordinates)) != 0:
                differ.append(f'M[{i}][{j}]: {ours} vs {plain(mass[i, j], coordinates)}')
        ours = sp.sympify(data['forcing'][i], locals=names)
        if sp.simplify(ours - plain(forcing[i], coordinates)) != 0:
            differ.append(f'f[{i}]: {ours} vs {plain(forcing[i], coordinates)}')
    for line in differ:
        print(line)
    print(f'{name}: {"agrees" if not differ else "DIFFERS"} with LagrangesMethod ({n} coordinates)')
    sys.exit(1 if differ else 0)


if __name__ == '__main__':
    main()
