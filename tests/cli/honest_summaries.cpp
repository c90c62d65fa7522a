// Summaries that say what happened and checks that fail when they should: `check` fails on an
// initial state off its constraints or with a singular mass matrix; `simulate` says why the
// energy of a driven or dissipative model changes (the figures from the CSV's own energy column),
// gives each multiplier's range (from the CSV's lambda column), prints no figures for rows it did
// not compute, takes stop_when under simulate:, and writes a row at each event.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "cli_support.hpp"

namespace unidyn {
namespace {

using namespace cli_test;

// A rod of length L in the plane, started at x = X.
std::string rod_model(const std::string& x) {
  const std::string path = temp_path("rod.yaml");
  write_file(path,
             "unidyn: 1\nparameters: {m: 1, g: 9.81, L: 1}\ncoordinates: [x, y]\nparticles:\n"
             "  P: {mass: m, position: [x, y, 0]}\nforces:\n  - gravity: -g*E2\nconstraints:\n"
             "  - {name: rod, position: x^2 + y^2 - L^2}\ninitial: {x: " +
                 x + "}\n");
  return path;
}

TEST(HonestSummaries, CheckFailsOffTheConstraints) {
  const Outcome off = run("check '" + rod_model("100") + "'");
  EXPECT_EQ(off.status, 1) << off.out << off.err;
  EXPECT_TRUE(contains(off.out, "the initial state violates the constraints")) << off.out;
  EXPECT_TRUE(contains(off.out, "Psi of rod is 1e+04")) << off.out;
  EXPECT_TRUE(contains(off.out, "check FAILED")) << off.out;
  const Outcome on = run("check '" + rod_model("1") + "'");
  EXPECT_EQ(on.status, 0) << on.out << on.err;
  EXPECT_TRUE(contains(on.out, "check passed")) << on.out;
}

// r = (x y, y, 0): M = m [[y², x y], [x y, x² + 1]] has det m² y⁴, singular at the start y = 0.
std::string singular_model(const std::string& more = "") {
  const std::string path = temp_path("singular.yaml");
  write_file(path,
             "unidyn: 1\nparameters: {m: 1}\ncoordinates: [x, y]\nparticles:\n"
             "  P: {mass: m, position: [x*y, y, 0]}\n" +
                 more);
  return path;
}

TEST(HonestSummaries, CheckFailsWithASingularMassMatrix) {
  const Outcome r = run("check '" + singular_model() + "'");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "cannot be solved at the initial state")) << r.out;
  // a unilateral contact that starts apart is not a violation
  const Outcome ball = run("check bouncing-ball");
  EXPECT_EQ(ball.status, 0) << ball.out;
}

// E(0), E(t_end) and the change agree with the energy column of the CSV; a conservative model
// keeps "relative drift".
TEST(HonestSummaries, EnergyOfDrivenAndDissipativeModels) {
  for (const std::string model : {"rotating-hoop", "sphere-slide-roll", "bouncing-ball"}) {
    const std::string csv = temp_path("energy.csv");
    const Outcome r = run("simulate " + model + " -o '" + csv + "'");
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "energy not conserved (")) << r.out;
    EXPECT_FALSE(contains(r.out, "relative drift")) << r.out;
    const Csv rows = parse_csv(read_file(csv));
    ASSERT_FALSE(rows.rows.empty());
    const double e0 = rows.at(0, "energy"), e1 = rows.at(rows.rows.size() - 1, "energy");
    EXPECT_NEAR(number_after(r.out, "E(0) = "), e0, 1e-9 * (1 + std::abs(e0))) << model;
    EXPECT_NEAR(number_after(r.out, "change "), e1 - e0, 1e-5 * (1 + std::abs(e0))) << model;
  }
  EXPECT_TRUE(contains(run("simulate rotating-hoop -o /dev/null").out, "(driven by t)"));
  EXPECT_TRUE(contains(run("simulate sphere-slide-roll -o /dev/null").out, "friction"));
  const Outcome conservative = run("simulate spherical-pendulum -o /dev/null");
  EXPECT_TRUE(contains(conservative.out, "relative drift")) << conservative.out;
  EXPECT_FALSE(contains(conservative.out, "not conserved")) << conservative.out;
}

