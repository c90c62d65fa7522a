// Angles robot files write as rounded multiples of π are read as the exact multiple only when
// typed to 13 digits or more (include/unidyn/formats/exact_angles.hpp).
#include "unidyn/formats/exact_angles.hpp"

#include <string>

#include <cmath>

#include <gtest/gtest.h>

#include "unidyn/formats/urdf.hpp"

namespace unidyn::formats {
namespace {

TEST(ExactAngles, RoundedMultiplesOfAQuarterPiAreTheMultiple) {
  EXPECT_EQ(exact_quarter_pi_multiple(1.5707963267948966), "pi/2");
  EXPECT_EQ(exact_quarter_pi_multiple(-1.5707963267949), "-pi/2");
  EXPECT_EQ(exact_quarter_pi_multiple(3.141592653589793), "pi");
  EXPECT_EQ(exact_quarter_pi_multiple(-3.14159265358979), "-pi");
  EXPECT_EQ(exact_quarter_pi_multiple(0.7853981633974483), "pi/4");
  EXPECT_EQ(exact_quarter_pi_multiple(4.71238898038469), "3*pi/2");
  EXPECT_EQ(exact_quarter_pi_multiple(-2.356194490192345), "-3*pi/4");
  EXPECT_EQ(exact_quarter_pi_multiple(6.283185307179586), "2*pi");
  EXPECT_EQ(exact_quarter_pi_multiple(0.0), "0");
  EXPECT_EQ(exact_quarter_pi_multiple(-0.0), "0");
}

// 1.5708 is 3.7e-6 from π/2: another angle, kept as typed; so are 0.3 and what is not a number.
TEST(ExactAngles, OtherAnglesAreNot) {
  EXPECT_FALSE(exact_quarter_pi_multiple(1.5708));
  EXPECT_FALSE(exact_quarter_pi_multiple(1.570796325));
  EXPECT_FALSE(exact_quarter_pi_multiple(3.1416));
  EXPECT_FALSE(exact_quarter_pi_multiple(0.3));
  EXPECT_FALSE(exact_quarter_pi_multiple(1e-9));
  EXPECT_FALSE(exact_quarter_pi_multiple(NAN));
  EXPECT_FALSE(exact_quarter_pi_multiple(INFINITY));
  EXPECT_FALSE(exact_quarter_pi_multiple(1e300));
}

// The importer writes a joint's rounded rpy as the multiple, and says so where the URDF has it;
// 1.5708 stays as typed.
TEST(ExactAngles, TheImporterWritesTheMultipleWithANote) {
  const std::string urdf = R"(<robot name="r">
  <link name="a"/>
  <link name="b"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  <link name="c"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  <joint name="j" type="revolute"><parent link="a"/><child link="b"/>
    <origin xyz="0 0 1" rpy="1.5707963267948966 0 -3.141592653589793"/></joint>
  <joint name="k" type="revolute"><parent link="b"/><child link="c"/>
    <origin rpy="1.5708 0 0"/></joint>
</robot>
)";
  const ImportedModel model = import_urdf(urdf, "r.urdf");
  EXPECT_NE(model.yaml.find("rpy: [pi/2, 0, -pi], revolute: j"), std::string::npos) << model.yaml;
  EXPECT_NE(model.yaml.find("rpy: [1.5708, 0, 0], revolute: k"), std::string::npos) << model.yaml;
  bool noted = false;
  for (const std::string& note : model.notes) {
    noted = noted || note.starts_with(
                         "r.urdf:6:30: rpy read 1.5707963267948966 as pi/2, "
                         "-3.141592653589793 as -pi");
  }
  EXPECT_TRUE(noted) << model.notes.front();
}

}  // namespace
}  // namespace unidyn::formats
