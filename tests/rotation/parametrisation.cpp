// Every parametrisation of a rotation behind one interface (book §6.5, §6.8, §6.9): parsing kind
// names, conversions between every pair of kinds, and refusal of input that is no rotation.
#include "unidyn/rotation/parametrisation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

#include "support/oracles.hpp"
#include "unidyn/rotation/errors.hpp"

namespace unidyn {
namespace {

using test::kPi;
using test::max_abs_diff;

using Kind = Parametrisation::Kind;

// The twelve Euler sets of §6.8, typed here.
const std::array<const char*, 12> kEulerNames = {"1-2-3", "1-3-2", "2-1-3", "2-3-1",
                                                 "3-1-2", "3-2-1", "1-2-1", "1-3-1",
                                                 "2-1-2", "2-3-2", "3-1-3", "3-2-3"};

// All sixteen kinds by name.
std::vector<std::string> all_kind_names() {
  std::vector<std::string> names = {"matrix", "axis-angle", "quaternion", "rodrigues"};
  for (const char* set : kEulerNames) names.push_back(std::string("euler:") + set);
  return names;
}

std::vector<Parametrisation> all_kinds() {
  std::vector<Parametrisation> kinds;
  for (const std::string& name : all_kind_names()) kinds.push_back(Parametrisation::parse(name));
  return kinds;
}

// (6.25) elementary rotation matrices R_x, R_y, R_z, typed as in the book; axis 1..3.
Tensor elementary(int axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Tensor R;
  if (axis == 1) R << 1, 0, 0, 0, c, -s, 0, s, c;
  if (axis == 2) R << c, 0, s, 0, 1, 0, -s, 0, c;
  if (axis == 3) R << c, -s, 0, s, c, 0, 0, 0, 1;
  return R;
}

// (6.20) Q = R_I(γ¹) R_J(γ²) R_K(γ³).
Tensor euler_oracle(int I, int J, int K, const Vec3& g) {
  return elementary(I, g[0]) * elementary(J, g[1]) * elementary(K, g[2]);
}

// (6.10) components of L(φ, r), r a unit vector.
Tensor axis_angle_oracle(const Vec3& r, double phi) {
  Tensor skew_r;
  skew_r << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return std::cos(phi) * (Tensor::Identity() - r * r.transpose()) + r * r.transpose() +
         std::sin(phi) * skew_r;
}

// (6.36) components in the Euler parameters.
Tensor quaternion_oracle(double e0, const Vec3& e) {
  Tensor skew_part;
  skew_part << 0, -2 * e0 * e.z(), 2 * e0 * e.y(), 2 * e0 * e.z(), 0, -2 * e0 * e.x(),
      -2 * e0 * e.y(), 2 * e0 * e.x(), 0;
  return (e0 * e0 - e.squaredNorm()) * Tensor::Identity() + 2 * e * e.transpose() + skew_part;
}

// (6.36) R = ((1 − λ · λ) I + 2 λ⊗λ − 2 ελ)/(1 + λ · λ).
Tensor rodrigues_oracle(const Vec3& l) {
  Tensor skew_l;
  skew_l << 0, -l.z(), l.y(), l.z(), 0, -l.x(), -l.y(), l.x(), 0;
  return ((1 - l.squaredNorm()) * Tensor::Identity() + 2 * l * l.transpose() + 2 * skew_l) /
         (1 + l.squaredNorm());
}

// e0 = cos(φ/2) ≥ 0 of a rotation tensor, from φ = atan2(2 |axial|, tr Q − 1) (exact near π).
double half_angle_cosine(const Tensor& Q) {
  const Vec3 w(Q(2, 1) - Q(1, 2), Q(0, 2) - Q(2, 0), Q(1, 0) - Q(0, 1));  // 2 sin φ r
  return std::cos(0.5 * std::atan2(w.norm(), Q.trace() - 1.0));
}

double orthogonality_defect(const Tensor& Q) {
  return std::max((Q.transpose() * Q - Tensor::Identity()).cwiseAbs().maxCoeff(),
                  std::abs(Q.determinant() - 1.0));
}

// Difference of two value lists of one kind, angles compared modulo 2π.
double value_difference(const Parametrisation& p, const std::vector<double>& a,
                        const std::vector<double>& b) {
  double worst = 0.0;
  for (std::size_t n = 0; n < a.size(); ++n) {
    double d = std::abs(a[n] - b[n]);
    const bool angle = p.kind == Kind::euler || (p.kind == Kind::axis_angle && n == 3);
    if (angle) d = std::min(d, std::abs(d - 2 * kPi));
    worst = std::max(worst, d);
  }
  return worst;
}

// Whether the values of Q in kind p are unique and well conditioned, so that a round trip must
// reproduce them (not the axis at φ = 0 or π, the quaternion sign at e0 = 0, Euler angles near
// gimbal lock except at exact lock where γ¹ = 0 by convention).
bool values_comparable(const Parametrisation& p, const std::vector<double>& values,
                       const Tensor& Q) {
  const double e0 = half_angle_cosine(Q);
  switch (p.kind) {
    case Kind::matrix:
      return true;
    case Kind::axis_angle:
      return values[3] > 1e-3 && values[3] < kPi - 1e-3;
    case Kind::quaternion:
      return e0 > 1e-3;
    case Kind::rodrigues:
      return e0 > 1e-2;
    case Kind::euler: {
      const double second = values[1];
      const double volume =
          p.euler_set.symmetric() ? std::abs(std::sin(second)) : std::abs(std::cos(second));
      return volume > 1e-3 || volume < 1e-15;
    }
  }
  return false;
}

// The rotations to convert: uniformly random ones and every special case of the kinds.
std::string number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

struct Sample {
  Tensor Q;
  std::string what;
};

std::vector<Sample> sample_rotations(int random_count) {
  test::Random random(7u);
  std::vector<Sample> samples;
  for (int n = 0; n < random_count; ++n) samples.push_back({random.rotation(), "random"});
  samples.push_back({Tensor::Identity(), "identity"});
  // (1e-12 about a general axis lies inside every symmetric set's gimbal-lock band: tested in
  // EulerAnglesInsideGimbalLockBand.)
  for (const double phi : {1e-11, 1e-8, 1e-4, kPi - 1e-4, kPi - 1e-8, kPi}) {
    for (const Vec3& r : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}) {
      samples.push_back({axis_angle_oracle(r, phi), "angle " + number(phi) + " about E"});
    }
    for (int n = 0; n < 3; ++n) {
      samples.push_back({axis_angle_oracle(random.unit_vector(), phi), "angle " + number(phi)});
    }
  }
  Tensor half_turn;
  half_turn << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  samples.push_back({half_turn, "diag(1, -1, -1)"});
  half_turn << -1, 0, 0, 0, -1, 0, 0, 0, 1;
  samples.push_back({half_turn, "diag(-1, -1, 1)"});
  // Each Euler set at gimbal lock, and near it on both sides of the 1e-12 detection threshold.
  for (const char* name : kEulerNames) {
    const int I = name[0] - '0', J = name[2] - '0', K = name[4] - '0';
    const bool symmetric = I == K;
    const std::array<double, 2> locks =
        symmetric ? std::array<double, 2>{0.0, kPi} : std::array<double, 2>{kPi / 2, -kPi / 2};
    for (const double lock : locks) {
      for (int n = 0; n < 2; ++n) {
        const Vec3 g(random.uniform(-kPi, kPi), lock, random.uniform(-kPi, kPi));
        samples.push_back({euler_oracle(I, J, K, g), std::string(name) + " at gimbal lock"});
      }
      // Outside the 1e-12 detection band; the band itself is tested in
      // EulerAnglesInsideGimbalLockBand.
      for (const double offset : {-2e-12, 1e-11, 1e-9, -1e-6}) {
        const Vec3 g(3.0, lock + offset, random.uniform(-kPi, kPi));
        samples.push_back(
            {euler_oracle(I, J, K, g), std::string(name) + " near gimbal lock, " + number(offset)});
      }
    }
  }
  return samples;
}

std::string describe(const std::vector<double>& values) {
  std::ostringstream out;
  out.precision(17);
  for (const double x : values) out << x << ' ';
  return out.str();
}

// The Rodrigues vector does not exist at angle π (§6.9), e0 = cos(φ/2) = 0.
bool rodrigues_undefined(const Tensor& Q) {
  return half_angle_cosine(Q) < 1e-13;
}
bool rodrigues_defined(const Tensor& Q) {
  return half_angle_cosine(Q) > 1e-11;
}

// rotation_to() that records whether a SingularConfiguration was thrown where it must be.
std::vector<double> to_values(const Parametrisation& p, const Tensor& Q, bool& singular) {
  singular = false;
  try {
    return rotation_to(p, Q);
  } catch (const SingularConfiguration&) {
    singular = true;
    return {};
  }
}

// Parses every kind's name: the four named kinds and all twelve Euler sets; size() and name().
TEST(Parametrisation, ParsesEveryKind) {
  const Parametrisation matrix = Parametrisation::parse("matrix");
  EXPECT_EQ(matrix.kind, Kind::matrix);
  EXPECT_EQ(matrix.size(), 9u);
  const Parametrisation axis_angle = Parametrisation::parse("axis-angle");
  EXPECT_EQ(axis_angle.kind, Kind::axis_angle);
  EXPECT_EQ(axis_angle.size(), 4u);
  const Parametrisation quaternion = Parametrisation::parse("quaternion");
  EXPECT_EQ(quaternion.kind, Kind::quaternion);
  EXPECT_EQ(quaternion.size(), 4u);
  const Parametrisation rodrigues = Parametrisation::parse("rodrigues");
  EXPECT_EQ(rodrigues.kind, Kind::rodrigues);
  EXPECT_EQ(rodrigues.size(), 3u);
  for (const char* name : kEulerNames) {
    const Parametrisation p = Parametrisation::parse(std::string("euler:") + name);
    EXPECT_EQ(p.kind, Kind::euler) << name;
    EXPECT_EQ(p.euler_set.first, name[0] - '0') << name;
    EXPECT_EQ(p.euler_set.second, name[2] - '0') << name;
    EXPECT_EQ(p.euler_set.third, name[4] - '0') << name;
    EXPECT_EQ(p.euler_set.symmetric(), name[0] == name[4]) << name;
    EXPECT_EQ(p.size(), 3u) << name;
  }
  for (const std::string& name : all_kind_names()) {
    const Parametrisation p = Parametrisation::parse(name);
    EXPECT_EQ(p.name(), name);
    const Parametrisation again = Parametrisation::parse(p.name());
    EXPECT_EQ(again.kind, p.kind) << name;
    EXPECT_EQ(again.name(), name);
    if (p.kind == Kind::euler) {
      EXPECT_EQ(again.euler_set, p.euler_set) << name;
    }
  }
  // The library's list of sets is the same twelve, each once.
  std::vector<std::string> listed;
  for (const EulerSet& set : all_euler_sets()) listed.push_back(set.name());
  std::sort(listed.begin(), listed.end());
  std::vector<std::string> typed(kEulerNames.begin(), kEulerNames.end());
  std::sort(typed.begin(), typed.end());
  EXPECT_EQ(listed, typed);
}

// Names that are no kind are refused with std::invalid_argument.
TEST(Parametrisation, RejectsUnknownNames) {
  for (const char* name :
       {"euler:1-1-2", "euler:", "Matrix", "quat", "euler:3-1-1", "euler:4-1-2", "euler:313",
        "euler:3-1-3 ", "euler:3-1-3-1", "euler", "axis_angle", "", "euler:0-1-2", "rodrigues "}) {
    EXPECT_THROW(Parametrisation::parse(name), std::invalid_argument) << "'" << name << "'";
  }
}

// rotation_from() against the book's formulas written here: (6.10), (6.20)/(6.25), (6.36).
TEST(Parametrisation, FromValuesMatchesBookFormulas) {
  test::Random random;
  for (int n = 0; n < 500; ++n) {
    const Tensor Q = random.rotation();
    const std::vector<double> rows = {Q(0, 0), Q(0, 1), Q(0, 2), Q(1, 0), Q(1, 1),
                                      Q(1, 2), Q(2, 0), Q(2, 1), Q(2, 2)};
    ASSERT_LE(max_abs_diff(rotation_from(Parametrisation::parse("matrix"), rows), Q), 1e-15) << n;

    const Vec3 r = random.unit_vector();
    const double phi = random.uniform(-7.0, 7.0);
    ASSERT_LE(max_abs_diff(rotation_from(Parametrisation::parse("axis-angle"),
                                         std::vector<double>{r.x(), r.y(), r.z(), phi}),
                           axis_angle_oracle(r, phi)),
              1e-14)
        << n;

    const Vec3 e = random.unit_vector() * std::sin(0.5 * phi);
    const double e0 = std::cos(0.5 * phi);
    ASSERT_LE(max_abs_diff(rotation_from(Parametrisation::parse("quaternion"),
                                         std::vector<double>{e0, e.x(), e.y(), e.z()}),
                           quaternion_oracle(e0, e)),
              1e-14)
        << n;

    const Vec3 l = random.vector(3.0);
    ASSERT_LE(max_abs_diff(rotation_from(Parametrisation::parse("rodrigues"),
                                         std::vector<double>{l.x(), l.y(), l.z()}),
                           rodrigues_oracle(l)),
              1e-14)
        << n;

    for (const char* name : kEulerNames) {
      const Vec3 g = random.vector(4.0);
      ASSERT_LE(max_abs_diff(rotation_from(Parametrisation::parse(std::string("euler:") + name),
                                           std::vector<double>{g.x(), g.y(), g.z()}),
                             euler_oracle(name[0] - '0', name[2] - '0', name[4] - '0', g)),
                1e-14)
          << n << " " << name;
    }
  }
}

// §6.5.1 W3 in every kind: the 3-2-3 angles (0.2, −0.5, 0.1), axis–angle, e0/e, λ, 3-2-1 angles.
TEST(Parametrisation, BookExampleW3InEveryKind) {
  const Tensor Q =
      rotation_from(Parametrisation::parse("euler:3-2-3"), std::vector<double>{0.2, -0.5, 0.1});
  Tensor printed;
  printed << 0.835959, -0.283542, -0.469869, 0.271321, 0.957764, -0.0952472, 0.47703, -0.0478627,
      0.877583;
  EXPECT_LE(max_abs_diff(Q, printed), 0.5e-6);

  const std::vector<double> aa = rotation_to(Parametrisation::parse("axis-angle"), Q);
  EXPECT_NEAR(aa[3] * 180 / kPi, 33.3161, 0.5e-4);
  EXPECT_NEAR(aa[0], 0.043135, 0.5e-6);
  EXPECT_NEAR(aa[1], -0.861981, 0.5e-6);
  EXPECT_NEAR(aa[2], 0.505103, 0.5e-6);

  const std::vector<double> q = rotation_to(Parametrisation::parse("quaternion"), Q);
  const std::array<double, 4> q_expected = {0.9580326, 0.0123650, -0.2470948, 0.1447925};
  for (int n = 0; n < 4; ++n) EXPECT_NEAR(q[n], q_expected[n], 0.5e-7) << n;

  const std::vector<double> l = rotation_to(Parametrisation::parse("rodrigues"), Q);
  const std::array<double, 3> l_expected = {0.0129067, -0.2579190, 0.1511352};
  for (int n = 0; n < 3; ++n) EXPECT_NEAR(l[n], l_expected[n], 0.5e-7) << n;

  const std::vector<double> ypr = rotation_to(Parametrisation::parse("euler:3-2-1"), Q);
  const std::array<double, 3> ypr_expected = {0.3138365, -0.4972728, -0.0544853};
  for (int n = 0; n < 3; ++n) EXPECT_NEAR(ypr[n], ypr_expected[n], 0.5e-7) << n;

  // θ ∈ [0, π] for 3-2-3: (0.2, −0.5, 0.1) ≡ (0.2 + π, 0.5, 0.1 + π), wrapped to (−π, π].
  const std::vector<double> g = rotation_to(Parametrisation::parse("euler:3-2-3"), Q);
  EXPECT_NEAR(g[0], 0.2 - kPi, 1e-14);
  EXPECT_NEAR(g[1], 0.5, 1e-14);
  EXPECT_NEAR(g[2], 0.1 - kPi, 1e-14);
}

// §6.3 (6.6): the six-digit W3 matrix (defect ~1e-6) is accepted and projected onto a rotation.
TEST(Parametrisation, AcceptsSixDigitMatrix) {
  const std::vector<double> rows = {0.835959,   -0.283542, -0.469869,  0.271321, 0.957764,
                                    -0.0952472, 0.47703,   -0.0478627, 0.877583};
  Tensor printed;
  printed << rows[0], rows[1], rows[2], rows[3], rows[4], rows[5], rows[6], rows[7], rows[8];
  const double input_defect = orthogonality_defect(printed);
  EXPECT_GT(input_defect, 1e-7);
  EXPECT_LT(input_defect, kRotationInputTolerance);
  const Tensor Q = rotation_from(Parametrisation::parse("matrix"), rows);
  EXPECT_LE(orthogonality_defect(Q), 1e-14);  // a few ulps of round-off
  EXPECT_LE(max_abs_diff(Q, printed), 2 * input_defect);
  // The exact rotation it approximates (to the printed digits) is the 3-2-3 one of the notes.
  EXPECT_LE(max_abs_diff(Q, euler_oracle(3, 2, 3, Vec3(0.2, -0.5, 0.1))), 1e-6);
}

// §6.5, §6.8, §6.9: rotation_from(to, rotation_to(to, Q)) = Q to 1e-12 for each of 16 kinds.
TEST(Parametrisation, EachKindRoundTrip) {
  const std::vector<Sample> samples = sample_rotations(500);
  for (const Parametrisation& p : all_kinds()) {
    double worst = 0.0;
    std::string worst_case;
    for (const Sample& s : samples) {
      bool singular = false;
      const std::vector<double> values = to_values(p, s.Q, singular);
      if (singular) {
        EXPECT_TRUE(p.kind == Kind::rodrigues && !rodrigues_defined(s.Q))
            << p.name() << " threw SingularConfiguration at " << s.what;
        continue;
      }
      if (p.kind == Kind::rodrigues) {
        EXPECT_FALSE(rodrigues_undefined(s.Q)) << "rodrigues did not throw at " << s.what;
      }
      ASSERT_EQ(values.size(), p.size()) << p.name();
      const double error = max_abs_diff(rotation_from(p, values), s.Q);
      if (error > worst) {
        worst = error;
        worst_case = s.what + ": " + describe(values);
      }
    }
    EXPECT_LE(worst, 1e-12) << p.name() << ", worst at " << worst_case;
  }
}

// §6.5, §6.8, §6.9: every ordered pair of the 16 kinds, A → Q → B → Q → A, to 1e-12.
TEST(Parametrisation, EveryPairOfKinds) {
  const std::vector<Sample> samples = sample_rotations(200);
  const std::vector<Parametrisation> kinds = all_kinds();
  for (const Parametrisation& A : kinds) {
    for (const Parametrisation& B : kinds) {
      double worst = 0.0, worst_values = 0.0;
      std::string worst_case, worst_values_case;
      int checked = 0;
      for (const Sample& s : samples) {
        bool singular = false;
        const std::vector<double> a = to_values(A, s.Q, singular);
        if (singular) continue;  // the Rodrigues vector at π, checked in EachKindRoundTrip
        const Tensor QA = rotation_from(A, a);
        const std::vector<double> b = to_values(B, QA, singular);
        if (singular) {
          EXPECT_TRUE(B.kind == Kind::rodrigues && !rodrigues_defined(QA))
              << A.name() << " -> " << B.name() << " threw at " << s.what;
          continue;
        }
        const Tensor QB = rotation_from(B, b);
        const std::vector<double> a_again = rotation_to(A, QB);
        const Tensor QA_again = rotation_from(A, a_again);
        const double error = std::max(max_abs_diff(QB, s.Q), max_abs_diff(QA_again, s.Q));
        if (error > worst) {
          worst = error;
          worst_case = s.what + ": " + describe(a) + "-> " + describe(b);
        }
        if (values_comparable(A, a, s.Q)) {
          const double d = value_difference(A, a, a_again);
          if (d > worst_values) {
            worst_values = d;
            worst_values_case = s.what + ": " + describe(a) + "-> " + describe(a_again);
          }
        }
        ++checked;
      }
      EXPECT_GT(checked, 150) << A.name() << " -> " << B.name();
      EXPECT_LE(worst, 1e-12) << A.name() << " -> " << B.name() << ", worst at " << worst_case;
      EXPECT_LE(worst_values, 1e-12) << A.name() << " -> " << B.name() << " -> " << A.name()
                                     << ", worst at " << worst_values_case;
    }
  }
}

// (6.20) near gimbal lock, |[g1, g2, g3]| ≤ kGimbalLockTolerance: angles still reproduce Q.
TEST(Parametrisation, EulerAnglesInsideGimbalLockBand) {
  // There γ¹ is set to 0; the acceptance criterion "answers every pair of kinds to 1e-12"
  // still applies, and every pair X → euler:I-J-K goes through this step.
  test::Random random(11u);
  for (const char* name : kEulerNames) {
    const int I = name[0] - '0', J = name[2] - '0', K = name[4] - '0';
    const Parametrisation p = Parametrisation::parse(std::string("euler:") + name);
    const std::array<double, 2> locks =
        I == K ? std::array<double, 2>{0.0, kPi} : std::array<double, 2>{kPi / 2, -kPi / 2};
    double worst = 0.0;
    std::string worst_case;
    const auto check = [&](const Tensor& Q, const std::string& what) {
      const double error = max_abs_diff(rotation_from(p, rotation_to(p, Q)), Q);
      if (error > worst) {
        worst = error;
        worst_case = what;
      }
    };
    for (const double lock : locks) {
      for (const double offset : {1e-14, 1e-13, 3e-13, 5e-13, 7e-13, 9e-13, 1e-12}) {
        for (double first = -3.1; first < 3.15; first += 0.2) {
          // Step into the admissible range of γ² (so the angles are also the canonical ones).
          const Vec3 g(first, lock + (lock > 0 ? -offset : offset), 0.7);
          check(euler_oracle(I, J, K, g), "angles (" + number(g[0]) + ", lock ± " + number(offset) +
                                              ", " + number(g[2]) + ")");
        }
      }
    }
    // A rotation by 1e-12 about a general axis has γ² ≈ 1e-12 in every symmetric set.
    for (int n = 0; n < 50; ++n) {
      const Vec3 r = random.unit_vector();
      check(axis_angle_oracle(r, 1e-12), "angle 1e-12 about a random axis");
    }
    EXPECT_LE(worst, 1e-12) << name << ", worst at " << worst_case;
  }
}

// Input of the wrong length is std::invalid_argument (and not a NotARotation).
TEST(Parametrisation, RejectsWrongCounts) {
  for (const Parametrisation& p : all_kinds()) {
    for (const std::size_t count : {std::size_t{0}, p.size() - 1, p.size() + 1, std::size_t{10}}) {
      if (count == p.size()) continue;
      const std::vector<double> values(count, 0.0);
      try {
        rotation_from(p, values);
        ADD_FAILURE() << p.name() << " accepted " << count << " numbers";
      } catch (const NotARotation&) {
        ADD_FAILURE() << p.name() << ": a wrong count is not a NotARotation";
      } catch (const std::invalid_argument&) {
      }
    }
  }
}

// (6.6), (6.36): NaN/inf, non-orthogonal, reflection, non-unit quaternion/axis are NotARotation.
TEST(Parametrisation, RejectsNonRotations) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const Parametrisation& p : all_kinds()) {
    for (const double bad : {nan, inf, -inf}) {
      std::vector<double> values = rotation_to(p, Tensor::Identity());
      for (std::size_t n = 0; n < values.size(); ++n) {
        std::vector<double> v = values;
        v[n] = bad;
        EXPECT_THROW(rotation_from(p, v), NotARotation) << p.name() << " entry " << n;
      }
    }
  }
  const Parametrisation matrix = Parametrisation::parse("matrix");
  const auto rows = [](const Tensor& M) {
    return std::vector<double>{M(0, 0), M(0, 1), M(0, 2), M(1, 0), M(1, 1),
                               M(1, 2), M(2, 0), M(2, 1), M(2, 2)};
  };
  test::Random random;
  const Tensor Q = random.rotation();
  Tensor M = Q;
  M(1, 2) += 1e-3;
  EXPECT_THROW(rotation_from(matrix, rows(M)), NotARotation);
  EXPECT_THROW(rotation_from(matrix, rows(1.001 * Q)), NotARotation);
  EXPECT_THROW(rotation_from(matrix, rows(Tensor::Zero())), NotARotation);
  EXPECT_THROW(rotation_from(matrix, rows(Vec3(1, 1, 2).asDiagonal())), NotARotation);
  // Reflections: orthogonal with det = −1.
  EXPECT_THROW(rotation_from(matrix, rows(Vec3(1, 1, -1).asDiagonal())), NotARotation);
  EXPECT_THROW(rotation_from(matrix, rows(-Q)), NotARotation);
  EXPECT_THROW(rotation_from(matrix, rows(-Tensor::Identity())), NotARotation);

  const Parametrisation quaternion = Parametrisation::parse("quaternion");
  EXPECT_THROW(rotation_from(quaternion, std::vector<double>{1, 0, 0, 0.01}), NotARotation);
  EXPECT_THROW(rotation_from(quaternion, std::vector<double>{2, 0, 0, 0}), NotARotation);
  EXPECT_THROW(rotation_from(quaternion, std::vector<double>{0, 0, 0, 0}), NotARotation);
  EXPECT_THROW(rotation_from(quaternion, std::vector<double>{0.5, 0.5, 0.5, 0.4}), NotARotation);

  const Parametrisation axis_angle = Parametrisation::parse("axis-angle");
  EXPECT_THROW(rotation_from(axis_angle, std::vector<double>{0, 0, 1.001, 0.3}), NotARotation);
  EXPECT_THROW(rotation_from(axis_angle, std::vector<double>{0, 0, 0, 0.3}), NotARotation);
  EXPECT_THROW(rotation_from(axis_angle, std::vector<double>{1, 1, 1, 0.3}), NotARotation);
}

// Unit input given to six or more digits is accepted and normalised (kRotationInputTolerance).
TEST(Parametrisation, AcceptsNearlyUnitInput) {
  const double off = 1.0 + 2e-6;
  const Tensor Qq = rotation_from(Parametrisation::parse("quaternion"),
                                  std::vector<double>{0.6 * off, 0.0, 0.8 * off, 0.0});
  EXPECT_LE(orthogonality_defect(Qq), 1e-14);
  EXPECT_LE(max_abs_diff(Qq, quaternion_oracle(0.6, Vec3(0, 0.8, 0))), 1e-15);
  const Tensor Qa = rotation_from(Parametrisation::parse("axis-angle"),
                                  std::vector<double>{0.0, 0.6 * off, 0.8 * off, 1.2});
  EXPECT_LE(orthogonality_defect(Qa), 1e-14);
  EXPECT_LE(max_abs_diff(Qa, axis_angle_oracle(Vec3(0, 0.6, 0.8), 1.2)), 1e-15);
}

}  // namespace
}  // namespace unidyn
