// libFuzzer target: the URDF and MJCF importers (tinyxml2, strict numbers, the tree, the YAML they
// write) on arbitrary bytes. A model error (with its position) is the expected way to refuse
// input; anything else that escapes — another exception, a crash, a sanitizer report, a hang — is
// a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "unidyn/formats/mjcf.hpp"
#include "unidyn/formats/urdf.hpp"
#include "unidyn/symbolic/expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // as read by default and with --limits (joint limits as contacts)
  for (const bool limits : {false, true}) {
    const unidyn::formats::ImportOptions options{limits};
    try {
      (void)unidyn::formats::import_urdf(text, "fuzz.urdf", options);
    } catch (const unidyn::ModelError&) {
      // refused with file:line:column
    }
    try {
      (void)unidyn::formats::import_mjcf(text, "fuzz.xml", options);
    } catch (const unidyn::ModelError&) {
    }
  }
  return 0;
}
