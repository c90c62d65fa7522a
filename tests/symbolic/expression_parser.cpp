// The model-file expression language: meaning, exactness, errors at the right place, and hostile
// input that may only ever be refused with a ModelError.
#include "unidyn/symbolic/expression_parser.hpp"

#include <chrono>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "support/oracles.hpp"

namespace unidyn {
namespace {

using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

// A small model: parameters m g L, coordinates theta phi with rates, helpers x y a b c, time t,
// a particle P with a position, and one callable name P.offset(v) = P.position + v.
class TestScope : public Scope {
 public:
  TestScope() {
    for (const char* name : {"m", "g", "L", "theta", "phi", "x", "y", "a", "b", "c", "t"}) {
      symbols_.emplace(name, GiNaC::symbol(name));
    }
    rates_.emplace("theta", GiNaC::symbol("theta_dot"));
    rates_.emplace("phi", GiNaC::symbol("phi_dot"));
  }

  const GiNaC::symbol& operator[](const std::string& name) const { return symbols_.at(name); }
  const GiNaC::symbol& rate_of(const std::string& name) const { return rates_.at(name); }
  VectorExpr position() const { return {(*this)["x"], (*this)["y"], -(*this)["L"]}; }

  std::optional<Value> lookup(std::string_view name) const override {
    if (name == "P.position") return Value::of(position());
    const auto it = symbols_.find(name);
    if (it == symbols_.end()) return std::nullopt;
    return Value::of(it->second);
  }

  std::optional<Expr> rate(std::string_view name) const override {
    const auto it = rates_.find(name);
    if (it == rates_.end()) return std::nullopt;
    return Expr(it->second);
  }

  std::optional<Value> call(std::string_view name, const std::vector<Value>& args) const override {
    if (name != "P.offset" || args.size() != 1 || !args[0].is_vector()) return std::nullopt;
    return Value::of(position() + args[0].vector);
  }

  std::vector<std::string> names() const override {
    std::vector<std::string> all{"P.position"};
    for (const auto& [name, symbol] : symbols_) all.push_back(name);
    return all;
  }

 private:
  std::map<std::string, GiNaC::symbol, std::less<>> symbols_;
  std::map<std::string, GiNaC::symbol, std::less<>> rates_;
};

// A Scope whose every answer fails: its exceptions must come out as ModelErrors.
class ThrowingScope : public Scope {
 public:
  std::optional<Value> lookup(std::string_view) const override {
    throw std::runtime_error("lookup failed");
  }
  std::optional<Expr> rate(std::string_view) const override {
    throw std::runtime_error("rate failed");
  }
  std::vector<std::string> names() const override { throw std::runtime_error("names failed"); }
};

// Where the texts start in the model file: errors must be offset from here.
const SourcePosition kOrigin{"model.yaml", 7, 12};

bool same(const Expr& a, const Expr& b) {
  return (a - b).expand().is_zero();
}

class ExpressionParser : public ::testing::Test {
 protected:
  Expr scalar(const std::string& text) const { return parse_scalar(text, scope, kOrigin); }
  VectorExpr vector(const std::string& text) const { return parse_vector(text, scope, kOrigin); }
  Expr s(const std::string& name) const { return scope[name]; }

  void expect_same(const std::string& text, const Expr& expected) const {
    const Expr parsed = scalar(text);
    EXPECT_TRUE(same(parsed, expected)) << text << " gave " << parsed << ", expected " << expected;
  }

  void expect_same(const std::string& text, const VectorExpr& expected) const {
    const VectorExpr parsed = vector(text);
    for (int i = 0; i < 3; ++i) {
      EXPECT_TRUE(same(parsed[i], expected[i])) << text << " component " << i + 1 << " gave "
                                                << parsed[i] << ", expected " << expected[i];
    }
  }

  // The value at x = 0.3, y = -0.7 (and every other symbol 1.25), as a double.
  double evaluate(const Expr& e) const {
    GiNaC::exmap point;
    for (const std::string& name : scope.names()) {
      if (name != "P.position") point[scope[name]] = 1.25;
    }
    point[s("x")] = 0.3;
    point[s("y")] = -0.7;
    const Expr value = GiNaC::evalf(e.subs(point));
    EXPECT_TRUE(is_a<numeric>(value)) << e << " is not a number at the point: " << value;
    return is_a<numeric>(value) ? ex_to<numeric>(value).to_double() : NAN;
  }