// Each multiplier's range over the run is the range of its CSV column.
TEST(HonestSummaries, MultiplierRanges) {
  const std::string csv = temp_path("helix.csv");
  const Outcome r = run("simulate helix -o '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const Csv rows = parse_csv(read_file(csv));
  const std::size_t column = rows.index("lambda(cylinder)");
  double low = rows.rows[0][column], high = low;
  for (const auto& row : rows.rows) {
    low = std::min(low, row[column]);
    high = std::max(high, row[column]);
  }
  const std::string label = "lambda(cylinder): from ";
  ASSERT_TRUE(contains(r.out, label)) << r.out;
  const std::string rest = r.out.substr(r.out.find(label) + label.size());
  EXPECT_NEAR(std::stod(rest), low, 1e-5 * std::abs(low));
  EXPECT_NEAR(std::stod(rest.substr(rest.find(" to ") + 4)), high, 1e-5 * std::abs(high) + 1e-9);
}

// A run that fails at its start computed no rows: no energy, residual or conserved figures.
TEST(HonestSummaries, NoFiguresWithoutRows) {
  const Outcome r =
      run("simulate '" + singular_model("conserved:\n  px: m*der(x)\n") + "' -o /dev/null");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.out, "0 rows")) << r.out;
  for (const char* figure : {"energy", "residuals", "conserved", "lambda("}) {
    EXPECT_FALSE(contains(r.out, figure)) << figure << "\n" << r.out;
  }
}

// stop_when may stand under simulate: (not in both places).
TEST(HonestSummaries, StopWhenUnderSimulate) {
  const std::string body =
      "unidyn: 1\nparameters: {g: 9.81}\ncoordinates: [z]\nparticles:\n"
      "  P: {mass: 1, position: [0, 0, z]}\nforces:\n  - gravity: -g*E3\ninitial: {z: 1}\n";
  const std::string path = temp_path("stop.yaml");
  write_file(path, body + "simulate: {t_end: 5, stop_when: [z]}\n");
  const Outcome r = run("simulate '" + path + "' -o /dev/null");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "simulated until stop_when")) << r.out;
  // the fall time sqrt(2/g)
  EXPECT_TRUE(contains(r.out, "t = 0.45152364098")) << r.out;
  write_file(path, body + "simulate: {stop_when: [z]}\nstop_when: [z]\n");
  const Outcome twice = run("simulate '" + path + "' -o /dev/null");
  expect_bad_input(twice, "twice");
  EXPECT_TRUE(contains(twice.err, "stop_when is given twice")) << twice.err;
}

