// Queries on a System.
#include "unidyn/model/system.hpp"

namespace unidyn {
namespace {

template <class T>
std::optional<std::size_t> find_by_name(const std::vector<T>& items, const std::string& wanted) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].name == wanted) return i;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::size_t> System::find_parameter(const std::string& wanted) const {
  return find_by_name(parameters, wanted);
}

std::optional<std::size_t> System::find_coordinate(const std::string& wanted) const {
  return find_by_name(coordinates(), wanted);
}

std::optional<std::size_t> System::find_particle(const std::string& wanted) const {
  return find_by_name(particles, wanted);
}

VectorExpr System::velocity(std::size_t p) const {
  return configuration.total_derivative(particles[p].position);
}

VectorExpr System::acceleration(std::size_t p) const {
  return configuration.total_derivative(velocity(p));
}

Expr System::potential_energy() const {
  Expr U = 0;
  for (const auto& f : forces) U += f.potential;
  return U;
}

Expr System::kinetic_energy() const {
  Expr T = 0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const VectorExpr v = velocity(p);
    T += particles[p].mass * dot(v, v) / 2;
  }
  return T;
}

GiNaC::exmap System::parameter_values() const {
  GiNaC::exmap map;
  for (const auto& p : parameters) map[p.symbol] = p.value;
  return map;
}

}  // namespace unidyn