  // A ModelError at line origin.line + line_offset and the given column of that line of the text.
  void expect_error(const std::string& text, int line_offset, int column,
                    const std::string& fragment) const {
    try {
      parse_expression(text, scope, kOrigin);
      ADD_FAILURE() << "no error for \"" << text << "\"";
    } catch (const ModelError& e) {
      const int expected_column = line_offset == 0 ? kOrigin.column + column - 1 : column;
      EXPECT_EQ(e.where().file, kOrigin.file) << text;
      EXPECT_EQ(e.where().line, kOrigin.line + line_offset) << text << ": " << e.what();
      EXPECT_EQ(e.where().column, expected_column) << text << ": " << e.what();
      EXPECT_NE(e.message().find(fragment), std::string::npos)
          << text << ": \"" << e.message() << "\" lacks \"" << fragment << "\"";
    }
  }

  // Parsing may succeed or throw ModelError, and nothing else.
  static void expect_only_model_errors(const std::string& text, const Scope& scope) {
    try {
      parse_expression(text, scope, kOrigin);
    } catch (const ModelError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << "\"" << text << "\" threw " << typeid(e).name() << ": " << e.what();
    } catch (...) {
      ADD_FAILURE() << "\"" << text << "\" threw something that is not an exception";
    }
  }

