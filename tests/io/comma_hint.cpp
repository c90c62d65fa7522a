// A YAML flow collection splits an unquoted expression at its commas: the errors that follow (an
// unclosed call, an unknown key made of the rest, a vector of four components) say so.
#include <gtest/gtest.h>

#include <string>

#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

const std::string kModel =
    "unidyn: 1\ncoordinates: [x]\nparticles:\n  P: {mass: 1, position: [x, 0, 0]}\n";

std::string error_of(const std::string& text) {
  try {
    (void)parse_model(text, "commas.yaml");
  } catch (const ModelError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for\n" << text;
  return "";
}

TEST(CommaHint, SplitExpressionsAreNamed) {
  const std::string hint = "quote an expression that contains one";
  // {height: dot(P.position, E3)}: the value "dot(P.position" does not close
  const std::string output = error_of(kModel + "outputs: {height: dot(P.position, E3)}\n");
  EXPECT_NE(output.find("commas.yaml:5:"), std::string::npos) << output;
  EXPECT_NE(output.find(hint), std::string::npos) << output;
  // [atan2(x, 1), 0, 0]: four components
  const std::string vector = error_of(
      "unidyn: 1\ncoordinates: [x]\nparticles:\n  P: {mass: 1, position: [atan2(x, 1), 0, 0]}\n");
  EXPECT_NE(vector.find("three components"), std::string::npos) << vector;
  EXPECT_NE(vector.find(hint), std::string::npos) << vector;
  // the rest of a split value becomes a key
  const std::string key =
      error_of(kModel + "forces:\n  - spring: {from: P, to: [0, 0, 0], energy: atan2(s, 1)}\n");
  EXPECT_NE(key.find("unknown key '1)'"), std::string::npos) << key;
  EXPECT_NE(key.find(hint), std::string::npos) << key;
  // an ordinary mistake gets no such hint
  const std::string plain = error_of(kModel + "outputs: {height: dot(P.position E3)}\n");
  EXPECT_EQ(plain.find(hint), std::string::npos) << plain;
}

}  // namespace
}  // namespace unidyn