// A parameter defined from others is computed anew from values given with --set, and the
// summary says so; one given with --set itself is used as given.
TEST(HonestSummaries, ParametersComputedFromSet) {
  const std::string path = temp_path("derived.yaml");
  write_file(path,
             "unidyn: 1\nparameters: {m: 1, g: 9.81, L: 1, L2: 2*L, tilt: 30*deg}\n"
             "coordinates: [phi]\nparticles:\n  P: {mass: m, position: \"L2*[sin(phi), 0, "
             "-cos(phi)]\"}\nforces:\n  - gravity: -g*E3\ninitial: {phi: tilt}\n");
  const std::string csv = temp_path("derived.csv");
  const Outcome r = run("simulate '" + path + "' --set L=3 --t-end 0.1 -o '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "parameter computed from --set: L2 = 6 from 2*L")) << r.out;
  const Csv rows = parse_csv(read_file(csv));
  // E = -m g L2 cos(30°) with L2 = 6
  EXPECT_NEAR(rows.at(0, "energy"), -9.81 * 6 * std::cos(std::numbers::pi / 6), 1e-12);
  const Outcome direct = run("simulate '" + path + "' --set L2=4 --t-end 0.1 -o '" + csv + "'");
  ASSERT_EQ(direct.status, 0) << direct.err;
  EXPECT_FALSE(contains(direct.out, "computed from --set")) << direct.out;
  EXPECT_NEAR(parse_csv(read_file(csv)).at(0, "energy"), -9.81 * 4 * std::cos(std::numbers::pi / 6),
              1e-12);
}

// An Euler-angle body started at its gimbal lock is bad input, with a set that is regular there.
TEST(HonestSummaries, GimbalLockAtTheStart) {
  for (const std::string command : {"simulate heavy-top -o /dev/null", "check heavy-top"}) {
    const Outcome r = run(command + " --set theta=0");
    expect_bad_input(r, command);
    EXPECT_TRUE(contains(r.err, "body 'top' starts at the gimbal lock of its 3-1-3 Euler angles"))
        << r.err;
    EXPECT_TRUE(contains(r.err, "{euler: 1-2-3, ...}")) << r.err;
    EXPECT_TRUE(contains(r.err, "quaternion")) << r.err;
  }
  EXPECT_EQ(run("check heavy-top --set theta=0.01").status, 0);
}

// The values given stay; those left out come from the constraints and the summary lists them; given
// values that violate a constraint are bad input (or, with --project, all are moved as before).
// An Atwood machine: y1 + y2 = −L.
const std::string kAtwood =
    "unidyn: 1\nparameters: {m1: 1, m2: 2, g: 9.81, L: 3}\ncoordinates: [y1, y2]\nparticles:\n"
    "  P1: {mass: m1, position: [0, y1, 0]}\n  P2: {mass: m2, position: [1, y2, 0]}\n"
    "forces:\n  - gravity: -g*E2\nconstraints:\n  - {name: string, position: -y1 - y2 - L}\n";

TEST(HonestSummaries, InitialValuesGivenStay) {
  const std::string path = temp_path("atwood.yaml");
  const std::string& model = kAtwood;
  write_file(path, model + "initial: {y1: -1, der(y1): 0.5}\n");
  const std::string csv = temp_path("atwood.csv");
  const Outcome r = run("simulate '" + path + "' --set y1=-0.9 --t-end 0.1 -o '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out,
                       "initial values computed from the constraints: y2 = -2.1, "
                       "der(y2) = -0.5"))
      << r.out;
  const Csv rows = parse_csv(read_file(csv));
  EXPECT_EQ(rows.at(0, "y1"), -0.9);
  EXPECT_EQ(rows.at(0, "der(y1)"), 0.5);
  // both given, and --set makes them disagree
  write_file(path, model + "initial: {y1: -1, y2: -2}\n");
  const Outcome conflict = run("simulate '" + path + "' --set y1=-0.9 -o /dev/null");
  expect_bad_input(conflict, "conflict");
  EXPECT_TRUE(contains(conflict.err,
                       "constraint 'string' (Psi = -0.1, coordinates y1 (given), "
                       "y2 (given))"))
      << conflict.err;
  const Outcome check = run("check '" + path + "' --set y1=-0.9");
  EXPECT_EQ(check.status, 1) << check.out;
  EXPECT_TRUE(contains(check.out, "check FAILED")) << check.out;
  const Outcome projected = run("simulate '" + path + "' --set y1=-0.9 --project -o /dev/null");
  EXPECT_EQ(projected.status, 0) << projected.err;
  EXPECT_TRUE(contains(projected.out, "the initial state was moved by")) << projected.out;
}

