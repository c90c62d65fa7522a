// `unidyn import`: a URDF or MJCF file as the model language's YAML.
#include "unidyn/commands/import_command.hpp"

#include <stdexcept>

#include "unidyn/commands/model_source.hpp"
#include "unidyn/formats/mjcf.hpp"
#include "unidyn/formats/urdf.hpp"
#include "unidyn/io/atomic_file.hpp"
#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn::commands {

void write_import(const std::string& file, const formats::ImportOptions& options,
                  const std::string& output, std::ostream& out, std::ostream& notes) {
  if (!is_imported(file)) {
    throw std::invalid_argument("'" + file +
                                "': unidyn imports URDF files (*.urdf) and MJCF files (*.xml "
                                "whose root element is <mujoco>)");
  }
  if (!output.empty()) expect_writable(output);
  const formats::ImportedModel model = import_robot_file(file, options);
  for (const auto& note : model.notes) notes << printable(note) << '\n';
  if (output.empty()) {
    out << model.yaml;
  } else {
    write_atomically(output, model.yaml);
  }
}

}  // namespace unidyn::commands
