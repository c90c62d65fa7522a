// The planes and spheres the position constraints hold points on (constraint_surfaces.hpp).
#include "unidyn/report/constraint_surfaces.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

constexpr int kSamples = 16;
// what the fit may leave of Ψ, relative to its size at the samples: round-off of a few operations
constexpr double kResidual = 1e-9;

// A point a constraint may hold: a particle, or a body's point of contact.
struct Candidate {
  std::string name;
  VectorExpr position;
};

// Ψ and r at a sample: the configuration's values were all real there.
struct Sample {
  double psi;
  Eigen::Vector3d r;
};

// Whether e contains one of the symbols.
bool has_any(const Expr& e, const std::vector<GiNaC::ex>& symbols) {
  return std::any_of(symbols.begin(), symbols.end(), [&](const GiNaC::ex& s) { return e.has(s); });
}

// The least-squares coefficients of Ψ in the columns of X, if they reproduce Ψ at every sample
// and the samples span the columns.
std::optional<Eigen::VectorXd> exact_fit(const Eigen::MatrixXd& X, const Eigen::VectorXd& psi) {
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
  qr.setThreshold(1e-10);
  if (qr.rank() < X.cols()) return std::nullopt;
  const Eigen::VectorXd coefficients = qr.solve(psi);
  const double scale = std::max(1.0, psi.cwiseAbs().maxCoeff());
  if ((X * coefficients - psi).cwiseAbs().maxCoeff() > kResidual * scale) return std::nullopt;
  return coefficients;
}

// x with the components below round-off of `scale` written 0 (the fit leaves 1e-17s).
Eigen::Vector3d cleaned(Eigen::Vector3d x, double scale) {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(x[i]) < 1e-12 * scale) x[i] = 0.0;
  }
  return x;
}

// The surface of Ψ at the samples for the point, if it is a plane or a sphere. The positions span
// the directions U about their mean r0 (all of space, or a plane for a point of a planar model):
// a plane is fitted as Ψ = a + β · Uᵀ(r − r0), so that its normal b = U β lies in those directions
// (a planar model's table stands across its plane); a sphere needs all of space.
std::optional<ConstraintSurface> surface_of(const std::vector<Sample>& samples) {
  const auto rows = static_cast<Eigen::Index>(samples.size());
  Eigen::MatrixXd R(rows, 3);
  Eigen::VectorXd psi(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    R.row(i) = samples[static_cast<std::size_t>(i)].r.transpose();
    psi[i] = samples[static_cast<std::size_t>(i)].psi;
  }
  const Eigen::RowVector3d r0 = R.colwise().mean();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(R.rowwise() - r0, Eigen::ComputeThinV);
  const Eigen::Vector3d sigma = svd.singularValues();
  const auto span = static_cast<Eigen::Index>((sigma.array() > 1e-9 * sigma[0]).count());
  if (sigma[0] == 0.0 || span < 2) return std::nullopt;
  const Eigen::MatrixXd U = svd.matrixV().leftCols(span);
  const double size = std::max(1.0, R.cwiseAbs().maxCoeff());
  ConstraintSurface surface;
  Eigen::MatrixXd X(rows, 1 + span);
  X.col(0).setOnes();
  X.rightCols(span) = (R.rowwise() - r0) * U;
  if (const auto f = exact_fit(X, psi)) {
    // (a + b · (r − r0) = 0): n = b/|b|, d = n · r0 − a/|b|, n's first non-zero component positive
    const Eigen::Vector3d b = U * f->tail(span);
    const double length = b.norm();
    if (length == 0.0) return std::nullopt;
    Eigen::Vector3d n = cleaned(b / length, 1.0);
    for (int i = 0; i < 3; ++i) {
      if (n[i] != 0.0) {
        n *= n[i] > 0 ? 1.0 : -1.0;
        break;
      }
    }
    surface.kind = ConstraintSurface::Kind::plane;
    surface.normal = n;
    surface.offset = n.dot(r0.transpose()) - (n.dot(b) / length) * (*f)[0] / length;
    if (std::abs(surface.offset) < 1e-12 * size) surface.offset = 0.0;
    return surface;
  }
  if (span < 3) return std::nullopt;
  X.resize(rows, 5);
  X.col(0).setOnes();
  X.middleCols(1, 3) = R;
  X.col(4) = R.rowwise().squaredNorm();
  if (const auto f = exact_fit(X, psi)) {
    // (a + b · r + k |r|² = 0): k |r + b/(2k)|² = |b|²/(4k) − a
    const double k = (*f)[4];
    if (std::abs(k) < 1e-12 * f->cwiseAbs().maxCoeff()) return std::nullopt;
    const Eigen::Vector3d center = -f->segment<3>(1) / (2 * k);
    const double square = center.squaredNorm() - (*f)[0] / k;
    if (!(square > 0)) return std::nullopt;
    surface.kind = ConstraintSurface::Kind::sphere;
    surface.radius = std::sqrt(square);
    surface.center = cleaned(center, surface.radius);
    return surface;
  }
  return std::nullopt;
}

}  // namespace

std::vector<ConstraintSurface> constraint_surfaces(const System& system,
                                                   const std::vector<double>& parameters) {
  std::vector<GiNaC::ex> q;
  for (const auto& c : system.coordinates()) q.push_back(c.value);
  // the configurations: each coordinate uniform in [−2, 2], the same ones on every run
  const GiNaC::exmap values = system.parameter_values(parameters);
  std::mt19937_64 random(20261126);
  std::vector<GiNaC::exmap> points(kSamples, values);
  for (GiNaC::exmap& point : points) {
    point[system.time()] = 0;
    for (const GiNaC::ex& s : q) {
      point[s] = GiNaC::numeric(4.0 * std::generate_canonical<double, 53>(random) - 2.0);
    }
  }
  std::vector<ConstraintSurface> surfaces;
  for (const Constraint& constraint : system.constraints) {
    if (constraint.kind != Constraint::Kind::position || constraint.parametrisation ||
        constraint.expression.has(system.time()) || !has_any(constraint.expression, q)) {
      continue;
    }
    // its own point of contact first, then the particles
    std::vector<Candidate> candidates;
    if (constraint.friction && has_any(constraint.friction->at[0] + constraint.friction->at[1] +
                                           constraint.friction->at[2],
                                       q)) {
      candidates.push_back({constraint.friction->on, constraint.friction->at});
    }
    for (const Particle& p : system.particles) candidates.push_back({p.name, p.position});
    for (const Candidate& candidate : candidates) {
      const auto at = real_values({constraint.expression, candidate.position[0],
                                   candidate.position[1], candidate.position[2]},
                                  points);
      std::vector<Sample> samples;
      for (std::size_t k = 0; k < points.size(); ++k) {
        if (at[0][k] && at[1][k] && at[2][k] && at[3][k]) {
          samples.push_back({*at[0][k], Eigen::Vector3d(*at[1][k], *at[2][k], *at[3][k])});
        }
      }
      if (samples.size() < 10) continue;
      if (auto surface = surface_of(samples)) {
        surface->constraint = constraint.name;
        surface->point = candidate.name;
        surfaces.push_back(*surface);
        break;
      }
    }
  }
  return surfaces;
}

}  // namespace unidyn