// Each event has its own row at the event's time, with the state the run goes on from (after an
// impact, the rebound), between the rows of the output grid; the summary counts them.
TEST(HonestSummaries, EventsHaveTheirOwnRows) {
  const std::string csv = temp_path("bounces.csv");
  const Outcome r = run("simulate bouncing-ball --t-end 2 -o '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const Csv rows = parse_csv(read_file(csv));
  std::vector<double> impacts;
  for (const std::string& line : lines_starting(r.out, "    t = ")) {
    if (contains(line, "impact")) impacts.push_back(std::stod(line.substr(8)));
  }
  ASSERT_EQ(impacts.size(), 3u) << r.out;  // at 0.45, 1.17 and 1.75 s
  EXPECT_TRUE(contains(r.out, "204 rows (3 at events between output times)")) << r.out;
  std::size_t on_grid = 0, found = 0;
  for (std::size_t i = 0; i < rows.rows.size(); ++i) {
    const double t = rows.at(i, "t");
    if (i > 0) {
      EXPECT_GT(t, rows.at(i - 1, "t")) << i;
    }
    if (std::abs(t - 0.01 * double(on_grid)) < 1e-12) {
      ++on_grid;
      continue;
    }
    ASSERT_LT(found, impacts.size()) << "a row at t = " << t;
    EXPECT_NEAR(t, impacts[found], 1e-11);
    EXPECT_NEAR(rows.at(i, "z"), 0.0, 1e-9);  // located to 1e-13 s
    EXPECT_GT(rows.at(i, "der(z)"), 0.0);
    ++found;
  }
  EXPECT_EQ(on_grid, 201u);
  EXPECT_EQ(found, impacts.size());
}

// --reduced eliminates y1 by the string (approach II): the value and rate given for y1 are kept,
// through the full model's start (y2 and its rate computed from the string), not dropped; values
// that contradict the string are bad input, and --project, which would move the given y1, is
// refused.
TEST(HonestSummaries, ReducedKeepsTheEliminatedCoordinatesValue) {
  const std::string path = temp_path("atwood-reduced.yaml");
  write_file(path, kAtwood + "initial: {y1: -0.9, der(y1): 0.5}\n");
  const std::string csv = temp_path("atwood-reduced.csv");
  const Outcome r = run("simulate '" + path + "' --reduced --t-end 0.1 -o '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "eliminated y1 by constraint string")) << r.err;
  EXPECT_TRUE(contains(r.out,
                       "initial values computed from the constraints: y2 = -2.1, "
                       "der(y2) = -0.5"))
      << r.out;
  const Csv rows = parse_csv(read_file(csv));
  EXPECT_EQ(rows.columns.size(), 4u) << rows.header;  // t, y2, der(y2), energy
  EXPECT_NEAR(rows.at(0, "y2"), -2.1, 1e-15);
  EXPECT_NEAR(rows.at(0, "der(y2)"), -0.5, 1e-15);
  // with the full equations, the same motion
  const std::string full_csv = temp_path("atwood-full.csv");
  ASSERT_EQ(run("simulate '" + path + "' --t-end 0.1 -o '" + full_csv + "'").status, 0);
  const Csv full = parse_csv(read_file(full_csv));
  ASSERT_EQ(full.rows.size(), rows.rows.size());
  for (std::size_t i = 0; i < rows.rows.size(); ++i) {
    EXPECT_NEAR(rows.at(i, "y2"), full.at(i, "y2"), 1e-12) << i;
  }
  // bad input (status 2, nothing on standard output) after the approach-II notes
  const Outcome conflict = run("simulate '" + path + "' --reduced --set y2=-2 -o /dev/null");
  EXPECT_EQ(conflict.status, 2) << conflict.err;
  EXPECT_TRUE(conflict.out.empty()) << conflict.out;
  EXPECT_TRUE(contains(conflict.err, "constraint 'string' (Psi = -0.1")) << conflict.err;
  const Outcome check = run("check '" + path + "' --reduced --set y2=-2");
  EXPECT_EQ(check.status, 1) << check.out;
  EXPECT_TRUE(contains(check.out, "check FAILED")) << check.out;
  const Outcome projected = run("simulate '" + path + "' --reduced --project -o /dev/null");
  EXPECT_EQ(projected.status, 2) << projected.err;
  EXPECT_TRUE(contains(projected.err, "--project cannot keep")) << projected.err;
}

// What removed energy is what happened in the run, not what the model could do: a rough contact
// with mu_d = 0 and a unilateral one never struck leave E conserved and unlabelled; with friction
// the energy taken is the friction's (the CSV's E(0) - E(end): the sphere is fixed, so nothing
// else does work); an impact is counted.
TEST(HonestSummaries, DissipationSaidOnlyWhenItHappened) {
  const Outcome smooth = run("simulate particle-leaving-sphere -o /dev/null");
  ASSERT_EQ(smooth.status, 0) << smooth.out << smooth.err;
  EXPECT_TRUE(contains(smooth.out, "energy: initial")) << smooth.out;
  EXPECT_FALSE(contains(smooth.out, "dissipative")) << smooth.out;
  const std::string csv = temp_path("rough.csv");
  const Outcome rough = run("simulate particle-leaving-sphere --set mu_d=0.2 -o '" + csv + "'");
  ASSERT_EQ(rough.status, 0) << rough.out << rough.err;
  EXPECT_FALSE(contains(rough.out, "impact")) << rough.out;
  const Csv rows = parse_csv(read_file(csv));
  ASSERT_FALSE(rows.rows.empty());
  const double lost = rows.at(0, "energy") - rows.at(rows.rows.size() - 1, "energy");
  ASSERT_GT(lost, 0.1);
  // the trapezoidal rule over rows 0.001 apart: well inside 1e-3 of the loss
  EXPECT_NEAR(number_after(rough.out, "dissipative: friction took "), lost, 1e-3 * lost)
      << rough.out;
  const Outcome struck = run("simulate inside-sphere -o /dev/null");
  EXPECT_TRUE(contains(struck.out, "(dissipative: 1 impact with restitution < 1)")) << struck.out;
}

// The benchmark bicycle below its weave speed falls over: its rear frame's roll, the second of
// its 3-1-2 angles, goes to -pi/2 (lying on the ground), the angles' gimbal lock. At every
// tolerance the run stops there with the advice — a loose one used to step past the lock and
// finish with a wrong motion (energy off by 2.5 %), a tight one to end in a bare step-size
// underflow — at the same time to a few ms.
TEST(HonestSummaries, AFallingBicycleStopsAtItsGimbalLock) {
  for (const char* rtol : {"1e-6", "1e-8"}) {
    const Outcome r =
        run(std::string("simulate bicycle --set v=3 --t-end 10 --rtol ") + rtol + " -o /dev/null");
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "Euler angles of body 'B' reached gimbal lock")) << r.out;
    EXPECT_TRUE(contains(r.out, "describe its rotation with a quaternion")) << r.out;
    EXPECT_NEAR(number_after(r.out, "stopped at t = "), 5.11, 0.01) << r.out;
  }
}

