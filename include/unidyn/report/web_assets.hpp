// The page script and style of `unidyn report` (web/: three.js, uPlot and KaTeX bundled by esbuild
// at build time from the npm packages pinned in web/package-lock.json), embedded in the binary.
#pragma once

#include <optional>
#include <string_view>

namespace unidyn {

struct WebAssets {
  std::string_view script, style;
};

// Nothing when the build had no Node.js and npm to make them (scripts/setup.sh installs them).
std::optional<WebAssets> web_assets();

}  // namespace unidyn
