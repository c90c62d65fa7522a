// The embedded web assets: bytes the assembler took from build/web (web_assets.S.in).
#include "unidyn/report/web_assets.hpp"

#ifdef UNIDYN_WEB_ASSETS
extern "C" const char unidyn_report_js[], unidyn_report_js_end[], unidyn_report_css[],
    unidyn_report_css_end[];
#endif

namespace unidyn {

std::optional<WebAssets> web_assets() {
#ifdef UNIDYN_WEB_ASSETS
  return WebAssets{
      {unidyn_report_js, static_cast<std::size_t>(unidyn_report_js_end - unidyn_report_js)},
      {unidyn_report_css, static_cast<std::size_t>(unidyn_report_css_end - unidyn_report_css)}};
#else
  return std::nullopt;
#endif
}

}  // namespace unidyn