// A stiff model (a heavily damped spring: m x'' = -k x - c x', c = 1e4, so λ = -1e4 and -1e-4)
// under dopri5 stops within a few thousand steps saying it is stiff and what to use (it used to
// creep towards max_steps); CVODE then follows the slow mode, x = x0 exp(-k t / c) to 1e-6 after
// the fast one has died away.
TEST(HonestSummaries, AStiffModelUnderDopri5SaysSo) {
  const std::string model = temp_path("stiff.yaml");
  write_file(model,
             "unidyn: 1\nparameters: {m: 1, k: 1, c: 1e4}\ncoordinates: [x]\nparticles:\n"
             "  P: {mass: m, position: [x, 0, 0]}\nforces:\n"
             "  - spring: {from: P, to: [0, 0, 0], stiffness: k}\n"
             "  - damper: {from: P, to: [0, 0, 0], coefficient: c}\n"
             "initial: {x: 1}\nsimulate: {t_end: 100, output_step: 1, rtol: 1e-8}\n");
  const Outcome explicit_method = run("simulate '" + model + "' -o /dev/null");
  EXPECT_EQ(explicit_method.status, 1) << explicit_method.out;
  EXPECT_TRUE(contains(explicit_method.out, "the model is stiff")) << explicit_method.out;
  EXPECT_TRUE(contains(explicit_method.out, "--method cvode")) << explicit_method.out;
  // about 1 000 steps of h = 3.3e-4 (the stability bound over 1e4)
  EXPECT_LT(number_after(explicit_method.out, "stopped at t = "), 5.0) << explicit_method.out;
  const std::string csv = temp_path("stiff.csv");
  const Outcome bdf = run("simulate '" + model + "' --method cvode -o '" + csv + "'");
  ASSERT_EQ(bdf.status, 0) << bdf.out;
  const Csv rows = parse_csv(read_file(csv));
  for (std::size_t k = 1; k < rows.rows.size(); ++k) {
    const double t = rows.at(k, "t");
    EXPECT_NEAR(rows.at(k, "x"), std::exp(-t / 1e4), 1e-6) << t;
  }
}

