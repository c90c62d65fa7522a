// SUNDIALS CVODE's BDF method behind the Stepper interface: one internal step per step(), the
// Nordsieck polynomial as dense output, and the model's projection inside CVODE's step.
#include "unidyn/integrate/cvode.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_proj.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>

#include "unidyn/numeric/number_text.hpp"

namespace unidyn {
namespace {

// An Eigen view of a serial N_Vector's data.
Eigen::Map<Eigen::VectorXd> view(N_Vector v) {
  return {N_VGetArrayPointer(v), static_cast<Eigen::Index>(N_VGetLength(v))};
}

}  // namespace

// CVODE's objects, freed in reverse order of creation.
struct CvodeBdf::Solver {
  SUNContext context = nullptr;
  void* memory = nullptr;
  N_Vector y = nullptr;
  N_Vector dky = nullptr;  // the derivatives of the step's polynomial, one at a time
  SUNMatrix jacobian = nullptr;
  SUNLinearSolver linear = nullptr;
  // CVODE's last error message, and its failure counters when it (re)started.
  std::string message;
  long rejected_base = 0;
  // Workspace of the callbacks.
  Eigen::VectorXd state, derivative;

  ~Solver() {
    if (memory != nullptr) CVodeFree(&memory);
    if (linear != nullptr) SUNLinSolFree(linear);
    if (jacobian != nullptr) SUNMatDestroy(jacobian);
    if (dky != nullptr) N_VDestroy(dky);
    if (y != nullptr) N_VDestroy(y);
    if (context != nullptr) SUNContext_Free(&context);
  }
};

struct CvodeBdf::Callbacks {
  // y' = f(t, y): 0 on success, 1 (recoverable: CVODE takes a smaller step) when f is not finite,
  // −1 (stop) when it threw.
  static int rhs(double t, N_Vector y, N_Vector ydot, void* self_pointer) {
    auto& self = *static_cast<CvodeBdf*>(self_pointer);
    Solver& s = *self.solver_;
    try {
      s.state = view(y);
      const bool finite = self.evaluate(t, s.state, s.derivative);
      view(ydot) = s.derivative;
      return finite ? 0 : 1;
    } catch (...) {
      self.error_ = std::current_exception();
      return -1;
    }
  }

  // The model's projection as CVODE's correction, corr = P(y) − y, and the step's error
  // estimate projected with it, err ← P(P(y) + err) − P(y) (to first order the tangent part of
  // err). Left unprojected, the error test sees the normal part the projection removed from the
  // last step as this step's error: with the projection's kinetic-energy metric far from the
  // error test's weights, that echo does not shrink with h, and CVODE takes millions of steps
  // with t + h = t (Andrews' squeezer at rtol 1e-10).
  static int project(double t, N_Vector y, N_Vector correction, double /*epsProj*/, N_Vector err,
                     void* self_pointer) {
    auto& self = *static_cast<CvodeBdf*>(self_pointer);
    Solver& s = *self.solver_;
    try {
      s.state = view(y);
      self.options_.projection(t, s.state);
      if (!s.state.allFinite()) return 1;
      view(correction) = s.state - view(y);
      if (err != nullptr) {
        s.derivative = s.state + view(err);
        self.options_.projection(t, s.derivative);
        if (!s.derivative.allFinite()) return 1;
        view(err) = s.derivative - s.state;
      }
      return 0;
    } catch (...) {
      self.error_ = std::current_exception();
      return -1;
    }
  }

