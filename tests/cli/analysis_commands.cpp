// `unidyn linearize` and `unidyn modes` as a user runs them: the same output on every run, bad
// input refused with exit status 2, a sweep's CSV and its boundaries.
#include <algorithm>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"

namespace unidyn::cli_test {
namespace {

const std::string kBicycleAt = " --at 'der(thR)=v/rR' 'der(phi)=0' 'der(delta)=0' 'der(psi)=0'";

TEST(AnalysisCommands, SameOutputOnEveryRun) {
#ifdef UNIDYN_SANITIZED
  // the same bytes on every run is the plain build's to check (44 s here): the sanitizers see
  // each of these commands once in the other tests
  GTEST_SKIP() << "checked in the plain build";
#endif
  for (const std::string& command : std::vector<std::string>{
           "linearize double-pendulum --at theta1=0 theta2=0", "modes bicycle" + kBicycleAt,
           "modes spring-chain --at x1=0 x2=0 --format json",
           "linearize torque-free-body --at 'der(psi)=5' --format json", "equilibria rotating-hoop",
           "equilibria double-pendulum --format json",
           "equilibria smooth-cone --cyclic theta --at 'p(theta)=h' --format json",
           "linearize rolling-disk --at 'theta=pi/2' 'der(phi)=10' --format json",
           "modes driven-pendulum --at phi=0 --format json",
           "modes driven-pendulum --at phi=0 --format latex"}) {
    const Outcome first = run(command);
    ASSERT_EQ(first.status, 0) << command << ": " << first.err;
    const Outcome again = run(command, "UNIDYN_RANDOM_LAYOUT=1");
    EXPECT_EQ(again.out, first.out) << command;
  }
  const Outcome modes = run("modes bicycle" + kBicycleAt);
  EXPECT_TRUE(contains(modes.out, "ignorable, dropped: x, y, psi, thR, thF")) << modes.out;
  EXPECT_TRUE(contains(modes.out, "stability: linearly stable")) << modes.out;
  const Outcome hoop = run("equilibria rotating-hoop");
  EXPECT_TRUE(hoop.out.starts_with("4 equilibria of Bead on a rotating hoop")) << hoop.out;
}

TEST(AnalysisCommands, BadInputRefused) {
  for (const std::string command :
       {"modes double-pendulum --at theta1=0.3", "modes double-pendulum --at nope=1",
        "modes double-pendulum --at theta1=0 --set theta2=1",
        "modes double-pendulum --at theta1=0 --sweep g=1:2", "linearize heavy-top --at theta=0",
        "modes double-pendulum --at theta1=0 --sweep g=1:2:3 --format json",
        "equilibria double-pendulum --starts 0", "equilibria double-pendulum --at theta1=x",
        "equilibria smooth-cone --at 'p(theta)=5'", "equilibria smooth-cone --cyclic nope",
        "equilibria smooth-cone --cyclic theta --at 'p(theta)=5' 'der(theta)=1'",
        "linearize smooth-cone --at 'p(theta)=5'", "equilibria block-incline",
        "linearize particle-leaving-sphere --at z=-1", "equilibria driven-pendulum",
        "modes double-pendulum --at theta1=0 theta2=0 --period 0",
        "modes driven-pendulum --at phi=0 --period 0.01", "modes switching-constraint --at x=0",
        "modes driven-pendulum --at phi=0 --sweep Omega=100:200:3 --period -1"}) {
    const Outcome r = run(command);
    EXPECT_EQ(r.status, 2) << command << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "unidyn: error:")) << command << ": " << r.err;
    EXPECT_EQ(r.out, "") << command;
  }
}

// Without --at the operating point is the model's initial state, said so; refused with the reason
// when it is not one. The hoop's bead starts at phi0: at the top (0) it is an equilibrium, where
// λ² = Ω² + g/R0.
TEST(AnalysisCommands, WithoutAtTheInitialState) {
  const Outcome top = run("modes rotating-hoop --set phi0=0");
  ASSERT_EQ(top.status, 0) << top.err;
  EXPECT_TRUE(contains(top.out, "from the model's initial state (no --at given)")) << top.out;
  EXPECT_TRUE(contains(top.out, "given: phi = 0")) << top.out;
  EXPECT_TRUE(contains(top.out, "stability: unstable")) << top.out;
  const Outcome json = run("linearize rotating-hoop --set phi0=0 --format json");
  EXPECT_TRUE(contains(json.out, "\"source\": \"the model's initial state (no --at given)\""))
      << json.out;
  const Outcome moving = run("modes rotating-hoop");
  EXPECT_EQ(moving.status, 2);
  EXPECT_TRUE(contains(moving.err,
                       "no --at given, and the model's initial state is not an "
                       "operating point: the acceleration of phi"))
      << moving.err;
}

