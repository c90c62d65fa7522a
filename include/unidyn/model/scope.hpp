// What names mean inside a model's expressions.
#pragma once

#include <map>
#include <string>

#include "unidyn/model/system.hpp"
#include "unidyn/symbolic/expression_parser.hpp"

namespace unidyn {

// Names of a System: parameters, coordinates and der(q), t, and particle members
// (P.position, P.velocity, P.acceleration, P.mass, P.momentum, P.angular_momentum about O,
// P.areal_velocity), and each constraint's multiplier c.lambda.
// Extra names (such as the stretch `s` inside a spring's energy) can be added on top.
class SystemScope : public Scope {
 public:
  explicit SystemScope(const System& system) : system_(system) {}

  void define(const std::string& name, Value value) { extra_.insert_or_assign(name, value); }

  std::optional<Value> lookup(std::string_view name) const override;
  std::optional<Expr> rate(std::string_view name) const override;
  std::optional<Value> call(std::string_view name, const std::vector<Value>& args) const override;
  std::vector<std::string> names() const override;

 private:
  // e1..e3, center, velocity, omega, H (about the centre), mass, angular_momentum (about O)
  std::optional<Value> body_member(std::size_t b, const std::string& member) const;

  const System& system_;
  std::map<std::string, Value, std::less<>> extra_;
};

}  // namespace unidyn
