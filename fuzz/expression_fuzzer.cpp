// libFuzzer target: the expression parser on arbitrary text, in the scope of a small model with
// coordinates, a particle, a body and a constraint (so names, members, calls, der() and vectors
// are all reachable), as a scalar and as a vector. A model error is the expected refusal.
#include <cstddef>
#include <cstdint>
#include <string>

#include "unidyn/io/model_file.hpp"
#include "unidyn/model/scope.hpp"
#include "unidyn/symbolic/expression_parser.hpp"

namespace {

const unidyn::System& model() {
  static const unidyn::System system = unidyn::parse_model(
      "unidyn: 1\n"
      "parameters: {m: 1, g: 9.81, L: 2, R: 0.5}\n"
      "coordinates: [x, y, psi, theta, phi]\n"
      "particles:\n"
      "  P: {mass: m, position: [x, y, 0]}\n"
      "bodies:\n"
      "  B:\n"
      "    mass: m\n"
      "    inertia: {disk: {radius: R}}\n"
      "    center: [x, 0, L]\n"
      "    rotation: {euler: 3-1-3, angles: [psi, theta, phi]}\n"
      "constraints:\n"
      "  - {name: c, position: x - L*sin(psi)}\n",
      "fuzz-scope.yaml");
  return system;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  static const unidyn::SystemScope scope(model());
  const unidyn::SourcePosition origin{"fuzz", 1, 1};
  try {
    (void)unidyn::parse_scalar(text, scope, origin);
  } catch (const unidyn::ModelError&) {
  }
  try {
    (void)unidyn::parse_vector(text, scope, origin);
  } catch (const unidyn::ModelError&) {
  }
  return 0;
}
