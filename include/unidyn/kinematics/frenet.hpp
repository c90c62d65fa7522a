// The Frenet triad, curvature and torsion of a space curve r(u) (book §2.11, §3.8).
#pragma once

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

struct FrenetTriad {
  Expr speed;           // ds/du = ‖r′‖
  VectorExpr tangent;   // e_t = r′ / ‖r′‖
  VectorExpr normal;    // e_n = e_b × e_t
  VectorExpr binormal;  // e_b = r′ × r″ / ‖r′ × r″‖
  Expr curvature;       // κ = ‖r′ × r″‖ / ‖r′‖³
  Expr torsion;         // τ = (r′ × r″) · r‴ / ‖r′ × r″‖²
};

// The triad of r(u) for any parameter u (not necessarily arc length). Undefined where r′ × r″ = 0
// (a straight piece): the normal, binormal and torsion then divide by zero.
FrenetTriad frenet_triad(const VectorExpr& r, const GiNaC::symbol& u);

}  // namespace unidyn
