// The parts of an import shared by its files and by the URDF and MJCF importers: what was ignored,
// numbers as YAML text, the model's YAML, and (URDF) the lines of a link's body.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "xml_source.hpp"

namespace unidyn::formats {

// Elements unidyn does not read, one note per kind of element at its first occurrence.
class Ignored {
 public:
  // `why` ends the note ("ignored", "not applied: ...").
  void add(const XmlSource& source, const tinyxml2::XMLElement& element, const std::string& why);
  std::vector<std::string> notes() const;

 private:
  struct Kind {
    SourcePosition first;
    std::string why;
    int count = 0;
  };
  std::map<std::string, Kind> kinds_;
  std::vector<std::string> order_;  // the kinds in the order first met
};

// Every child element of `element` whose name is not in `known` is ignored.
void ignore_others(const XmlSource& source, const tinyxml2::XMLElement& element,
                   std::initializer_list<const char*> known, Ignored& ignored);

// "[a, b, c]" of the numbers as typed.
std::string vector_text(const std::vector<Number>& numbers);

// The number with 17 significant digits (it reads back as the same double).
std::string exact_text(double x);

// "{tensor: [[J11, J12, J13], [J21, J22, J23], [J31, J32, J33]]}" of the components' texts.
std::string tensor_text(const std::vector<std::vector<std::string>>& rows);

// A YAML double-quoted string of printable text.
std::string quoted(const std::string& text);

// "a, b, c"
std::string joined(const std::vector<std::string>& items);

// A tensor a body can have (as the model reader checks it): positive semi-definite and each
// principal moment at most the sum of the other two (7.18′); else refused at `element`.
void expect_realisable(const XmlSource& source, const tinyxml2::XMLElement& element,
                       const Eigen::Matrix3d& J);

// What an imported model is written from: the bodies' lines, the coordinates, the forces after
// gravity (dampers), the constraints' lines, the initial values.
struct Written {
  std::vector<std::string> bodies;
  std::vector<std::string> coordinates;
  std::vector<std::string> dampers;
  std::vector<std::string> constraints;
  std::vector<std::string> initial;
};

class Names;

// A joint's position limits as two unilateral contacts (--limits), named after its coordinate Q:
// Q_lower, Q − (lower) ≥ 0, and Q_upper, (upper) − Q ≥ 0, each holding while it pushes and
// stopping the joint without rebound (restitution 0); `lower` and `upper` are the model's texts.
void write_limits(const std::string& coordinate, const std::string& lower, const std::string& upper,
                  const SourcePosition& where, Names& names, std::vector<std::string>& notes,
                  Written& written);

// A joint's damper as a force line: a slide damper in a sliding joint, else a torsion damper.
std::string damper_line(bool slides, const std::string& coordinate, const std::string& coefficient);

// The model's header and gravity: `format` ("URDF", "MJCF"), `parameters` ("{g: 9.81}") and the
// gravity force's line ("  - gravity: -g*E3", or "" for none).
struct ModelHeader {
  std::string name;
  std::string file;
  std::string format;
  std::string parameters;
  std::string gravity;
};

// The model's YAML: header, parameters, coordinates, bodies, forces, initial state, run.
std::string model_yaml(const ModelHeader& header, const Written& written);

// A file's text, read in blocks and refused past `max_bytes` (/dev/zero, a log file named by
// mistake): `what` names it in the messages ("URDF file").
std::string read_bounded_file(const std::string& path, std::size_t max_bytes,
                              const std::string& what);

// What a link's body is written from.
struct LinkContext {
  const XmlSource& source;
  std::vector<std::string>& notes;
  Ignored& ignored;
  const std::map<std::string, const tinyxml2::XMLElement*>& materials;  // <robot>'s, by name
  bool limits = false;  // --limits: joint limits as unilateral contacts
};

// The body lines of a link after its `joint:` (indented under the body `name`): mass, inertia
// and centre from <inertial> (mass: 0 without one: a frame), and visual from <visual>.
std::vector<std::string> link_body_lines(const LinkContext& context,
                                         const tinyxml2::XMLElement& link, const std::string& name);

}  // namespace unidyn::formats
