// Re-executing the command with address-space layout randomisation off (cli/fixed_layout.hpp).
#include "fixed_layout.hpp"

#include <sys/personality.h>
#include <unistd.h>

#include <cstdlib>

namespace unidyn::cli {

void use_fixed_layout(char** argv) {
  if (std::getenv("UNIDYN_RANDOM_LAYOUT") != nullptr) return;
  // the current persona, unchanged (0xffffffff only queries it)
  const int persona = personality(0xffffffff);
  if (persona == -1 || (persona & ADDR_NO_RANDOMIZE) != 0) return;
  if (personality(static_cast<unsigned long>(persona) | ADDR_NO_RANDOMIZE) == -1) return;
  // the same program, arguments and environment; on failure go on in the current layout
  execv("/proc/self/exe", argv);
  personality(static_cast<unsigned long>(persona));
}

}  // namespace unidyn::cli
