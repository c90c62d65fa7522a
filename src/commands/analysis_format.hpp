// The pieces the analysis commands' output is made of (analysis_report.hpp, floquet_report.hpp):
// numbers, tables of matrices, state names, as text, JSON and LaTeX.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "unidyn/analysis/operating_point.hpp"

namespace unidyn::commands::format {

// A number with `digits` significant digits; zero (of either sign) as 0.
std::string number(double x, int digits = 12);
// a, b i, a+b i or a-b i with `digits` significant digits.
std::string complex_text(std::complex<double> z, int digits);
std::string joined(const std::vector<std::string>& items);
// A matrix as a table: the column names above, each row's name on its left.
std::string table(const Eigen::MatrixXd& A, const std::vector<std::string>& rows,
                  const std::vector<std::string>& columns);
// The values given ("phi = 0", "der(phi) = 2") of the point.
std::vector<std::string> given_values(const System& system, const OperatingPoint& point);
// [[a, b], [c, d]] and ["x", "y"].
std::string json_matrix(const Eigen::MatrixXd& A);
std::string json_names(const std::vector<std::string>& names);
// A number in LaTeX: twelve significant digits, 1.5e-07 as 1.5 \times 10^{-7}.
std::string latex_number(double x);
// A state name in LaTeX: phi → \phi, der(phi) → \dot{\phi}.
std::string latex_state(const std::string& name);
// The "operating_point" {coordinates, rates, accelerations} and "computed" members of a JSON
// object, each line indented by two spaces and ended by a comma.
std::string point_json(const System& system, const OperatingPoint& point);
// A bmatrix of entries already in LaTeX.
std::string bmatrix(const std::vector<std::vector<std::string>>& rows);
// A numeric matrix as a bmatrix.
std::string latex_matrix(const Eigen::MatrixXd& A);

}  // namespace unidyn::commands::format
