// libFuzzer target: the model-file reader (YAML, the expression parser, every section's checks)
// on arbitrary bytes. A model error (with its position) is the expected way to refuse input;
// anything else that escapes — another exception, a crash, a sanitizer report, a hang — is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "unidyn/io/model_file.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)unidyn::parse_model(text, "fuzz.yaml");
  } catch (const unidyn::ModelError&) {
    // refused with file:line:column
  }
  return 0;
}
