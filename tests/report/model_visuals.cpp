// The bundled models draw as what they are on the report's 3-D scene (docs/model-format.md,
// `visual:`): the bicycle's wheels as disks of radius rR and rF in their planes, the rolling disk
// as a disk, the robot's arm as a rod of its length — read from the scene's JSON, against the
// models' own parameters.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "../../src/report/page_data.hpp"
#include "support/model_run.hpp"

namespace unidyn {
namespace {

// A body as the scene draws it: its shape ("" for its ellipsoid of inertia), dimensions and colour.
struct Drawn {
  std::string shape;
  std::vector<double> dimensions;
  std::string color;
};

// The text of `"key": "…"` at or after `from`.
std::string quoted_after(const std::string& json, const std::string& key, std::size_t from) {
  const std::size_t at = json.find("\"" + key + "\": \"", from) + key.size() + 5;
  return json.substr(at, json.find('"', at) - at);
}

// The scene of a bundled model with its parameters' values (no run: the shapes need none).
std::string scene_of(const System& system) {
  std::vector<double> parameters;
  for (const auto& p : system.parameters) parameters.push_back(p.value);
  const EquationsOfMotion unused;
  return scene_json(ReportModel{system, unused, parameters, "", {}, 0, "", {}, ""}, ReportRun{});
}

// A model's value of a parameter.
double parameter(const System& system, const std::string& name) {
  return system.parameters.at(system.find_parameter(name).value()).value;
}

// How the scene draws the body `name`.
Drawn drawn(const std::string& scene, const std::string& name) {
  const std::size_t body = scene.find("{\"name\": \"" + name + "\", \"semi_axes\"");
  EXPECT_NE(body, std::string::npos) << "no body " << name << " in " << scene;
  const std::size_t visual = scene.find("\"visual\": {", body);
  if (body == std::string::npos || visual == std::string::npos) return {};
  Drawn out{quoted_after(scene, "shape", visual), {}, quoted_after(scene, "color", visual)};
  const char* at = scene.c_str() + scene.find("\"dimensions\": [", visual) + 15;
  for (char* end = nullptr; *at != ']'; at = *end == ',' ? end + 1 : end) {
    out.dimensions.push_back(std::strtod(at, &end));
  }
  return out;
}

// The bicycle's wheels (axles along e2) are disks of radius rR and rF in their planes e1–e3: thin
// ellipsoids with semi-axes rR, rR/15, rR (a `disk` lies across e3); its frames keep their
// ellipsoids of inertia, coloured.
TEST(ModelVisuals, BicycleWheelsAreDisksOfTheirRadii) {
  const System bicycle = load_model(test::model_path("bicycle"));
  const std::string scene = scene_of(bicycle);
  for (const auto& [wheel, radius] : {std::pair{"R", "rR"}, std::pair{"F", "rF"}}) {
    const Drawn d = drawn(scene, wheel);
    const double r = parameter(bicycle, radius);
    EXPECT_EQ(d.shape, "ellipsoid") << wheel;
    ASSERT_EQ(d.dimensions.size(), 3u) << wheel;
    EXPECT_DOUBLE_EQ(d.dimensions[0], r) << wheel;
    EXPECT_DOUBLE_EQ(d.dimensions[1], r / 15) << wheel;
    EXPECT_DOUBLE_EQ(d.dimensions[2], r) << wheel;
  }
  EXPECT_DOUBLE_EQ(parameter(bicycle, "rR"), 0.3);
  EXPECT_DOUBLE_EQ(parameter(bicycle, "rF"), 0.35);
  for (const char* frame : {"B", "H"}) {
    const Drawn d = drawn(scene, frame);
    EXPECT_EQ(d.shape, "") << frame;
    EXPECT_FALSE(d.color.empty()) << frame;
  }
}

// A bundled model's body drawn as one shape whose one dimension is the parameter given.
void expect_drawn_as(const std::string& model, const std::string& body, const std::string& shape,
                     const std::string& dimension) {
  const System system = load_model(test::model_path(model));
  const Drawn d = drawn(scene_of(system), body);
  EXPECT_EQ(d.shape, shape) << model;
  ASSERT_EQ(d.dimensions.size(), 1u) << model;
  EXPECT_DOUBLE_EQ(d.dimensions[0], parameter(system, dimension)) << model;
}

// The rolling disk, its inertia a disk of radius R, is drawn as that disk.
TEST(ModelVisuals, RollingDiskIsItsDisk) {
  expect_drawn_as("rolling-disk", "disk", "disk", "R");
}

// The robot's arm is a rod of its length L along e3 (its end P is L/2 below its centre).
TEST(ModelVisuals, RobotArmIsARodOfItsLength) {
  expect_drawn_as("robot-arm", "arm", "rod", "L");
}

}  // namespace
}  // namespace unidyn
