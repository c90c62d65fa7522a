// Evaluating an expression in doubles, node by node.
#include "unidyn/symbolic/real_value.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <unordered_map>
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

// Values at several points at once, NaN where not a finite real: each node is looked at once
// (shared nodes too) whatever the number of points.
using Samples = std::vector<double>;

class Evaluator {
 public:
  explicit Evaluator(const std::vector<GiNaC::exmap>& points) : points_(points) {}

  const Samples& operator()(const Expr& e) const {
    // a node shared by several parents once (the node held: op() makes some anew, and a freed
    // node's address may be another's next)
    const GiNaC::basic* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (const auto it = memo_.find(node); it != memo_.end()) return it->second.second;
    Samples v = value(e);
    for (double& x : v) {
      if (!std::isfinite(x)) x = NAN;
    }
    return memo_.emplace(node, std::make_pair(e, std::move(v))).first->second.second;
  }

 private:
  Samples constant(double x) const { return Samples(points_.size(), x); }

  // a scalar function of one or two values at each point
  template <typename F>
  Samples each(const Samples& x, const Samples& y, F f) const {
    Samples r(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) r[k] = f(x[k], y[k]);
    return r;
  }

  Samples value(const Expr& e) const {
    using GiNaC::is_exactly_a;
    if (is_exactly_a<GiNaC::numeric>(e)) {
      const auto& n = GiNaC::ex_to<GiNaC::numeric>(e);
      return constant(n.is_real() ? n.to_double() : NAN);
    }
    if (is_exactly_a<GiNaC::add>(e) || is_exactly_a<GiNaC::mul>(e)) {
      // the operands' values in increasing magnitude (then value), not GiNaC's order (which
      // changes from build to build): the same rounding whatever order the terms are kept in,
      // and for −(b − a) as for a − b, which GiNaC writes either way; a zero without a sign
      const bool sum = is_exactly_a<GiNaC::add>(e);
      std::vector<const Samples*> operands;
      for (const auto& operand : e) operands.push_back(&(*this)(operand));
      Samples result(points_.size());
      std::vector<double> at(operands.size());
      for (std::size_t k = 0; k < result.size(); ++k) {
        bool defined = true;
        for (std::size_t i = 0; i < operands.size(); ++i) {
          at[i] = (*operands[i])[k];
          defined = defined && !std::isnan(at[i]);
        }
        if (!defined) {
          result[k] = NAN;
          continue;
        }
        std::sort(at.begin(), at.end(), [](double a, double b) {
          return std::fabs(a) != std::fabs(b) ? std::fabs(a) < std::fabs(b) : a < b;
        });
        double r = sum ? 0.0 : 1.0;
        for (const double v : at) r = sum ? r + v : r * v;
        result[k] = r == 0.0 ? 0.0 : r;
      }
      return result;
    }
    if (is_exactly_a<GiNaC::power>(e)) {
      return each((*this)(e.op(0)), (*this)(e.op(1)), [](double base, double exponent) {
        if (base == 0.0 && exponent <= 0.0) return double(NAN);  // division by zero
        return std::pow(base, exponent);
      });
    }
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      Samples r(points_.size());
      for (std::size_t k = 0; k < r.size(); ++k) {
        const auto found = points_[k].find(e);
        r[k] = found == points_[k].end() || !GiNaC::is_a<GiNaC::numeric>(found->second)
                   ? NAN
                   : (*this)(found->second)[k];
      }
      return r;
    }
    if (GiNaC::is_a<GiNaC::constant>(e)) {
      const Expr v = GiNaC::evalf(e);
      return GiNaC::is_a<GiNaC::numeric>(v) ? (*this)(v) : constant(NAN);
    }
    if (GiNaC::is_a<GiNaC::function>(e) && (e.nops() == 1 || e.nops() == 2)) {
      const Samples& x = (*this)(e.op(0));
      const Samples& y = e.nops() == 2 ? (*this)(e.op(1)) : x;
      const std::string& name = GiNaC::ex_to<GiNaC::function>(e).get_name();
      if (name != "atan2" && !apply(name, 0.5, 0.5)) return constant(NAN);
      return each(x, y, [&](double a, double b) {
        if (std::isnan(a) || std::isnan(b)) return double(NAN);
        return apply(name, a, b).value_or(NAN);
      });
    }
    return constant(NAN);
  }

  const std::vector<GiNaC::exmap>& points_;
  mutable std::unordered_map<const GiNaC::basic*, std::pair<Expr, Samples>> memo_;
};

std::optional<double> finite(double x) {
  if (std::isnan(x)) return std::nullopt;
  return x;
}

}  // namespace

std::optional<double> real_value(const Expr& e, const GiNaC::exmap& values) {
  const std::vector<GiNaC::exmap> points{values};
  return finite(Evaluator(points)(e)[0]);
}

std::vector<std::vector<std::optional<double>>> real_values(
    const std::vector<Expr>& e, const std::vector<GiNaC::exmap>& points) {
  const Evaluator evaluate(points);
  std::vector<std::vector<std::optional<double>>> result;
  for (const Expr& x : e) {
    const Samples& v = evaluate(x);
    result.emplace_back();
    for (const double y : v) result.back().push_back(finite(y));
  }
  return result;
}

}  // namespace unidyn
