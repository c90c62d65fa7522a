// The model file's impulses: `impulses: [{time: t1, at: P, value: [..]}, {time: t2, on: B,
// point: [X1, X2, X3], value: [..]}]` — an impulse Î at a particle, or at a material point of a
// body (components on its basis from its centre, default the centre), at a time after the start.
#include "model_reader.hpp"

namespace unidyn::model_reading {

void ModelReader::read_impulses(const YAML::Node& node, System& system) {
  if (!node.IsSequence()) {
    fail(node,
         "impulses is a list of {time: T, at: P, value: [..]} or {time: T, on: B, point: "
         "[X1, X2, X3], value: [..]}");
  }
  const SystemScope scope(system);
  for (const auto& spec : node) {
    expect_map(spec, "an impulse");
    expect_keys(spec, {"time", "at", "on", "point", "value"}, "an impulse");
    if (!spec["time"] || !spec["value"] || !!spec["at"] == !!spec["on"]) {
      fail(spec,
           "an impulse needs time:, value: and either at: (a particle) or on: (a body, with "
           "point: [X1, X2, X3] on its basis from its centre)");
    }
    AppliedImpulse impulse;
    impulse.name = "impulse " + std::to_string(system.impulses.size() + 1);
    impulse.where = at(spec);
    // its time: a number or parameters, after the start (a change at the start is an initial rate)
    impulse.time = scalar_expr(spec["time"], scope, "time");
    expect_state_only(spec["time"], impulse.time, system, "an impulse's time");
    expect_parameters_only(spec["time"], impulse.time, system,
                           "an impulse's time is a number or depends on parameters only");
    impulse.impulse = vector_expr(spec["value"], scope, "value");
    expect_state_only(spec["value"], impulse.impulse, system, "an impulse");
    if (spec["at"]) {
      if (spec["point"]) fail(spec["point"], "point: is for a body (on: B)");
      const auto p = system.find_particle(scalar(spec["at"], "at"));
      if (!p) fail(spec["at"], "at: must name a particle");
      impulse.point = system.particles[*p].position;
    } else {
      const auto b = system.find_body(scalar(spec["on"], "on"));
      if (!b) fail(spec["on"], "on: must name a body");
      const VectorExpr X =
          spec["point"] ? vector_expr(spec["point"], scope, "point") : VectorExpr{};
      for (const auto& q : system.coordinates()) {
        for (int i = 0; i < 3; ++i) {
          if (X[i].has(q.value) || X[i].has(system.time())) {
            fail(spec["point"], "a point on a body is constant on its basis");
          }
        }
      }
      impulse.point = system.material_point(*b, X);
    }
    system.impulses.push_back(std::move(impulse));
  }
}

}  // namespace unidyn::model_reading