  // Keep CVODE's message for the exception instead of printing it.
  static void error_handler(int /*code*/, const char* /*module*/, const char* function,
                            char* message, void* self_pointer) {
    static_cast<CvodeBdf*>(self_pointer)->solver_->message = std::string(function) + ": " + message;
  }
};

CvodeBdf::CvodeBdf(OdeFunction rhs, CvodeOptions options)
    : Stepper(std::move(rhs)), options_(std::move(options)) {
  if (!(options_.rtol >= 0.0) || !(options_.atol > 0.0) || !std::isfinite(options_.rtol) ||
      !std::isfinite(options_.atol)) {
    throw std::invalid_argument("cvode: rtol must be ≥ 0 and atol > 0, both finite");
  }
  if (options_.max_order < 1 || options_.max_order > 5) {
    throw std::invalid_argument("cvode: max_order must be 1 to 5");
  }
  if (options_.max_steps == 0) throw std::invalid_argument("cvode: max_steps must be positive");
}

CvodeBdf::~CvodeBdf() = default;

void CvodeBdf::restart() {
  start_pending_ = true;
  taylor_.clear();
}

// A replaced state cannot enter CVODE's history: it starts again from it (at order 1).
void CvodeBdf::before_reset_state() {
  start_pending_ = true;
}

void CvodeBdf::start_solver() {
  const auto n = static_cast<sunindextype>(y().size());
  const bool fresh = !solver_ || N_VGetLength(solver_->y) != n;
  if (fresh) {
    solver_ = std::make_unique<Solver>();
    Solver& s = *solver_;
    if (SUNContext_Create(nullptr, &s.context) != 0) throw std::runtime_error("cvode: no context");
    s.y = N_VNew_Serial(n, s.context);
    s.dky = N_VNew_Serial(n, s.context);
    s.jacobian = SUNDenseMatrix(n, n, s.context);
    s.memory = CVodeCreate(CV_BDF, s.context);
    if (s.y == nullptr || s.dky == nullptr || s.jacobian == nullptr || s.memory == nullptr) {
      throw std::runtime_error("cvode: out of memory");
    }
    s.linear = SUNLinSol_Dense(s.y, s.jacobian, s.context);
    view(s.y) = y();
    int flag = CVodeInit(s.memory, &Callbacks::rhs, t(), s.y);
    if (flag == CV_SUCCESS) flag = CVodeSetUserData(s.memory, this);
    if (flag == CV_SUCCESS) {
      flag = CVodeSetErrHandlerFn(s.memory, &Callbacks::error_handler, this);
    }
    if (flag == CV_SUCCESS) flag = CVodeSStolerances(s.memory, options_.rtol, options_.atol);
    if (flag == CV_SUCCESS) flag = CVodeSetLinearSolver(s.memory, s.linear, s.jacobian);
    if (flag == CV_SUCCESS) flag = CVodeSetMaxOrd(s.memory, options_.max_order);
    if (flag == CV_SUCCESS && options_.projection) {
      flag = CVodeSetProjFn(s.memory, &Callbacks::project);
      if (flag == CV_SUCCESS) flag = CVodeSetProjErrEst(s.memory, SUNTRUE);
    }
    if (flag != CV_SUCCESS) fail(flag, t());
  } else {
    view(solver_->y) = y();
    const int flag = CVodeReInit(solver_->memory, t(), solver_->y);
    if (flag != CV_SUCCESS) fail(flag, t());
  }
  solver_->rejected_base = 0;
  start_pending_ = false;
}

void CvodeBdf::advance(double t_limit) {
  if (start_pending_) start_solver();
  Solver& s = *solver_;
  StepperStats& stats = mutable_stats();
  if (stats.accepted_steps + stats.rejected_steps >= options_.max_steps) {
    throw IntegrationError(describe("reached max_steps = " + std::to_string(options_.max_steps) +
                                    " at t = " + detail::to_text(t())),
                           t());
  }
  // One internal step that does not pass t_limit.
  int flag = CVodeSetStopTime(s.memory, t_limit);
  double t_new = t();
  if (flag == CV_SUCCESS) flag = CVode(s.memory, t_limit, s.y, &t_new, CV_ONE_STEP);
  if (flag < 0) fail(flag, t());
  // Rejections: error-test and convergence failures since CVODE (re)started.
  long error_failures = 0, convergence_failures = 0;
  CVodeGetNumErrTestFails(s.memory, &error_failures);
  CVodeGetNumNonlinSolvConvFails(s.memory, &convergence_failures);
  const long rejected = error_failures + convergence_failures;
  stats.rejected_steps += static_cast<std::size_t>(rejected - s.rejected_base);
  s.rejected_base = rejected;
  // The step's polynomial as Taylor coefficients at its end (exact: it has degree q), q the order
  // of the step just taken — not CVodeGetCurrentOrder, the order of the next one: when that is
  // q + 1, CVodeGetDky refuses k = q + 1 and the last coefficient was a stale one (rows inside such
  // a step off by 1e-5 at rtol 1e-8).
  int order = 0;
  CVodeGetLastOrder(s.memory, &order);
  CVodeGetLastStep(s.memory, &last_step_);
  last_order_ = order;
  taylor_.resize(static_cast<std::size_t>(order) + 1);
  for (int k = 0; k <= order; ++k) {
    if (const int got = CVodeGetDky(s.memory, t_new, k, s.dky); got != CV_SUCCESS) fail(got, t_new);
    taylor_[static_cast<std::size_t>(k)] = view(s.dky);
  }
  // a step that does not move t (t + h = t): the step size is below t's round-off, and no
  // number of such steps gets the run anywhere
  if (t_new == t()) {
    throw IntegrationError(
        describe("the step size fell below the round-off of t (t + h = t) at t = " +
                 detail::to_text(t_new)),
        t_new);
  }
  Eigen::VectorXd y_new = view(s.y);
  if (!y_new.allFinite()) {
    throw IntegrationError(describe("the state became non-finite at t = " + detail::to_text(t_new)),
                           t_new);
  }
  accept_step(t_new, y_new);
}

void CvodeBdf::interpolate(double t, Eigen::VectorXd& y_out) const {
  // Horner on Σ_k c_k s^k / k!, s = t − t().
  const double s = t - this->t();
  y_out = taylor_.back();
  for (int k = static_cast<int>(taylor_.size()) - 2; k >= 0; --k) {
    y_out = taylor_[static_cast<std::size_t>(k)] + (s / (k + 1)) * y_out;
  }
}

void CvodeBdf::fail(int flag, double t_at) {
  if (error_) {
    std::exception_ptr error = std::exchange(error_, nullptr);
    start_pending_ = true;
    std::rethrow_exception(error);
  }
  char* name = CVodeGetReturnFlagName(flag);
  std::string message = name != nullptr ? name : "CVODE error " + std::to_string(flag);
  std::free(name);
  if (solver_ && !solver_->message.empty()) message += " (" + solver_->message + ")";
  start_pending_ = true;
  throw IntegrationError(describe(message + " at t = " + detail::to_text(t_at)), t_at);
}

}  // namespace unidyn
