// The pieces of the report page's data (report_page.cpp): numbers, names, the 3-D scene and the
// equilibria, as JSON.
#pragma once

#include <string>
#include <vector>

#include "unidyn/report/report_page.hpp"

namespace unidyn {

// A number for the page's plots and scene: nine significant digits (the CSV keeps every bit);
// null when not finite.
std::string page_number(double x);

// ["a", "b"].
std::string json_names(const std::vector<std::string>& names);

// The 3-D scene: the bodies' shapes, the particles' spheres, the box the motion stays in, the
// owners of the constraint forces drawn.
std::string scene_json(const ReportModel& model, const ReportRun& run);

// The equilibria found (or why none were sought), each with its verdict and eigenvalues.
std::string equilibria_json(const ReportModel& model);

// The linearisation about the operating point (or why there is none): its label, LaTeX, modes
// with their frequencies, damping ratios and shapes, and the verdict.
std::string operating_point_json(const ReportModel& model);

}  // namespace unidyn
