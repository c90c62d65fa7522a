// The dynamics tape printed as a self-contained C, Python or MATLAB function.
#include "unidyn/numeric/code_export.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "tape_language.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {
namespace {

using detail::TapeLanguage;

TapeLanguage tape_language(CodeLanguage language) {
  switch (language) {
    case CodeLanguage::c:
      return TapeLanguage::c;
    case CodeLanguage::python:
      return TapeLanguage::python;
    case CodeLanguage::matlab:
      return TapeLanguage::matlab;
  }
  return TapeLanguage::c;
}

// A constant: exact hexadecimal in C, otherwise the shortest decimal that reads back exactly.
std::string literal(double value, CodeLanguage language) {
  if (std::isnan(value)) {
    return language == CodeLanguage::c        ? "NAN"
           : language == CodeLanguage::python ? "math.nan"
                                              : "NaN";
  }
  if (std::isinf(value)) {
    const std::string inf = language == CodeLanguage::c        ? "INFINITY"
                            : language == CodeLanguage::python ? "math.inf"
                                                               : "Inf";
    return value > 0 ? inf : "(-" + inf + ")";
  }
  char text[64];
  if (language == CodeLanguage::c) {
    std::snprintf(text, sizeof text, "%a", value);
    return text;
  }
  // the shortest decimal that reads back as the same double
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// The text of each input register: t, q[i], qd[i], p[k] (MATLAB from 1).
std::vector<std::string> input_names(std::size_t n, std::size_t parameters, CodeLanguage language) {
  const int base = language == CodeLanguage::matlab ? 1 : 0;
  const bool matlab = language == CodeLanguage::matlab;
  const auto element = [&](const char* array, std::size_t i) {
    return std::string(array) + (matlab ? "(" : "[") + std::to_string(i + base) +
           (matlab ? ")" : "]");
  };
  std::vector<std::string> names{"t"};
  for (std::size_t i = 0; i < n; ++i) names.push_back(element("q", i));
  for (std::size_t i = 0; i < n; ++i) names.push_back(element("qd", i));
  for (std::size_t k = 0; k < parameters; ++k) names.push_back(element("p", k));
  return names;
}

// The tape's body: the registers it reads set from the inputs and constants, then each
// instruction, one statement per line with `indent` (in C the registers declared first).
std::string tape_body(const Tape& tape, const std::vector<std::string>& inputs,
                      CodeLanguage language, const std::string& indent) {
  std::ostringstream os;
  const std::string end = language == CodeLanguage::python ? "" : ";";
  const std::size_t n_inputs = tape.input_count(), constants = tape.constant_count();
  const auto reg = [](std::uint32_t r) { return "r" + std::to_string(r); };
  // the registers read (an unread input or constant is not set: no unused variables in C)
  std::vector<bool> read(tape.register_count(), false), written(tape.register_count(), false);
  for (const TapeInstruction& i : tape.instructions()) {
    read[i.a] = true;
    if (i.op == TapeOp::sincos) {
      written[i.b] = true;
    } else {
      read[i.b] = true;
    }
    written[i.dst] = true;
  }
  for (const std::uint32_t r : tape.output_registers()) read[r] = true;
  for (std::size_t r = 0; r < n_inputs + constants; ++r) written[r] = read[r];
  if (language == CodeLanguage::c) {
    std::string declared;
    for (std::size_t r = 0; r < tape.register_count(); ++r) {
      if (written[r]) declared += (declared.empty() ? " r" : ", r") + std::to_string(r);
    }
    if (!declared.empty()) os << indent << "double" << declared << ";\n";
  }
  for (std::size_t r = 0; r < n_inputs + constants; ++r) {
    if (!read[r]) continue;
    os << indent << "r" << r << " = "
       << (r < n_inputs ? inputs[r] : literal(tape.constants()[r - n_inputs], language)) << end
       << "\n";
  }
  const TapeLanguage dialect = tape_language(language);
  for (const TapeInstruction& i : tape.instructions()) {
    if (i.op == TapeOp::sincos) {
      // sin x and cos x into dst and b; the one whose register holds x is written last
      const std::string x = reg(i.a);
      const std::string sine = indent + reg(i.dst) + " = " + detail::tape_function("sin", dialect) +
                               "(" + x + ")" + end + "\n";
      const std::string cosine = indent + reg(i.b) + " = " + detail::tape_function("cos", dialect) +
                                 "(" + x + ")" + end + "\n";
      os << (i.dst == i.a ? cosine + sine : sine + cosine);
      continue;
    }
    os << indent << reg(i.dst) << " = " << detail::tape_operation(i.op, reg(i.a), reg(i.b), dialect)
       << end << "\n";
  }
  return os.str();
}

// The header: what the functions compute, the parameters in order with the model's values.
std::string header(const System& system, const char* comment) {
  std::ostringstream os;
  const auto line = [&](const std::string& text) { os << comment << " " << text << "\n"; };
  line(system.name + ": Lagrange's equations, generated by unidyn");
  line("M(q, t) q'' = f(q, q', t) + A^T lambda,  A q'' + b = 0");
  line("coordinates q (and rates qd) in order:");
  std::string names;
  for (const auto& q : system.coordinates()) names += " " + q.name;
  line(" " + names);
  line("parameters p in order, with the model's values:");
  for (const auto& p : system.parameters)
    line("   " + p.name + " = " + literal(p.value, CodeLanguage::python));
  return os.str();
}

std::string c_source(const System& system, const Tape& tape, const std::string& name) {
  const std::size_t n = system.coordinates().size(), m = system.constraints.size();
  std::ostringstream os;
  os << "/*\n" << header(system, " *") << " */\n#include <math.h>\n\n";
  os << "/* M (n*n, row by row), f (n), A (m*n, row by row), b (m) at (t, q, qd, p). */\n";
  os << "void " << name
     << "_eom(double t, const double* q, const double* qd, const double* p, double* M, double* f, "
        "double* A, double* b) {\n";
  os << tape_body(tape, input_names(n, system.parameters.size(), CodeLanguage::c), CodeLanguage::c,
                  "  ");
  const auto& out = tape.output_registers();
  std::size_t k = 0;
  for (std::size_t i = 0; i < n * n; ++i) os << "  M[" << i << "] = r" << out[k++] << ";\n";
  for (std::size_t i = 0; i < n; ++i) os << "  f[" << i << "] = r" << out[k++] << ";\n";
  for (std::size_t i = 0; i < m * n; ++i) os << "  A[" << i << "] = r" << out[k++] << ";\n";
  for (std::size_t i = 0; i < m; ++i) os << "  b[" << i << "] = r" << out[k++] << ";\n";
  os << "  (void)t; (void)q; (void)qd; (void)p; (void)A; (void)b;\n}\n\n";
  const std::size_t size = n + m;
  os << "/* q'' (n) and lambda (m) at (t, q, qd, p): [M -A^T; A 0] [q''; lambda] = [f; -b] by\n"
        "   Gaussian elimination with partial pivoting. Returns 0, or -1 when it is singular. */\n";
  os << "int " << name
     << "_accelerations(double t, const double* q, const double* qd, const double* p, double* "
        "qdd, double* lambda) {\n";
  os << "  enum { N = " << n << ", C = " << m << ", S = " << size << " };\n";
  os << "  double M[N * N], f[N], A[(C > 0 ? C : 1) * N], b[C > 0 ? C : 1], K[S][S + 1];\n";
  os << "  int i, j, k;\n";
  os << "  " << name << "_eom(t, q, qd, p, M, f, A, b);\n";
  os << R"(  for (i = 0; i < S; ++i)
    for (j = 0; j <= S; ++j) K[i][j] = 0.0;
  for (i = 0; i < N; ++i) {
    for (j = 0; j < N; ++j) K[i][j] = M[i * N + j];
    for (k = 0; k < C; ++k) K[i][N + k] = -A[k * N + i];
    K[i][S] = f[i];
  }
  for (k = 0; k < C; ++k) {
    for (j = 0; j < N; ++j) K[N + k][j] = A[k * N + j];
    K[N + k][S] = -b[k];
  }
  for (k = 0; k < S; ++k) {
    int pivot = k;
    for (i = k + 1; i < S; ++i)
      if (fabs(K[i][k]) > fabs(K[pivot][k])) pivot = i;
    if (K[pivot][k] == 0.0) return -1;
    for (j = k; j <= S; ++j) {
      double swap = K[k][j];
      K[k][j] = K[pivot][j];
      K[pivot][j] = swap;
    }
    for (i = k + 1; i < S; ++i) {
      double factor = K[i][k] / K[k][k];
      for (j = k; j <= S; ++j) K[i][j] -= factor * K[k][j];
    }
  }
  for (i = S - 1; i >= 0; --i) {
    double x = K[i][S];
    for (j = i + 1; j < S; ++j) x -= K[i][j] * K[j][S];
    K[i][S] = x / K[i][i];
  }
  for (i = 0; i < N; ++i) qdd[i] = K[i][S];
  for (k = 0; k < C; ++k) lambda[k] = K[N + k][S];
  return 0;
}
)";
  return os.str();
}

