// What `unidyn derive MODEL [--method M]` prints, from a C++ program through the commands layer
// (unidyn/commands/): the same function the command calls, so the same bytes.
//
//   embed-derive MODEL [METHOD]   the model's equations of motion in the book's form
#include <cstdio>
#include <exception>
#include <iostream>

#include "unidyn/commands/model_commands.hpp"
#include "unidyn/commands/model_source.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: embed-derive MODEL [METHOD]\n");
    return 2;
  }
  try {
    // a model file or a bundled model's name, read once
    const unidyn::commands::LoadedModel model = unidyn::commands::load_named_model(argv[1]);
    // derive's options: Lagrange's equations as text in the book's form unless told otherwise
    unidyn::commands::ModelOptions options;
    if (argc > 2) options.method = argv[2];
    unidyn::commands::write_derivation(std::cout, options, model);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "embed-derive: %s\n", e.what());
    return 2;
  }
}
