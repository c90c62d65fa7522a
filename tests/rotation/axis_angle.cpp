#include "unidyn/rotation/axis_angle.hpp"

#include "support/oracles.hpp"

namespace unidyn {
namespace {

TEST(AxisAngle, Smoke) {
  const Tensor Q = rotation_tensor(AxisAngle{basis_vector(3), test::kPi / 2});
  EXPECT_NEAR(Q(1, 0), 1.0, 1e-15);
}

}  // namespace
}  // namespace unidyn
