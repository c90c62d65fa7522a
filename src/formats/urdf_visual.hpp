// A link's <visual> as a body's `visual:` (how `unidyn report` draws it).
#pragma once

#include <string>
#include <vector>

#include "urdf_parts.hpp"

namespace unidyn::formats {

// The `visual:` line of a body whose centre of mass is `center` (on the link frame): its first
// <visual> that is a box, cylinder or sphere centred there without rotation, with its colour;
// every other <visual> a note (the body is drawn as its ellipsoid of inertia without one).
std::vector<std::string> visual_lines(const LinkContext& context, const tinyxml2::XMLElement& link,
                                      const std::vector<Number>& center);

// A frame (a link of mass 0) is not drawn: a note for each of its <visual> elements.
void frame_visuals(const LinkContext& context, const tinyxml2::XMLElement& link);

}  // namespace unidyn::formats
