// Checks of a model with its parameters' values, at load: positive masses, inertia tensors a body
// can have (positive semi-definite, the triangle inequalities (7.18′), a lamina on the boundary),
// no rotation about an axis of zero inertia (the planar ladder whose rod lies along its axis of
// rotation), no coordinate that moves nothing. Each refusal names its position.
#include <gtest/gtest.h>

#include <string>

#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// The position and message of the error `text` gives, or a failure.
std::pair<SourcePosition, std::string> error_of(const std::string& text) {
  try {
    (void)parse_model(text, "checks.yaml");
  } catch (const ModelError& e) {
    return {e.where(), e.what()};
  }
  ADD_FAILURE() << "no error for\n" << text;
  return {};
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::string particle_model(const std::string& mass) {
  return "unidyn: 1\nparameters: {m: -2}\ncoordinates: [x]\nparticles:\n  P: {mass: " + mass +
         ", position: [x, 0, 0]}\n";
}

TEST(ModelChecks, MassesArePositive) {
  for (const std::string mass : {"0", "-1", "m", "m + 1"}) {
    const auto [where, message] = error_of(particle_model(mass));
    EXPECT_EQ(where.line, 5) << message;
    EXPECT_EQ(where.column, 13) << message;
    EXPECT_TRUE(contains(message, "a mass must be positive")) << message;
  }
  EXPECT_NO_THROW((void)parse_model(particle_model("m + 3"), "checks.yaml"));
}

std::string body_model(const std::string& inertia, const std::string& rotation) {
  return "unidyn: 1\nparameters: {L: 2}\ncoordinates: [x, theta]\nbodies:\n  B:\n    mass: 1\n"
         "    inertia: " +
         inertia + "\n    rotation: " + rotation + "\n    center: [x, 0, 0]\n";
}

TEST(ModelChecks, InertiaABodyCanHave) {
  const std::string turn = "{axis: [1, 0, 0], angle: theta}";
  // (7.18′): 3 > 1 + 1
  const auto [where, message] = error_of(body_model("[1, 1, 3]", turn));
  EXPECT_EQ(where.line, 7) << message;
  EXPECT_TRUE(contains(message, "(7.18')")) << message;
  // not positive semi-definite
  EXPECT_TRUE(
      contains(error_of(body_model("{tensor: [[1, 0, 0], [0, 1, 0], [0, 0, -1]]}", turn)).second,
               "positive semi-definite"));
  // a lamina (C = A + B) and a thin disk are on the boundary, allowed
  EXPECT_NO_THROW((void)parse_model(body_model("[1, 1, 2]", turn), "checks.yaml"));
  EXPECT_NO_THROW((void)parse_model(body_model("{disk: {radius: L}}", turn), "checks.yaml"));
}

// The ladder: a rod lies along e3; turned about E3 = e3 its rotation has no inertia. Turned first
// so that it lies along E1, the same rotation is about an axis across the rod.
TEST(ModelChecks, NoRotationAboutAnAxisOfZeroInertia) {
  const std::string rod = "{rod: {length: L}}";
  const auto [where, message] = error_of(body_model(rod, "{axis: [0, 0, 1], angle: theta}"));
  EXPECT_EQ(where.line, 8) << message;
  EXPECT_TRUE(contains(message, "body 'B' turns about its axis")) << message;
  EXPECT_TRUE(contains(message, "inertia is zero")) << message;
  EXPECT_NO_THROW((void)parse_model(
      body_model(rod, "[{axis: [0, 0, 1], angle: theta}, {axis: [0, 1, 0], angle: pi/2}]"),
      "checks.yaml"));
}

TEST(ModelChecks, EveryCoordinateMovesSomething) {
  const auto [where, message] = error_of(
      "unidyn: 1\ncoordinates: [x, y, z]\nparticles:\n  P: {mass: 1, position: [x, 0, "
      "z]}\n");
  EXPECT_EQ(where.line, 2) << message;
  EXPECT_EQ(where.column, 18) << message;
  EXPECT_TRUE(contains(message, "coordinate 'y' moves nothing")) << message;
}

}  // namespace
}  // namespace unidyn
