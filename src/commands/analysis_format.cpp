// The analysis commands' numbers, tables and names as text, JSON and LaTeX.
#include "analysis_format.hpp"

#include "unidyn/io/json_text.hpp"
#include "unidyn/numeric/number_text.hpp"
#include "unidyn/symbolic/coordinates.hpp"

namespace unidyn::commands::format {

// A number with `digits` significant digits; zero (of either sign) as 0.
std::string number(double x, int digits) {
  return x == 0.0 ? "0" : detail::to_short_text(x, digits);
}

// a, b i, a+b i or a-b i with `digits` significant digits.
std::string complex_text(std::complex<double> z, int digits) {
  if (z.imag() == 0.0) return number(z.real(), digits);
  const std::string imaginary = number(std::abs(z.imag()), digits) + "i";
  if (z.real() == 0.0) return (z.imag() < 0 ? "-" : "") + imaginary;
  return number(z.real(), digits) + (z.imag() < 0 ? "-" : "+") + imaginary;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// A matrix as a table: the column names above, each row's name on its left.
std::string table(const Eigen::MatrixXd& A, const std::vector<std::string>& rows,
                  const std::vector<std::string>& columns) {
  std::vector<std::vector<std::string>> cells(static_cast<std::size_t>(A.rows()));
  std::size_t width = 0, label = 0;
  for (const auto& c : columns) width = std::max(width, c.size());
  for (const auto& r : rows) label = std::max(label, r.size());
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
      cells[static_cast<std::size_t>(i)].push_back(number(A(i, j)));
      width = std::max(width, cells[static_cast<std::size_t>(i)].back().size());
    }
  }
  std::string out = "  " + std::string(label, ' ');
  for (const auto& c : columns) out += "  " + std::string(width - c.size(), ' ') + c;
  out += '\n';
  for (std::size_t i = 0; i < cells.size(); ++i) {
    out += "  " + rows[i] + std::string(label - rows[i].size(), ' ');
    for (const auto& cell : cells[i]) out += "  " + std::string(width - cell.size(), ' ') + cell;
    out += '\n';
  }
  return out;
}

// The values given and the coordinates' and rates' names.
std::vector<std::string> given_values(const System& system, const OperatingPoint& point) {
  std::vector<std::string> out;
  const auto& q = system.coordinates();
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (point.q_given[i])
      out.push_back(q[i].name + " = " + number(point.q[static_cast<Eigen::Index>(i)]));
  }
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (point.qdot_given[i]) {
      out.push_back("der(" + q[i].name + ") = " + number(point.qdot[static_cast<Eigen::Index>(i)]));
    }
  }
  return out;
}

std::string json_matrix(const Eigen::MatrixXd& A) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    out += i ? ", [" : "[";
    for (Eigen::Index j = 0; j < A.cols(); ++j) out += (j ? ", " : "") + json_number(A(i, j));
    out += "]";
  }
  return out + "]";
}

std::string json_names(const std::vector<std::string>& names) {
  std::string out = "[";
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + quoted(names[i]);
  return out + "]";
}

// A number in LaTeX: twelve significant digits, 1.5e-07 as 1.5 \times 10^{-7}.
std::string latex_number(double x) {
  const std::string text = number(x);
  const std::size_t e = text.find('e');
  if (e == std::string::npos) return text;
  const int exponent = std::stoi(text.substr(e + 1));
  return text.substr(0, e) + " \\times 10^{" + std::to_string(exponent) + "}";
}

// A state name in LaTeX: phi → \phi, der(phi) → \dot{\phi}.
std::string latex_state(const std::string& name) {
  if (name.starts_with("der(")) return "\\dot{" + latex_name(name.substr(4, name.size() - 5)) + "}";
  return latex_name(name);
}

// A bmatrix of entries already in LaTeX.
std::string bmatrix(const std::vector<std::vector<std::string>>& rows) {
  std::string out = "\\begin{bmatrix}";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    out += i ? " \\\\ " : " ";
    for (std::size_t j = 0; j < rows[i].size(); ++j) out += (j ? " & " : "") + rows[i][j];
  }
  return out + " \\end{bmatrix}";
}

std::string point_json(const System& system, const OperatingPoint& point) {
  const auto& q = system.coordinates();
  const auto values = [&](const Eigen::VectorXd& v, const std::string& prefix,
                          const std::string& suffix) {
    std::string s = "{";
    for (std::size_t i = 0; i < q.size(); ++i) {
      s += (i ? ", " : "") + quoted(prefix + q[i].name + suffix) + ": " +
           json_number(v[static_cast<Eigen::Index>(i)]);
    }
    return s + "}";
  };
  const std::string source =
      point.source.empty() ? "" : "  \"source\": " + quoted(point.source) + ",\n";
  return source + "  \"operating_point\": {\"coordinates\": " + values(point.q, "", "") +
         ",\n    \"rates\": " + values(point.qdot, "der(", ")") +
         ",\n    \"accelerations\": " + values(point.qddot, "der(der(", "))") +
         "},\n  \"computed\": " + json_names(point.computed) + ",\n";
}

std::string latex_matrix(const Eigen::MatrixXd& A) {
  std::vector<std::vector<std::string>> rows(static_cast<std::size_t>(A.rows()));
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
      rows[static_cast<std::size_t>(i)].push_back(latex_number(A(i, j)));
    }
  }
  return bmatrix(rows);
}

}  // namespace unidyn::commands::format
