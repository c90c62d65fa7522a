// `unidyn report`: one self-contained HTML page of a model and a run of it — the model and its
// equations of motion in the book's form (rendered as MathML), whether Newton–Euler and Lagrange
// agree and which velocity constraints are integrable; plots of the run (coordinates, rates,
// energy and its error, multipliers, outputs, conserved quantities) with its events marked;
// phase portraits; the equilibria, and the linearisation and modes about an operating point; and
// the motion in 3-D (particles as spheres, bodies as their shapes or ellipsoids of inertia,
// numeric/poses.hpp; the constraints' planes and spheres, report/constraint_surfaces.hpp). The
// page's script and style are embedded (report/web_assets.hpp), its data is one JSON object in
// it: it opens from a file, with no network and no server.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "unidyn/analysis/equilibria.hpp"
#include "unidyn/analysis/floquet.hpp"
#include "unidyn/analysis/modes.hpp"
#include "unidyn/equations/lagrange.hpp"
#include "unidyn/report/web_assets.hpp"

namespace unidyn {

// A run of the model: its rows with their columns (the simulation's, then the poses', then the
// constraint forces' of `force_owners`, numeric/constraint_forces.hpp), the summary printed for
// it, and its phases and events (t, what).
struct ReportRun {
  std::vector<std::string> columns;
  std::vector<std::string> force_owners;
  std::vector<std::vector<double>> rows;
  std::string summary;
  std::vector<std::pair<double, std::string>> events;
};

// The linearisation the page shows (analysis/linearization.hpp, analysis/modes.hpp): what point it
// is about, ẋ = A x in LaTeX as `unidyn modes --format latex` writes it (and A's closed form where
// there is one), and the modes, their shapes in `coordinates`.
struct ReportOperatingPoint {
  std::string label;
  std::string latex;
  std::vector<std::string> coordinates;
  ModeAnalysis modes;
  // A periodic motion of a driven system (analysis/floquet.hpp): its period and Floquet
  // multipliers in place of the modes, and ẋ = A(t) x with the monodromy matrix in the LaTeX.
  std::optional<FloquetAnalysis> floquet;
  double period = 0.0;
};

// What the page says of the model beyond its equations: the Newton–Euler check in words, and its
// equilibria (analysis/equilibria.hpp) with the starts they were sought from, or why they were
// not sought; the linearisation about an operating point, or why there is none.
struct ReportModel {
  const System& system;
  const EquationsOfMotion& equations;
  std::vector<double> parameters;
  std::string check;
  std::optional<EquilibriumSearchResult> equilibria;
  std::size_t equilibrium_starts = 0;
  std::string equilibria_not_sought;
  std::optional<ReportOperatingPoint> operating_point;
  std::string no_operating_point;
};

// The page. Equal input gives the same bytes.
std::string report_page(const ReportModel& model, const ReportRun& run, const WebAssets& assets);

}  // namespace unidyn