  TestScope scope;
};

TEST_F(ExpressionParser, PrecedenceAndAssociativity) {
  const Expr x = s("x"), a = s("a"), b = s("b"), c = s("c");
  expect_same("-x^2", -GiNaC::pow(x, 2));
  expect_same("-2^2", -4);
  expect_same("2^3^2", 512);
  expect_same("x^a^2", GiNaC::pow(x, GiNaC::pow(a, 2)));
  expect_same("2^-1", numeric(1, 2));
  expect_same("2^-x^2", GiNaC::pow(2, -GiNaC::pow(x, 2)));
  expect_same("a/b/c", a / (b * c));
  expect_same("a/b*c", a * c / b);
  expect_same("a-b-c", a - b - c);
  expect_same("a-b+c", a - b + c);
  expect_same("a+b*c", a + b * c);
  expect_same("(a+b)*c", (a + b) * c);
  expect_same("a*b^2", a * GiNaC::pow(b, 2));
  expect_same("a^b*c", GiNaC::pow(a, b) * c);
  expect_same("-a*b", -(a * b));
  expect_same("a*-b", -(a * b));
  expect_same("a - -b", a + b);
  expect_same("--a", a);
  expect_same("+a", a);
  expect_same("2*3+4*5", 26);
  expect_same("((a))", a);
}

TEST_F(ExpressionParser, NumbersAreExactRationals) {
  const Expr m = s("m");
  const Expr twentieth = scalar("0.05*m");
  EXPECT_TRUE(twentieth.is_equal(m / 20)) << twentieth;
  EXPECT_TRUE(twentieth.coeff(m).info(GiNaC::info_flags::rational));
  EXPECT_TRUE(scalar("1e-3").is_equal(numeric(1, 1000)));
  EXPECT_TRUE(scalar("2.5E+2").is_equal(250));
  EXPECT_TRUE(scalar("2.5e2").is_equal(250));
  EXPECT_TRUE(scalar(".5").is_equal(numeric(1, 2)));
  EXPECT_TRUE(scalar("5.").is_equal(5));
  EXPECT_TRUE(scalar("007").is_equal(7));
  EXPECT_TRUE(scalar("0.1 + 0.2").is_equal(numeric(3, 10)));
  EXPECT_TRUE(scalar("9.81").is_equal(numeric(981, 100)));
  EXPECT_TRUE(scalar("0e999").is_zero());
  EXPECT_TRUE(scalar("1.5e-0003").is_equal(numeric(3, 2000)));
  EXPECT_TRUE(
      scalar("123456789012345678901234567890").is_equal(numeric("123456789012345678901234567890")));
}

TEST_F(ExpressionParser, EveryFunctionMapsToItsGinacFunction) {
  struct Case {
    const char* text;
    double expected;
  };
  const double x = 0.3, y = -0.7;
  const Case cases[] = {
      {"sin(x)", std::sin(x)},
      {"cos(x)", std::cos(x)},
      {"tan(x)", std::tan(x)},
      {"asin(x)", std::asin(x)},
      {"acos(x)", std::acos(x)},
      {"atan(x)", std::atan(x)},
      {"sinh(x)", std::sinh(x)},
      {"cosh(x)", std::cosh(x)},
      {"tanh(x)", std::tanh(x)},
      {"exp(x)", std::exp(x)},
      {"log(x)", std::log(x)},
      {"sqrt(x)", std::sqrt(x)},
      {"abs(y)", std::abs(y)},
      {"abs(x)", std::abs(x)},
      {"sign(y)", -1.0},
      {"sign(x)", 1.0},
      {"atan2(x, y)", std::atan2(x, y)},
      {"atan2(y, x)", std::atan2(y, x)},
  };
  for (const Case& c : cases) EXPECT_NEAR(evaluate(scalar(c.text)), c.expected, 1e-14) << c.text;
  EXPECT_TRUE(scalar("sign(0)").is_zero());
  EXPECT_TRUE(scalar("sin(pi/6)").is_equal(numeric(1, 2)));
  EXPECT_TRUE(scalar("pi").is_equal(GiNaC::Pi));
}

TEST_F(ExpressionParser, VectorsAndTheirOperations) {
  const Expr a = s("a"), b = s("b"), c = s("c"), m = s("m");
  expect_same("[a, b, c]", VectorExpr(a, b, c));
  expect_same("E1", VectorExpr(1, 0, 0));
  expect_same("E2", VectorExpr(0, 1, 0));
  expect_same("E3", VectorExpr(0, 0, 1));
  expect_same("a*E1 + b*E2 - c*E3", VectorExpr(a, b, -c));
  expect_same("E1*m", VectorExpr(m, 0, 0));
  expect_same("m*E1*2", VectorExpr(2 * m, 0, 0));
  expect_same("[2, 4, 6]/2", VectorExpr(1, 2, 3));
  expect_same("-E1", VectorExpr(-1, 0, 0));
  expect_same("cross(E1, E2)", VectorExpr(0, 0, 1));
  expect_same("cross([a, b, c], E1)", VectorExpr(0, c, -b));
  expect_same("dot([1, 2, 3], [4, 5, 6])", Expr(32));
  expect_same("dot([a, b, c], E2)", b);
  expect_same("norm([3, 4, 0])", Expr(5));
  expect_same("norm(E1)*m", m);
  expect_same("P.position", scope.position());
  expect_same("P.offset(E3)", scope.position() + VectorExpr(0, 0, 1));
  expect_same("[a^2, (b), -c]", VectorExpr(GiNaC::pow(a, 2), b, -c));
}

TEST_F(ExpressionParser, RatesTimeAndNewlines) {
  const Expr theta = s("theta"), m = s("m"), L = s("L"), g = s("g");
  expect_same("der(theta)", scope.rate_of("theta"));
  expect_same("m*L^2*der(theta)^2/2 + m*g*L*cos(theta)",
              m * GiNaC::pow(L, 2) * GiNaC::pow(scope.rate_of("theta"), 2) / 2 +
                  m * g * L * GiNaC::cos(theta));
  expect_same("sin(t)", GiNaC::sin(s("t")));
  expect_same("m *\n  g\r\n\t+ L", m * g + L);
}

TEST_F(ExpressionParser, SphericalPendulumPosition) {
  const Expr L = s("L"), theta = s("theta"), phi = s("phi");
  const VectorExpr r = vector("L*[sin(theta)*cos(phi), sin(theta)*sin(phi), -cos(theta)]");
  expect_same("L*[sin(theta)*cos(phi), sin(theta)*sin(phi), -cos(theta)]",
              VectorExpr(L * GiNaC::sin(theta) * GiNaC::cos(phi),
                         L * GiNaC::sin(theta) * GiNaC::sin(phi), -L * GiNaC::cos(theta)));
  // |r| = L at any configuration.
  EXPECT_NEAR(evaluate(dot(r, r)), 1.25 * 1.25, 1e-14);
}

TEST_F(ExpressionParser, ErrorsNameTheOffendingToken) {
  // Names
  expect_error("m + thta", 0, 5, "unknown name 'thta'; did you mean 'theta'?");
  expect_error("m + foo", 0, 5, "unknown name 'foo'");
  expect_error("P.positon", 0, 1, "did you mean 'P.position'?");
  expect_error("sin + 1", 0, 1, "'sin' is a function: write sin(x)");
  expect_error("der", 0, 1, "'der' is a function");
  expect_error("m(2)", 0, 1, "'m' is not a function");
  expect_error("pi(2)", 0, 1, "'pi' is not a function");
  expect_error("sinn(m)", 0, 1, "unknown function 'sinn'; did you mean 'sin'?");
  // der
  expect_error("der(m)", 0, 5, "'m' is not a coordinate");
  expect_error("der(thet)", 0, 5, "did you mean 'theta'?");
  expect_error("der(2)", 0, 5, "der needs the name of a coordinate");
  expect_error("der(theta", 0, 10, "expected ')'");
  // Types
  expect_error("sin(E1)", 0, 5, "sin needs a scalar");
  expect_error("E1*E2", 0, 3, "cannot multiply two vectors: use dot(a, b) or cross(a, b)");
  expect_error("m*E1*E2", 0, 5, "cannot multiply two vectors");
  expect_error("m + E1", 0, 3, "'+' needs two scalars or two vectors, not a scalar and a vector");
  expect_error("E1 - m", 0, 4, "'-' needs two scalars or two vectors");
  expect_error("m/E1", 0, 2, "cannot divide by a vector");
  expect_error("E1^2", 0, 3, "cannot raise a vector to a power");
  expect_error("2^E1", 0, 3, "exponent must be a scalar");
  expect_error("dot(E1, m)", 0, 9, "dot needs a vector as its second argument");
  expect_error("norm(m)", 0, 6, "norm needs a vector");
  expect_error("atan2(m)", 0, 1, "atan2 takes 2 arguments");
  expect_error("sin(m, g)", 0, 1, "sin takes 1 argument");
  expect_error("cross(E1)", 0, 1, "cross takes 2 arguments");
  // Vector literals
  expect_error("[1, 2]", 0, 6, "a vector has three components");
  expect_error("[1, 2, 3, 4]", 0, 9, "a vector has three components");
  expect_error("[1, E1, 3]", 0, 5, "must be a scalar");
  expect_error("[1 2 3]", 0, 4, "expected ','");
  expect_error("[1, 2, 3", 0, 9, "expected ']'");
  // Structure
  expect_error("(a + b", 0, 7, "expected ')' to close the '(' at 7:12");
  expect_error("3 +", 0, 4, "expected a number, a name, '(' or '['");
  expect_error("", 0, 1, "found the end of the expression");
  expect_error("   ", 0, 4, "found the end of the expression");
  expect_error("m m", 0, 3, "expected an operator");
  expect_error("2x", 0, 2, "expected an operator");
  expect_error(")", 0, 1, "expected a number");
  expect_error("m)", 0, 2, "unmatched ')'");
  expect_error("m]", 0, 2, "unmatched ']'");
  expect_error("m, g", 0, 2, "unexpected ','");
  expect_error("2^^3", 0, 3, "expected a number");
  expect_error("sin(m", 0, 6, "expected ',' or ')'");
  // Characters and numbers
  expect_error("m $ g", 0, 3, "unexpected character '$'");
  expect_error("m + \xCE\xB8", 0, 5, "names and operators are ASCII");
  expect_error(std::string("m\0g", 3), 0, 2, "unexpected character (byte 0x00)");
  expect_error("2**3", 0, 2, "'**' is not an operator");
  expect_error("1e+", 0, 1, "malformed number");
  expect_error("m + 2E", 0, 5, "malformed number");
  expect_error("1e99999999999", 0, 1, "out of range");
  expect_error("1e100000", 0, 1, "out of range");
  // Undefined values
  expect_error("1/0", 0, 2, "division by zero");
  expect_error("x/(x - x)", 0, 2, "division by zero");
  expect_error("0^-1", 0, 2, "division by zero");
  expect_error("0^0", 0, 2, "0^0 is undefined");
  expect_error("log(0)", 0, 1, "cannot evaluate log");
  expect_error("m + tan(pi/2)", 0, 5, "cannot evaluate tan");
  // Huge numbers
  expect_error("2^99999999999", 0, 2, "number too large");
  expect_error("10^100000", 0, 3, "number too large");
  expect_error("(2*x)^(10^9)", 0, 6, "number too large");
  expect_error("sqrt(2)^(10^9)", 0, 8, "number too large");
  expect_error("9^9^9^9", 0, 4, "number too large");
}

TEST_F(ExpressionParser, ErrorsAcrossLines) {
  expect_error("m +\n  thta", 1, 3, "did you mean 'theta'?");
  expect_error("m +\r\n\r\n   foo", 2, 4, "unknown name 'foo'");
  expect_error("(m +\n g", 1, 3, "expected ')' to close the '(' at 7:12");
  expect_error("m +\tfoo", 0, 5, "unknown name 'foo'");
  // Without a known origin, positions count within the text.
  try {
    parse_expression("m +\n foo", scope, {});
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().column, 2);
    EXPECT_EQ(std::string(e.what()), "<input>:2:2: unknown name 'foo'");
  }
}

TEST_F(ExpressionParser, ScalarOrVectorAsRequired) {
  EXPECT_THROW(scalar("E1"), ModelError);
  EXPECT_THROW(vector("m*g"), ModelError);
  try {
    scalar("  (E1 + E2)");
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().column, kOrigin.column + 2);
    EXPECT_NE(e.message().find("expected a scalar"), std::string::npos) << e.what();
  }
  try {
    vector("m*g");
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().column, kOrigin.column);
    EXPECT_NE(e.message().find("expected a vector"), std::string::npos) << e.what();
  }
  const Value v = parse_expression("E1", scope, kOrigin);
  EXPECT_TRUE(v.is_vector());
}

