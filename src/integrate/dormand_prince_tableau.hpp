// Coefficients of the Dormand–Prince RK5(4)7M pair and of its continuous extension.
#pragma once

namespace unidyn::detail::dormand_prince {

// Nodes and stages: Dormand & Prince (1980); Hairer, Nørsett & Wanner, Solving ODEs I, §II.5,
// Table 5.2.
inline constexpr double c2 = 1.0 / 5.0, c3 = 3.0 / 10.0, c4 = 4.0 / 5.0, c5 = 8.0 / 9.0;
inline constexpr double a21 = 1.0 / 5.0;
inline constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
inline constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
inline constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                        a54 = -212.0 / 729.0;
inline constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0,
                        a64 = 49.0 / 176.0, a65 = -5103.0 / 18656.0;
// Fifth-order weights, also the last stage (first same as last): b = a7j.
inline constexpr double a71 = 35.0 / 384.0, a73 = 500.0 / 1113.0, a74 = 125.0 / 192.0,
                        a75 = -2187.0 / 6784.0, a76 = 11.0 / 84.0;

// Error estimate e = b − b̂ (fifth- minus fourth-order weights), as in Hairer's DOPRI5.
inline constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0,
                        e5 = -17253.0 / 339200.0, e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;

// Continuous extension of Shampine (1986), "Some practical Runge–Kutta formulas", Math. Comp. 46,
// 135–150, in the form of DOPRI5's CONTD5 (HNW I, §II.6).
inline constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                        d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                        d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

}  // namespace unidyn::detail::dormand_prince
