// Evaluating an expression in doubles, node by node.
#include "unidyn/symbolic/real_value.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace unidyn {
namespace {

using Unary = double (*)(double);

// The functions of the model language, by GiNaC name (as the tape compiles them).
std::optional<double> apply(const std::string& name, double x, double y) {
  static const std::map<std::string, Unary> unary = {
      {"sin", [](double v) { return std::sin(v); }},
      {"cos", [](double v) { return std::cos(v); }},
      {"tan", [](double v) { return std::tan(v); }},
      {"asin", [](double v) { return std::asin(v); }},
      {"acos", [](double v) { return std::acos(v); }},
      {"atan", [](double v) { return std::atan(v); }},
      {"sinh", [](double v) { return std::sinh(v); }},
      {"cosh", [](double v) { return std::cosh(v); }},
      {"tanh", [](double v) { return std::tanh(v); }},
      {"exp", [](double v) { return std::exp(v); }},
      {"log", [](double v) { return std::log(v); }},
      {"abs", [](double v) { return std::fabs(v); }},
      {"csgn", [](double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }},
      {"step", [](double v) { return v > 0 ? 1.0 : (v < 0 ? 0.0 : 0.5); }}};
  if (name == "atan2") return std::atan2(x, y);
  const auto f = unary.find(name);
  if (f == unary.end()) return std::nullopt;
  return f->second(x);
}

class Evaluator {
 public:
  explicit Evaluator(const GiNaC::exmap& values) : values_(values) {}

  std::optional<double> operator()(const Expr& e) const {
    std::optional<double> v = value(e);
    if (v && !std::isfinite(*v)) return std::nullopt;
    return v;
  }

 private:
  std::optional<double> value(const Expr& e) const {
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
      const auto& n = GiNaC::ex_to<GiNaC::numeric>(e);
      if (!n.is_real()) return std::nullopt;
      return n.to_double();
    }
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      const auto found = values_.find(e);
      if (found == values_.end() || !GiNaC::is_a<GiNaC::numeric>(found->second))
        return std::nullopt;
      return (*this)(found->second);
    }
    if (GiNaC::is_a<GiNaC::constant>(e)) {
      const Expr v = GiNaC::evalf(e);
      return GiNaC::is_a<GiNaC::numeric>(v) ? (*this)(v) : std::nullopt;
    }
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
      // the operands' values in increasing order, not GiNaC's (which changes from build to
      // build): the same rounding whatever order the terms are kept in
      const bool sum = GiNaC::is_a<GiNaC::add>(e);
      std::vector<double> operands;
      for (const auto& operand : e) {
        const auto v = (*this)(operand);
        if (!v) return std::nullopt;
        operands.push_back(*v);
      }
      std::sort(operands.begin(), operands.end());
      double result = sum ? 0.0 : 1.0;
      for (const double v : operands) result = sum ? result + v : result * v;
      return result;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
      const auto base = (*this)(e.op(0)), exponent = (*this)(e.op(1));
      if (!base || !exponent) return std::nullopt;
      if (*base == 0.0 && *exponent <= 0.0) return std::nullopt;  // division by zero
      return std::pow(*base, *exponent);
    }
    if (GiNaC::is_a<GiNaC::function>(e) && (e.nops() == 1 || e.nops() == 2)) {
      const auto x = (*this)(e.op(0));
      const auto y = e.nops() == 2 ? (*this)(e.op(1)) : x;
      if (!x || !y) return std::nullopt;
      return apply(GiNaC::ex_to<GiNaC::function>(e).get_name(), *x, *y);
    }
    return std::nullopt;
  }

  const GiNaC::exmap& values_;
};

}  // namespace

std::optional<double> real_value(const Expr& e, const GiNaC::exmap& values) {
  return Evaluator(values)(e);
}

}  // namespace unidyn
