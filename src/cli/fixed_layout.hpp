// One memory layout for every run of the command, so that equal input gives byte-identical output.
//
// GiNaC orders the terms of a sum and the factors of a product by hash values seeded with the
// addresses of C++ type names inside libginac, and address-space layout randomisation moves those
// on every run. The printers are independent of that order (symbolic/canonical_text.hpp), but the
// forms GiNaC's own algorithms (normal forms, collection) return can depend on it, and the compiled
// equations inherit every rounding. The command therefore re-executes itself once with the
// randomisation of its own process turned off (personality(2) ADDR_NO_RANDOMIZE, as `setarch -R`
// does): the layout, and so every derivation and every number, is then the same from run to run.
#pragma once

namespace unidyn::cli {

// Re-executes the running command with ADDR_NO_RANDOMIZE unless it already has it (or the kernel
// refuses it, or UNIDYN_RANDOM_LAYOUT is set: then it goes on as it is). Returns only when no
// re-execution happened.
void use_fixed_layout(char** argv);

}  // namespace unidyn::cli
