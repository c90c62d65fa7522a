// The planes and spheres of the position constraints (report/constraint_surfaces.hpp), against
// the surfaces the constraints were written for: closed forms typed here, not fitted.
#include "unidyn/report/constraint_surfaces.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

using Kind = ConstraintSurface::Kind;

std::vector<ConstraintSurface> surfaces_of(
    const System& system, const std::vector<std::pair<std::string, double>>& set = {}) {
  return constraint_surfaces(system, initial_state(system, set).parameters);
}

// A particle free in space (x, y, z), or a second one moving in the plane y = 5 (x, z), held by
// the constraints given.
System free_particles(const std::string& constraints) {
  return parse_model(
      "unidyn: 1\nname: surfaces\nparameters: {m: 1, a: 0.5}\ncoordinates: [x, y, z, u, w]\n"
      "particles:\n  P: {mass: m, position: [x, y, z]}\n  Q: {mass: m, position: [u, 5, w]}\n"
      "constraints:\n" +
          constraints,
      "surfaces.yaml");
}

TEST(ConstraintSurfaces, PlaneAtItsDistanceFromTheOrigin) {
  // x + 2y − 3 = 0: n = (1, 2, 0)/√5, n · r = 3/√5
  const auto found = surfaces_of(free_particles("  - {name: wall, position: x + 2*y - 3}\n"));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].constraint, "wall");
  EXPECT_EQ(found[0].point, "P");
  EXPECT_EQ(found[0].kind, Kind::plane);
  EXPECT_NEAR((found[0].normal - Eigen::Vector3d(1, 2, 0) / std::sqrt(5.0)).norm(), 0, 1e-12);
  EXPECT_NEAR(found[0].offset, 3 / std::sqrt(5.0), 1e-12);
  // written the other way round, −x − 2y + 3: the same plane, the same normal
  const auto flipped = surfaces_of(free_particles("  - {name: wall, position: 3 - x - 2*y}\n"));
  ASSERT_EQ(flipped.size(), 1u);
  EXPECT_NEAR((flipped[0].normal - found[0].normal).norm(), 0, 1e-12);
  EXPECT_NEAR(flipped[0].offset, found[0].offset, 1e-12);
}

TEST(ConstraintSurfaces, SphereOffTheOriginWithItsParameter) {
  // (x − 1)² + y² + (z − 2)² = a², scaled by 3
  const System system =
      free_particles("  - {name: ball, position: 3*((x - 1)^2 + y^2 + (z - 2)^2 - a^2)}\n");
  for (const double a : {0.5, 2.0}) {
    const auto found = surfaces_of(system, {{"a", a}});
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].kind, Kind::sphere);
    EXPECT_NEAR((found[0].center - Eigen::Vector3d(1, 0, 2)).norm(), 0, 1e-10);
    EXPECT_NEAR(found[0].radius, a, 1e-10);
  }
}

TEST(ConstraintSurfaces, APlanarModelsTableStandsAcrossItsPlane) {
  // Q moves in y = 5: its table w = 1 is the plane z = 1 (its normal in Q's plane)
  const auto found = surfaces_of(free_particles("  - {name: table, position: w - 1}\n"));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].point, "Q");
  EXPECT_NEAR((found[0].normal - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-12);
  EXPECT_NEAR(found[0].offset, 1.0, 1e-12);
  // a circle in Q's plane is not a sphere, and not drawn as one
  EXPECT_TRUE(surfaces_of(free_particles("  - {name: ring, position: u^2 + w^2 - 1}\n")).empty());
}

TEST(ConstraintSurfaces, OtherSurfacesAndConstraintsAreNotDrawn) {
  // a cylinder, a paraboloid, two particles' distance, a plane moving with time
  for (const char* constraint :
       {"  - {name: c, position: x^2 + y^2 - 1}\n", "  - {name: c, position: z - x^2 - y^2}\n",
        "  - {name: c, position: (x - u)^2 + (z - w)^2 - 1}\n",
        "  - {name: c, position: z - 0.1*t}\n"}) {
    EXPECT_TRUE(surfaces_of(free_particles(constraint)).empty()) << constraint;
  }
}

TEST(ConstraintSurfaces, BundledModels) {
  // the sphere the particle leaves, of radius R0; the Cartesian pendulum's, of radius L
  const System leaving = load_model(test::model_path("particle-leaving-sphere"));
  const auto sphere = surfaces_of(leaving, {{"R0", 1.7}});
  ASSERT_EQ(sphere.size(), 1u);
  EXPECT_EQ(sphere[0].kind, Kind::sphere);
  EXPECT_NEAR(sphere[0].radius, 1.7, 1e-10);
  EXPECT_NEAR(sphere[0].center.norm(), 0, 1e-10);
  const auto rod =
      surfaces_of(load_model(test::model_path("spherical-pendulum-cartesian")), {{"L", 2.5}});
  ASSERT_EQ(rod.size(), 1u);
  EXPECT_NEAR(rod[0].radius, 2.5, 1e-10);
  // the bouncing ball's table z = 0 (a planar model), under the ball the point of contact of the
  // sphere sliding and rolling (its centre is at z = R, its contact on the table)
  for (const char* model : {"bouncing-ball", "sphere-slide-roll"}) {
    const auto table = surfaces_of(load_model(test::model_path(model)));
    ASSERT_EQ(table.size(), 1u) << model;
    EXPECT_EQ(table[0].kind, Kind::plane);
    EXPECT_NEAR((table[0].normal - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-12) << model;
    EXPECT_NEAR(table[0].offset, 0, 1e-12) << model;
  }
  // the roller coaster's flat z = 0, not its track y = A cos(π x/L0)
  const auto coaster = surfaces_of(load_model(test::model_path("roller-coaster")));
  ASSERT_EQ(coaster.size(), 1u);
  EXPECT_EQ(coaster[0].constraint, "flat");
}

}  // namespace
}  // namespace unidyn