std::string python_source(const System& system, const Tape& tape, const std::string& name) {
  const std::size_t n = system.coordinates().size(), m = system.constraints.size();
  std::ostringstream os;
  os << header(system, "#") << "# " << name << ": eom(t, q, qd, p) -> (M, f, A, b); "
     << "accelerations(t, q, qd, p) -> (qdd, lam)\nimport math\n\n";
  os << "N = " << n << "\nC = " << m << "\nPARAMETERS = {";
  for (std::size_t k = 0; k < system.parameters.size(); ++k) {
    os << (k ? ", " : "") << "'" << system.parameters[k].name
       << "': " << literal(system.parameters[k].value, CodeLanguage::python);
  }
  os << "}\n\n\ndef eom(t, q, qd, p):\n";
  os << "    \"\"\"M (n lists of n), f, A (m lists of n), b at (t, q, qd, p).\"\"\"\n";
  os << tape_body(tape, input_names(n, system.parameters.size(), CodeLanguage::python),
                  CodeLanguage::python, "    ");
  const auto& out = tape.output_registers();
  std::size_t k = 0;
  const auto rows = [&](std::size_t count, std::size_t width) {
    std::string text = "[";
    for (std::size_t i = 0; i < count; ++i) {
      text += i ? ", [" : "[";
      for (std::size_t j = 0; j < width; ++j) text += (j ? ", r" : "r") + std::to_string(out[k++]);
      text += "]";
    }
    return text + "]";
  };
  const std::string M = rows(n, n), f = rows(1, n), A = rows(m, n), b = rows(1, m);
  os << "    return " << M << ", " << f.substr(1, f.size() - 2) << ", " << A << ", "
     << b.substr(1, b.size() - 2) << "\n\n\n";
  os << R"(def accelerations(t, q, qd, p):
    """q'' and lambda at (t, q, qd, p): [M -A^T; A 0] [q''; lambda] = [f; -b] by Gaussian
    elimination with partial pivoting; raises ZeroDivisionError when it is singular."""
    M, f, A, b = eom(t, q, qd, p)
    S = N + C
    K = [[0.0] * (S + 1) for _ in range(S)]
    for i in range(N):
        for j in range(N):
            K[i][j] = M[i][j]
        for k in range(C):
            K[i][N + k] = -A[k][i]
        K[i][S] = f[i]
    for k in range(C):
        for j in range(N):
            K[N + k][j] = A[k][j]
        K[N + k][S] = -b[k]
    for k in range(S):
        pivot = max(range(k, S), key=lambda i: abs(K[i][k]))
        if K[pivot][k] == 0.0:
            raise ZeroDivisionError('the system is singular')
        K[k], K[pivot] = K[pivot], K[k]
        for i in range(k + 1, S):
            factor = K[i][k] / K[k][k]
            for j in range(k, S + 1):
                K[i][j] -= factor * K[k][j]
    for i in range(S - 1, -1, -1):
        x = K[i][S]
        for j in range(i + 1, S):
            x -= K[i][j] * K[j][S]
        K[i][S] = x / K[i][i]
    return [K[i][S] for i in range(N)], [K[N + k][S] for k in range(C)]
)";
  return os.str();
}

