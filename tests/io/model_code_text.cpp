// The part of a model file that determines its compiled code (the native-code cache's key): the
// same for files that differ in comments, layout, name, initial values or simulate settings;
// different for any change of what is compiled.
#include <gtest/gtest.h>

#include <string>

#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

const std::string kBody =
    "coordinates: [phi]\nparticles:\n  P: {mass: m, position: \"L*[sin(phi), 0, -cos(phi)]\"}\n"
    "forces:\n  - gravity: -g*E3\noutputs:\n  z: dot(P.position, E3)\n";

std::string key(const std::string& text) {
  return model_code_text(text, "code.yaml");
}

TEST(ModelCodeText, IgnoresWhatDoesNotChangeTheCode) {
  const std::string a = "unidyn: 1\nname: A\nparameters: {m: 1, g: 9.81, L: 1}\n" + kBody +
                        "initial: {phi: 0.1}\nsimulate: {t_end: 5}\n";
  const std::string b =
      "# a comment\nunidyn: 1\nname: \"Another name\"\nreference: book\n"
      "parameters:\n  m: 1\n  g: 9.81   # gravity\n  L: 1\n" +
      kBody + "initial: {phi: 2, der(phi): 1}\nsimulate: {t_end: 50, rtol: 1e-8}\n";
  EXPECT_EQ(key(a), key(b));
}

TEST(ModelCodeText, ChangesWithWhatIsCompiled) {
  const std::string base = "unidyn: 1\nparameters: {m: 1, g: 9.81, L: 1}\n" + kBody;
  const std::string k = key(base);
  EXPECT_NE(key(base + "conserved:\n  x: dot(P.position, E1)\n"), k);
  EXPECT_NE(key(base + "simulate: {stop_when: [phi]}\n"), k);
  EXPECT_NE(key("unidyn: 1\nparameters: {m: 2, g: 9.81, L: 1}\n" + kBody), k);
  std::string other = base;
  other.replace(other.find("-g*E3"), 5, "-g*E2");
  EXPECT_NE(key(other), k);
}

}  // namespace
}  // namespace unidyn
