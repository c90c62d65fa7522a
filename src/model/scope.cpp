// Name resolution for model expressions.
#include "unidyn/model/scope.hpp"

namespace unidyn {

std::optional<Value> SystemScope::lookup(std::string_view name) const {
  if (const auto it = extra_.find(name); it != extra_.end()) return it->second;
  const std::string key(name);
  if (key == "t") return Value::of(system_.time());
  if (const auto p = system_.find_parameter(key)) return Value::of(system_.parameters[*p].symbol);
  if (const auto q = system_.find_coordinate(key)) {
    return Value::of(system_.coordinates()[*q].value);
  }
  if (const auto d = system_.find_definition(key)) {
    const Definition& definition = system_.definitions[*d];
    return definition.is_vector ? Value::of(definition.vector) : Value::of(definition.scalar);
  }
  // Members: P.position, P.velocity, P.acceleration, P.mass of a particle; c.lambda of a
  // constraint.
  const std::size_t dot = key.find('.');
  if (dot == std::string::npos) return std::nullopt;
  const std::string owner = key.substr(0, dot);
  const std::string member = key.substr(dot + 1);
  for (const auto& c : system_.constraints) {
    if (c.name == owner && member == "lambda") return Value::of(c.multiplier);
  }
  if (const auto b = system_.find_body(owner)) return body_member(*b, member);
  const auto p = system_.find_particle(owner);
  if (!p) return std::nullopt;
  if (member == "position") return Value::of(system_.particles[*p].position);
  if (member == "velocity") return Value::of(system_.velocity(*p));
  if (member == "acceleration") return Value::of(system_.acceleration(*p));
  if (member == "mass") return Value::of(system_.particles[*p].mass);
  // (1.3) G = m v, H_O = r × m v about the fixed origin, and the areal velocity ½ r × v
  const Expr& m = system_.particles[*p].mass;
  const VectorExpr& r = system_.particles[*p].position;
  if (member == "momentum") return Value::of(m * system_.velocity(*p));
  if (member == "angular_momentum") return Value::of(cross(r, m * system_.velocity(*p)));
  if (member == "areal_velocity") return Value::of(cross(r, system_.velocity(*p)) / 2);
  return std::nullopt;
}

std::optional<Value> SystemScope::body_member(std::size_t b, const std::string& member) const {
  const Body& body = system_.bodies[b];
  if (member == "e1" || member == "e2" || member == "e3") {
    return Value::of(system_.body_basis_vector(b, member[1] - '0'));
  }
  if (member == "center") return Value::of(body.center);
  if (member == "origin") return Value::of(body.origin);
  if (member == "velocity") return Value::of(system_.center_velocity(b));
  if (member == "omega") return Value::of(system_.angular_velocity(b));
  if (member == "H") return Value::of(system_.angular_momentum(b));
  if (member == "mass") return Value::of(body.mass);
  // H_O = x̄ × m v̄ + H about the fixed origin
  if (member == "angular_momentum") {
    return Value::of(cross(body.center, body.mass * system_.center_velocity(b)) +
                     system_.angular_momentum(b));
  }
  return std::nullopt;
}

std::optional<Value> SystemScope::call(std::string_view name,
                                       const std::vector<Value>& args) const {
  // body.point([X1, X2, X3]): the material point x̄ + Q X; body.frame_point(X): o + Q X
  const std::string key(name);
  const std::size_t dot = key.find('.');
  if (dot == std::string::npos) return std::nullopt;
  const std::string member = key.substr(dot + 1);
  if (member != "point" && member != "frame_point") return std::nullopt;
  const auto b = system_.find_body(key.substr(0, dot));
  if (!b || args.size() != 1 || !args[0].is_vector()) return std::nullopt;
  if (member == "point") return Value::of(system_.material_point(*b, args[0].vector));
  const Body& body = system_.bodies[*b];
  return Value::of(body.origin + times(body.rotation, args[0].vector));
}

std::optional<Expr> SystemScope::rate(std::string_view name) const {
  if (const auto q = system_.find_coordinate(std::string(name))) {
    return Expr(system_.coordinates()[*q].rate);
  }
  return std::nullopt;
}

std::vector<std::string> SystemScope::names() const {
  std::vector<std::string> all{"t"};
  for (const auto& [name, value] : extra_) all.push_back(name);
  for (const auto& p : system_.parameters) all.push_back(p.name);
  for (const auto& q : system_.coordinates()) all.push_back(q.name);
  for (const auto& d : system_.definitions) all.push_back(d.name);
  for (const auto& c : system_.constraints) all.push_back(c.name + ".lambda");
  for (const auto& b : system_.bodies) {
    for (const char* member : {".e1", ".e2", ".e3", ".center", ".origin", ".velocity", ".omega",
                               ".H", ".mass", ".angular_momentum"}) {
      all.push_back(b.name + member);
    }
  }
  for (const auto& p : system_.particles) {
    for (const char* member : {".position", ".velocity", ".acceleration", ".mass", ".momentum",
                               ".angular_momentum", ".areal_velocity"}) {
      all.push_back(p.name + member);
    }
  }
  return all;
}

}  // namespace unidyn
