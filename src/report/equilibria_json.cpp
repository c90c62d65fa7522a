// The report page's equilibria: each with its coordinates, verdict and eigenvalues.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "page_data.hpp"
#include "unidyn/io/json_text.hpp"

namespace unidyn {
namespace {

// The linearisation's eigenvalues as text.
std::string eigenvalues_json(const ModeAnalysis& modes) {
  std::vector<std::string> out;
  for (const Mode& mode : modes.modes) out.push_back(eigenvalue_text(mode, modes.tolerance));
  return json_names(out);
}

}  // namespace

// The equilibria found: for each its coordinates (an ignorable one "any"), verdict and reason,
// eigenvalues, the dimension of a continuum it lies on, and the energy method's word.
std::string equilibria_json(const ReportModel& model) {
  if (!model.equilibria) {
    return "{\"not_sought\": " + unidyn::quoted(model.equilibria_not_sought) + "}";
  }
  const EquilibriumSearchResult& found = *model.equilibria;
  const auto& q = model.system.coordinates();
  std::vector<std::string> items;
  for (const Equilibrium& e : found.equilibria) {
    std::vector<std::string> values;
    for (std::size_t i = 0; i < q.size(); ++i) {
      const auto& ignorable = e.linearization.ignorable;
      const bool any = std::find(ignorable.begin(), ignorable.end(), q[i].name) != ignorable.end();
      values.push_back(any ? std::string("\"any\"")
                           : fmt::format("{:.9g}", e.point.q[static_cast<Eigen::Index>(i)]));
    }
    items.push_back(
        "{\"coordinates\": [" + fmt::format("{}", fmt::join(values, ", ")) +
        "], \"stability\": " + unidyn::quoted(to_string(e.modes.verdict)) + ", \"reason\": " +
        unidyn::quoted(e.modes.reason) + ", \"eigenvalues\": " + eigenvalues_json(e.modes) +
        ", \"continuum\": " + std::to_string(e.continuum) + ", \"potential_minimum\": " +
        (e.potential_minimum ? (*e.potential_minimum ? "true" : "false") : "null") + "}");
  }
  return fmt::format("{{\"starts\": {}, \"singular\": {}, \"moving\": {}, \"items\": [{}]}}",
                     model.equilibrium_starts, found.singular, found.not_steady,
                     fmt::join(items, ",\n"));
}

}  // namespace unidyn
