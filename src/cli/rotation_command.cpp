// `unidyn rotation convert --from KIND VALUES... --to KIND` and `unidyn rotation show`.
#include "rotation_command.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "unidyn/rotation/axis_angle.hpp"
#include "unidyn/rotation/errors.hpp"
#include "unidyn/rotation/euler_parameters.hpp"
#include "unidyn/rotation/parametrisation.hpp"
#include "unidyn/rotation/rodrigues_vector.hpp"

namespace unidyn::cli {
namespace {

double parse_number(const std::string& text) {
  double x = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, x);
  if (ec != std::errc() || ptr != end)
    throw std::invalid_argument("'" + text + "' is not a number");
  return x;
}

// Shortest decimal form that reads back to the same double.
std::string join(const std::vector<double>& values) {
  std::string line;
  for (std::size_t n = 0; n < values.size(); ++n) {
    if (n > 0) line += ' ';
    line += fmt::format("{}", values[n]);
  }
  return line;
}

// Which values of a parametrisation are angles: the axis-angle pair's last, every Euler angle.
bool is_angle(const Parametrisation& p, std::size_t index) {
  return (p.kind == Parametrisation::Kind::axis_angle && index == 3) ||
         p.kind == Parametrisation::Kind::euler;
}

// The rotation tensor given by `--from KIND VALUES...` (angles in degrees with --degrees).
Tensor parse_rotation(const std::vector<std::string>& from, bool degrees) {
  const Parametrisation kind = Parametrisation::parse(from.at(0));
  std::vector<double> values;
  for (std::size_t n = 1; n < from.size(); ++n) {
    const double value = parse_number(from[n]);
    values.push_back(degrees && is_angle(kind, n - 1) ? value * std::numbers::pi / 180 : value);
  }
  return rotation_from(kind, values);
}

void print_show(const Tensor& Q, bool degrees) {
  const double unit = degrees ? 180.0 / std::numbers::pi : 1.0;
  fmt::print("rotation tensor Q (rows; Q_ij = E_i . Q E_j):\n");
  for (int i = 0; i < 3; ++i) fmt::print("  {:>22} {:>22} {:>22}\n", Q(i, 0), Q(i, 1), Q(i, 2));
  const AxisAngle a = axis_angle(Q);
  fmt::print("axis-angle (6.8): axis {} angle {} rad = {} deg\n",
             join({a.axis.x(), a.axis.y(), a.axis.z()}), a.angle,
             a.angle * 180.0 / std::numbers::pi);
  const EulerParameters e = euler_parameters(Q);
  fmt::print("quaternion (6.36): {}\n", join({e.e0, e.e.x(), e.e.y(), e.e.z()}));
  try {
    const Vec3 l = rodrigues_vector(Q).lambda;
    fmt::print("rodrigues (6.36): {}\n", join({l.x(), l.y(), l.z()}));
  } catch (const SingularConfiguration& error) {
    fmt::print("rodrigues (6.36): undefined ({})\n", error.what());
  }
  fmt::print("euler angles (6.20), {}; [g1,g2,g3] is zero at gimbal lock:\n",
             degrees ? "deg" : "rad");
  for (const EulerSet& set : all_euler_sets()) {
    const EulerAngles angles = euler_angles(set, Q);
    fmt::print("  {}: {:>22} {:>22} {:>22}   [g1,g2,g3] = {:+.6f}{}\n", set.name(),
               angles.angles[0] * unit, angles.angles[1] * unit, angles.angles[2] * unit,
               angles.volume, angles.singular ? "  GIMBAL LOCK (first angle set to 0)" : "");
  }
}

}  // namespace

void add_rotation_command(CLI::App& app, RotationCommand& command) {
  command.rotation = app.add_subcommand("rotation", "Rotation tensors and their parametrisations");
  command.rotation->require_subcommand(1);

  const std::string kinds =
      "KIND is matrix (9 numbers, row by row), axis-angle (x y z angle), quaternion (e0 e1 e2 e3), "
      "rodrigues (3 numbers) or euler:I-J-K (3 angles); angles in radians (degrees with --degrees)";
  command.convert = command.rotation->add_subcommand(
      "convert", "Convert a rotation from one parametrisation to another. " + kinds);
  command.convert->add_option("--from", command.from, "KIND VALUES...")
      ->required()
      ->expected(2, 10);
  command.convert->add_option("--to", command.to, "KIND")->required();
  command.convert->add_flag("--degrees", command.degrees, "angles in degrees, given and printed");

  command.show = command.rotation->add_subcommand(
      "show",
      "Print a rotation in every parametrisation, with each Euler set's distance to "
      "gimbal lock. " +
          kinds);
  command.show->add_option("--from", command.from, "KIND VALUES...")->required()->expected(2, 10);
  command.show->add_flag("--degrees", command.degrees, "angles in degrees, given and printed");
}

int run_rotation_command(const RotationCommand& command) {
  const Tensor Q = parse_rotation(command.from, command.degrees);
  if (command.convert->parsed()) {
    const Parametrisation to = Parametrisation::parse(command.to);
    std::vector<double> values = rotation_to(to, Q);
    for (std::size_t n = 0; n < values.size() && command.degrees; ++n) {
      if (is_angle(to, n)) values[n] *= 180.0 / std::numbers::pi;
    }
    fmt::print("{}\n", join(values));
  } else {
    print_show(Q, command.degrees);
  }
  return 0;
}

}  // namespace unidyn::cli
