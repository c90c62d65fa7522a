// Outputs and conserved quantities that are vectors: three CSV columns name.x, name.y, name.z,
// the components on E1, E2, E3, each a column name of its own.
#include <gtest/gtest.h>

#include <string>

#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

const std::string kModel =
    "unidyn: 1\ncoordinates: [x]\nparticles:\n  P: {mass: 2, position: [x, 3, 0]}\n";

TEST(VectorOutputs, ThreeColumnsEach) {
  const System s = parse_model(kModel +
                                   "outputs:\n  r: P.position\n  v: [der(x), 0, 1]\n  d: x\n"
                                   "conserved:\n  p: P.momentum\n",
                               "vectors.yaml");
  ASSERT_EQ(s.outputs.size(), 7u);
  const char* names[] = {"r.x", "r.y", "r.z", "v.x", "v.y", "v.z", "d"};
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(s.outputs[i].name, names[i]);
  const Expr& x = s.coordinates()[0].value;
  const Expr& xdot = s.coordinates()[0].rate;
  EXPECT_TRUE((s.outputs[0].expression - x).is_zero());
  EXPECT_TRUE((s.outputs[1].expression - 3).is_zero());
  EXPECT_TRUE((s.outputs[3].expression - xdot).is_zero());
  ASSERT_EQ(s.conserved.size(), 3u);
  EXPECT_EQ(s.conserved[0].name, "p.x");
  EXPECT_TRUE((s.conserved[0].expression - 2 * xdot).is_zero());
}

TEST(VectorOutputs, ComponentNamesAreColumns) {
  try {
    (void)parse_model(kModel + "outputs:\n  r: P.position\n  r.y: x\n", "vectors.yaml");
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().line, 7);
    EXPECT_NE(std::string(e.what()).find("'r.y' is already the name of a CSV column"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace unidyn
