// The YAML text of the benchmark's pendulum-N (bench/MODELS.md): N point masses on unit links,
// relative hinge angles q1..qN, the first link hinged at the origin, gravity −g E2. Header-only:
// the tests build the same chain (tests/models/inertia_assembly.cpp).
#pragma once

#include <string>

namespace unidyn::bench {

inline std::string pendulum_text(int links) {
  std::string text = "unidyn: 1\nname: pendulum-" + std::to_string(links) +
                     "\nparameters: {m: 1.0, L: 1.0, g: 9.81}\ncoordinates: [";
  for (int k = 1; k <= links; ++k) text += (k > 1 ? ", q" : "q") + std::to_string(k);
  text += "]\nparticles:\n";
  std::string theta;
  for (int k = 1; k <= links; ++k) {
    theta += (k > 1 ? " + q" : "q") + std::to_string(k);
    text += "  P" + std::to_string(k) + ": {mass: m, position: \"" +
            (k > 1 ? "P" + std::to_string(k - 1) + ".position + " : std::string()) + "L*[sin(" +
            theta + "), -cos(" + theta + "), 0]\"}\n";
  }
  text += "forces:\n  - gravity: -g*E2\ninitial: {q1: 0.5";
  if (links > 1) text += ", q2: 0.0";
  text += "}\nsimulate: {t_end: 100, output_step: 1, rtol: 1e-10}\n";
  return text;
}

}  // namespace unidyn::bench