// A pendulum on a vibrating pivot (issue 34's case, Kapitza): at 0.8 of the boundary the inverted
// position falls (Floquet: a multiplier outside the unit circle), above it it stands, and the sweep
// finds the boundary at sqrt(4g/(l |a0(2a/l)|)) = 198.199059109 (a0 of the Mathieu equation:
// tests/analysis/floquet.cpp checks it against Hill's determinant).
TEST(AnalysisCommands, DrivenPendulumByFloquet) {
  const Outcome falls = run("modes driven-pendulum --at phi=0 --set Omega=158");
  ASSERT_EQ(falls.status, 0) << falls.err;
  EXPECT_TRUE(contains(falls.out, "the equations depend on t periodically, T = 0.0397669956151 s"))
      << falls.out;
  EXPECT_TRUE(contains(falls.out, "monodromy matrix Phi")) << falls.out;
  EXPECT_TRUE(contains(falls.out, "stability: unstable: multipliers outside the unit circle"))
      << falls.out;
  const Outcome stands = run("modes driven-pendulum --at phi=0 --set Omega=250");
  EXPECT_TRUE(contains(stands.out, "stability: linearly stable")) << stands.out;
  const Outcome linear = run("linearize driven-pendulum --at phi=0");
  ASSERT_EQ(linear.status, 0) << linear.err;
  EXPECT_TRUE(contains(linear.out, "x' = A(t) x, A(t + T) = A(t)")) << linear.out;
  EXPECT_FALSE(contains(linear.out, "multipliers")) << linear.out;
  const Outcome sweep = run("modes driven-pendulum --at phi=0 --sweep Omega=150:260:12");
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  EXPECT_TRUE(contains(sweep.err, "stability changes at Omega = 198.1990591")) << sweep.err;
  EXPECT_TRUE(sweep.out.starts_with("Omega,period,largest_modulus,growth,re(mu1),im(mu1)"))
      << sweep.out;
  const Outcome frozen = run("equilibria driven-pendulum");
  EXPECT_TRUE(contains(frozen.err, "depend on t")) << frozen.err;
}

// Fig. 2.9: the circular orbit on the smooth cone at the momentum h, with its rate, stable by
// Routh.
TEST(AnalysisCommands, SteadyMotionsAtAMomentum) {
  const Outcome r = run("equilibria smooth-cone --cyclic theta --at 'p(theta)=h'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(
      r.out.starts_with("2 steady motions of Particle on a smooth cone with a spring "
                        "(cyclic: theta;"))
      << r.out;
  EXPECT_TRUE(contains(r.out, "R = 1.62526688286, theta = any (cyclic)")) << r.out;
  EXPECT_TRUE(contains(r.out, "a strict minimum: stable at these momenta (Routh)")) << r.out;
}

// A continuum of equilibria (the knife-edge car at rest, any heading) is counted apart from the
// isolated ones, and only its first points listed.
TEST(AnalysisCommands, ContinuaCountedNotListedInFull) {
  const Outcome r = run("equilibria chaplygin-car --starts 20");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.starts_with("0 isolated equilibria and 20 points of continua of equilibria"))
      << r.out;
  EXPECT_TRUE(contains(r.out, "not listed: 17 more points of continua")) << r.out;
  EXPECT_FALSE(contains(r.out, "  4. ")) << r.out;
}

TEST(AnalysisCommands, SweepWritesRowsAndBoundaries) {
  const Outcome r = run("modes bicycle" + kBicycleAt + " --sweep v=0:10:21");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.starts_with("v,growth,re1,im1,")) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 22);
  // the two boundaries, as printed (15 digits), against Table 2 of Meijaard et al. (2007)
  std::vector<double> speeds;
  for (std::size_t at = r.err.find("changes at v = "); at != std::string::npos;
       at = r.err.find("changes at v = ", at + 1)) {
    speeds.push_back(std::stod(r.err.substr(at + 15)));
  }
  ASSERT_EQ(speeds.size(), 2u) << r.err;
  EXPECT_NEAR(speeds[0], 4.29238253634111, 1e-10);
  EXPECT_NEAR(speeds[1], 6.02426201538837, 1e-10);
}

}  // namespace
}  // namespace unidyn::cli_test