// A parallelogram four-bar written with its crank angles and the coupler's, closed by two rows:
// when the bars align (t ≈ 0.71) the rows lose rank and the accelerations off the motion's branch
// have no solution: CVODE stops there at once (its step below the round-off of t), in under 10 000
// steps — it used to shrink its step for minutes at N = 40 (53.7 million steps).
TEST(HonestSummaries, AStuckRunStopsAtOnce) {
  const std::string model = temp_path("four-bar.yaml");
  write_file(model,
             "unidyn: 1\nparameters: {g: 9.81}\ncoordinates: [th0, th1, ph]\nbodies:\n"
             "  c0: {mass: 1, inertia: [0, 1/12, 1/12], rotation: {axis: [0, 0, 1], angle: th0}, "
             "center: 0.5*c0.e1}\n"
             "  c1: {mass: 1, inertia: [0, 1/12, 1/12], rotation: {axis: [0, 0, 1], angle: th1}, "
             "center: '[1, 0, 0] + 0.5*c1.e1'}\n"
             "  cp: {mass: 1, inertia: [0, 1/12, 1/12], rotation: {axis: [0, 0, 1], angle: ph}, "
             "center: 'c0.e1 + 0.5*cp.e1'}\n"
             "forces:\n  - gravity: -g*E2\nconstraints:\n"
             "  - {name: x, position: cos(th0) + cos(ph) - 1 - cos(th1)}\n"
             "  - {name: y, position: sin(th0) + sin(ph) - sin(th1)}\n"
             "initial: {th0: pi/2, th1: pi/2, ph: 0, der(th0): -1, der(th1): -1, der(ph): 0}\n"
             "simulate: {t_end: 20, output_step: 0.01}\n");
  const Outcome r = run("simulate '" + model + "' --method cvode -o /dev/null");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "t + h = t")) << r.out;
  // where: an instant the bars align, sin θ = 0 on the parallelogram's own motion — one degree of
  // freedom, (2/3 + 1) θ'' = −(1 + 1) g cos θ (two cranks' and the coupler's energies) — by RK4
  const double stop = number_after(r.out, "stopped at t = ");
  double theta = std::acos(0.0), rate = -1.0, nearest = INFINITY;
  const auto accel = [](double th) { return -2.0 * 9.81 * std::cos(th) / (5.0 / 3.0); };
  for (double t = 0, h = 1e-5; t < 20; t += h) {
    const double k1 = rate, l1 = accel(theta), k2 = rate + h / 2 * l1,
                 l2 = accel(theta + h / 2 * k1), k3 = rate + h / 2 * l2,
                 l3 = accel(theta + h / 2 * k2), k4 = rate + h * l3, l4 = accel(theta + h * k3);
    const double next = theta + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    rate += h / 6 * (l1 + 2 * l2 + 2 * l3 + l4);
    if (std::sin(next) * std::sin(theta) <= 0) nearest = std::min(nearest, std::abs(stop - t));
    theta = next;
  }
  EXPECT_LT(nearest, 1e-3) << r.out;
  EXPECT_LT(number_after(r.out, "integrate "), 2.0) << r.out;
  EXPECT_LT(number_after(r.out, "s; "), 10000) << r.out;
}

// A rod written twice (Ψ and 2Ψ) is a redundant row: accepted and named by `simulate` and `check`,
// the motion that of the rod written once, and its multiplier shared as the least-norm pair
// (λ/5, 2λ/5) of λ₁ + 2λ₂ = λ, the single rod's.
TEST(HonestSummaries, ARedundantRowIsNamedAndItsMultiplierShared) {
  const std::string once =
      "unidyn: 1\nparameters: {g: 9.81}\ncoordinates: [x, y]\nparticles:\n"
      "  P: {mass: 1, position: [x, y, 0]}\nforces:\n  - gravity: -g*E2\nconstraints:\n"
      "  - {name: rod, position: x^2 + y^2 - 1}\n";
  const std::string start =
      "initial: {x: 0.6, y: -0.8, der(x): 0}\nsimulate: {t_end: 2, output_step: 0.1}\n";
  const std::string single = temp_path("rod.yaml"), twice = temp_path("rod-twice.yaml");
  write_file(single, once + start);
  write_file(twice, once + "  - {name: rod_again, position: 2*(x^2 + y^2 - 1)}\n" + start);
  const std::string a = temp_path("rod.csv"), b = temp_path("rod-twice.csv");
  ASSERT_EQ(run("simulate '" + single + "' -o '" + a + "'").status, 0);
  const Outcome r = run("simulate '" + twice + "' -o '" + b + "'");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "note: 'rod_again' depends on the other constraints")) << r.out;
  EXPECT_TRUE(contains(r.out, "minimum-norm")) << r.out;
  const Csv one = parse_csv(read_file(a)), two = parse_csv(read_file(b));
  ASSERT_EQ(one.rows.size(), two.rows.size());
  for (std::size_t k = 0; k < one.rows.size(); ++k) {
    EXPECT_NEAR(two.at(k, "y"), one.at(k, "y"), 1e-8);
    const double lambda = one.at(k, "lambda(rod)");
    EXPECT_NEAR(two.at(k, "lambda(rod)"), lambda / 5, 1e-8 * std::abs(lambda));
    EXPECT_NEAR(two.at(k, "lambda(rod_again)"), 2 * lambda / 5, 1e-8 * std::abs(lambda));
  }
  const Outcome checked = run("check '" + twice + "'");
  EXPECT_EQ(checked.status, 0) << checked.out;
  EXPECT_TRUE(contains(checked.out, "note: 'rod_again' depends")) << checked.out;
}

}  // namespace
}  // namespace unidyn