TEST_F(ExpressionParser, ScopeFailuresBecomeModelErrors) {
  const ThrowingScope failing;
  try {
    parse_expression("1 + m", failing, kOrigin);
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().column, kOrigin.column + 4);
    EXPECT_NE(e.message().find("lookup failed"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_expression("der(q)", failing, kOrigin), ModelError);
  EXPECT_THROW(parse_expression("f(1)", failing, kOrigin), ModelError);
  EXPECT_TRUE(same(parse_scalar("2*pi", failing, kOrigin), 2 * GiNaC::Pi));
}

TEST_F(ExpressionParser, ReservedNames) {
  for (const char* name : {"pi", "E1", "E2", "E3", "der", "sin", "atan2", "sign", "norm"}) {
    EXPECT_TRUE(is_reserved_name(name)) << name;
  }
  for (const char* name : {"m", "theta", "t", "e1", "Pi", "top.e1"}) {
    EXPECT_FALSE(is_reserved_name(name)) << name;
  }
}

TEST_F(ExpressionParser, HugeNumbersAreRefusedOrKeptSymbolic) {
  const Expr x = s("x");
  EXPECT_TRUE(scalar("x^99999999999").is_equal(GiNaC::pow(x, numeric("99999999999"))));
  EXPECT_TRUE(scalar("x^(10^9)").is_equal(GiNaC::pow(x, 1000000000)));
  EXPECT_TRUE(scalar("(x^(1/2))^(10^9)").is_equal(GiNaC::pow(x, 500000000)));
  EXPECT_TRUE(scalar("2^1000").is_equal(GiNaC::pow(2, 1000)));
  EXPECT_TRUE(scalar("x^(2^1000)*x").is_equal(GiNaC::pow(x, GiNaC::pow(2, 1000) + 1)));
  EXPECT_TRUE(scalar("sqrt(4^40000)").is_equal(GiNaC::pow(2, 40000)));
  EXPECT_THROW(scalar("(2^65000)*(2^65000)"), ModelError);
  EXPECT_THROW(scalar("(2^65000*x)^3"), ModelError);
  // A sum is not expanded, so its numbers are not raised.
  EXPECT_NO_THROW(scalar("(2^65000 + x)^3"));
}

// Limits: a long, wide or deep text is refused quickly, never a crash or a hang.
TEST_F(ExpressionParser, HostileNestingLengthAndGrowth) {
  const auto started = std::chrono::steady_clock::now();
  // 256 levels at most: the 257th '(' (column 257 of the text) is refused.
  expect_error(std::string(100000, '('), 0, 257, "nested too deeply");
  expect_error(std::string(99999, '-') + "x", 0, 257, "nested too deeply");
  expect_error(std::string(50000, '['), 0, 257, "nested too deeply");
  std::string calls;
  for (int i = 0; i < 20000; ++i) calls += "sin(";
  expect_error(calls, 0, 4 * 256 + 1, "nested too deeply");
  std::string powers;
  for (int i = 0; i < 40000; ++i) powers += "x^";
  expect_error(powers + "x", 0, 2 * 256 + 1, "nested too deeply");
  // 255 levels of parentheses are fine.
  EXPECT_TRUE(scalar(std::string(255, '(') + "m" + std::string(255, ')')).is_equal(s("m")));

  // More than 100000 characters, here a megabyte, is refused at the start of the text.
  std::string megabyte;
  while (megabyte.size() < (1u << 20)) megabyte += "m + ";
  expect_error(megabyte + "m", 0, 1, "expression too long");

  // Nested cross products would double in size at every level.
  std::string nested = "E1";
  for (int i = 0; i < 60; ++i) nested = "cross(" + nested + ", [a, b, c])";
  EXPECT_THROW(vector(nested), ModelError);
  try {
    vector(nested);
  } catch (const ModelError& e) {
    EXPECT_NE(e.message().find("expression too large"), std::string::npos) << e.what();
  }

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_LT(seconds, 10.0);  // refusals are immediate
}

// Long chains up to the length limit are built in one step each, not one term at a time.
TEST_F(ExpressionParser, LongButLegalInputIsFast) {
  const auto started = std::chrono::steady_clock::now();
  std::string sum;
  while (sum.size() < ExpressionLimits::max_length - 10) sum += "m+";
  sum += "m";
  const Expr many_m = scalar(sum);
  EXPECT_TRUE(many_m.is_equal(static_cast<long>(sum.size() / 2 + 1) * s("m")));

  // A wide sum of distinct terms, multiplied by 2 again and again.
  std::string wide = "(";
  int terms = 0;
  while (wide.size() < 50000) {
    ++terms;
    wide += (terms > 1 ? "+x^" : "x^") + std::to_string(terms);
  }
  wide += ")";
  int twos = 0;
  for (; wide.size() < ExpressionLimits::max_length - 2; ++twos) wide += "*2";
  const Expr doubled = scalar(wide);
  EXPECT_EQ(doubled.nops(), static_cast<std::size_t>(terms));
  EXPECT_TRUE(doubled.coeff(s("x"), 1).is_equal(GiNaC::pow(2, twos)));

  // 2*2*...*2 within the number limit.
  std::string product = "2";
  while (product.size() < 99999) product += "*2";
  EXPECT_TRUE(scalar(product).is_equal(GiNaC::pow(2, 50000)));

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_LT(seconds, 10.0);  // quadratic chains would take minutes
}

// Random bytes: every one of them parses or is refused with a ModelError.
TEST_F(ExpressionParser, FuzzRandomBytes) {
  std::mt19937 engine(20261121u);
  std::uniform_int_distribution<int> length(0, 40);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<int> ascii(0x20, 0x7E);
  std::bernoulli_distribution printable(0.8);
  for (int n = 0; n < 4000; ++n) {
    std::string text;
    for (int i = length(engine); i > 0; --i) {
      text += static_cast<char>(printable(engine) ? ascii(engine) : byte(engine));
    }
    expect_only_model_errors(text, scope);
  }
}

// Random sequences of the language's own tokens reach deeper into the parser.
TEST_F(ExpressionParser, FuzzTokenSoup) {
  const std::vector<std::string> tokens = {
      "m",   "x",     "theta", "P.position", "P.offset",    "E1",   "E2",   "pi",   "t",  "der",
      "sin", "atan2", "dot",   "cross",      "norm",        "sqrt", "log",  "sign", "0",  "1",
      "2",   "0.5",   "1e-3",  "1e999",      "99999999999", "10",   "(",    "(",    ")",  ")",
      "[",   "]",     ",",     ",",          "+",           "-",    "*",    "/",    "^",  "^",
      " ",   "\n",    "foo",   ".",          "der(theta)",  "**",   "\xFF", "e",    "2e", "0^",
      "/0",  "E"};
  std::mt19937 engine(7u);
  std::uniform_int_distribution<std::size_t> pick(0, tokens.size() - 1);
  std::uniform_int_distribution<int> length(1, 30);
  for (int n = 0; n < 6000; ++n) {
    std::string text;
    for (int i = length(engine); i > 0; --i) text += tokens[pick(engine)];
    expect_only_model_errors(text, scope);
    expect_only_model_errors(text, ThrowingScope{});
  }
}

// Random expressions from the grammar itself, with random types and hostile numbers, so that
// many of them parse and reach GiNaC.
class ExpressionGenerator {
 public:
  explicit ExpressionGenerator(unsigned seed) : engine_(seed) {}

  std::string operator()(int depth) {
    static const std::vector<std::string> leaves = {
        "m", "x", "theta", "t",    "E1", "P.position",  "pi",    "der(theta)", "0",
        "1", "2", "0.5",   "3e-2", "7",  "99999999999", "1e999", "[1, 0, m]"};
    static const std::vector<std::string> functions = {"sin",  "cos",  "tan",  "asin", "acos",
                                                       "atan", "sinh", "cosh", "tanh", "exp",
                                                       "log",  "sqrt", "abs",  "sign"};
    static const std::vector<std::string> operators = {" + ", " - ", "*", "/", "^"};
    if (depth <= 0 || pick(4) == 0) return leaves[pick(leaves.size())];
    switch (pick(7)) {
      case 0:
        return "-" + (*this)(depth - 1);
      case 1:
        return "(" + (*this)(depth - 1) + ")";
      case 2:
        return functions[pick(functions.size())] + "(" + (*this)(depth - 1) + ")";
      case 3:
        return "atan2(" + (*this)(depth - 1) + ", " + (*this)(depth - 1) + ")";
      case 4: {
        static const std::vector<std::string> vector_functions = {"dot", "cross", "norm"};
        const std::string& f = vector_functions[pick(3)];
        if (f == "norm") return "norm(" + (*this)(depth - 1) + ")";
        return f + "(" + (*this)(depth - 1) + ", " + (*this)(depth - 1) + ")";
      }
      case 5:
        return "[" + (*this)(depth - 1) + ", " + (*this)(depth - 1) + ", " + (*this)(depth - 1) +
               "]";
      default:
        return (*this)(depth - 1) + operators[pick(operators.size())] + (*this)(depth - 1);
    }
  }

 private:
  std::size_t pick(std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(engine_);
  }

  std::mt19937 engine_;
};

TEST_F(ExpressionParser, FuzzGeneratedExpressions) {
  ExpressionGenerator generate(31u);
  int parsed = 0;
  for (int n = 0; n < 3000; ++n) {
    const std::string text = generate(6);
    try {
      parse_expression(text, scope, kOrigin);
      ++parsed;
    } catch (const ModelError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << "\"" << text << "\" threw " << typeid(e).name() << ": " << e.what();
    }
  }
  // The generator is only useful if a good share of its expressions get through.
  EXPECT_GT(parsed, 300);
}

// Valid expressions with characters deleted, repeated or replaced.
TEST_F(ExpressionParser, FuzzMutatedExpressions) {
  const std::vector<std::string> seeds = {
      "L*[sin(theta)*cos(phi), sin(theta)*sin(phi), -cos(theta)]",
      "m*L^2*der(theta)^2/2 + m*g*L*cos(theta)",
      "dot(cross(P.position, E3), E1 - 2.5e-3*E2) / norm(P.offset([1, 2, 3]))",
      "atan2(x, -y)^-2^3 - sqrt(abs(sign(a) * 0.05))",
  };
  const std::string alphabet = "()[],+-*/^.e0129 xmE";
  std::mt19937 engine(99u);
  std::uniform_int_distribution<int> edits(1, 6);
  std::uniform_int_distribution<int> kind(0, 2);
  std::uniform_int_distribution<std::size_t> letter(0, alphabet.size() - 1);
  for (int n = 0; n < 3000; ++n) {
    std::string text = seeds[static_cast<std::size_t>(n) % seeds.size()];
    for (int e = edits(engine); e > 0 && !text.empty(); --e) {
      const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(engine);
      switch (kind(engine)) {
        case 0:
          text.erase(at, 1);
          break;
        case 1:
          text.insert(at, 1, text[at]);
          break;
        default:
          text[at] = alphabet[letter(engine)];
          break;
      }
    }
    expect_only_model_errors(text, scope);
  }
}

}  // namespace
}  // namespace unidyn