std::string matlab_source(const System& system, const Tape& tape, const std::string& name) {
  const std::size_t n = system.coordinates().size(), m = system.constraints.size();
  std::ostringstream os;
  os << "function [qdd, lambda, M, f, A, b] = " << name << "(t, q, qd, p)\n";
  os << header(system, "%") << "% [qdd; lambda] solve [M -A'; A 0] [qdd; lambda] = [f; -b].\n";
  os << tape_body(tape, input_names(n, system.parameters.size(), CodeLanguage::matlab),
                  CodeLanguage::matlab, "  ");
  const auto& out = tape.output_registers();
  std::size_t k = 0;
  const auto matrix = [&](std::size_t rows, std::size_t cols) {
    std::string text = "[";
    for (std::size_t i = 0; i < rows; ++i) {
      for (std::size_t j = 0; j < cols; ++j) {
        text += (j ? ", r" : "r") + std::to_string(out[k++]);
      }
      if (i + 1 < rows) text += "; ";
    }
    return text + "]";
  };
  os << "  M = " << matrix(n, n) << ";\n";
  os << "  f = " << matrix(n, 1) << ";\n";
  os << "  A = " << (m > 0 ? matrix(m, n) : "zeros(0, " + std::to_string(n) + ")") << ";\n";
  os << "  b = " << (m > 0 ? matrix(m, 1) : std::string("zeros(0, 1)")) << ";\n";
  os << "  x = [M, -A'; A, zeros(" << m << ")] \\ [f; -b];\n";
  os << "  qdd = x(1:" << n << ");\n  lambda = x(" << n + 1 << ":end);\nend\n";
  return os.str();
}

}  // namespace

std::string export_code(const System& system, const EquationsOfMotion& eq, CodeLanguage language,
                        const std::string& name) {
  const Tape tape = dynamics_tape(system, eq);
  switch (language) {
    case CodeLanguage::c:
      return c_source(system, tape, name);
    case CodeLanguage::python:
      return python_source(system, tape, name);
    case CodeLanguage::matlab:
      return matlab_source(system, tape, name);
  }
  return {};
}

}  // namespace unidyn
