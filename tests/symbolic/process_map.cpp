// f over many expressions in forked processes (symbolic/process_map.hpp): the results are f's own,
// in order, however many processes share the work; failures are raised as without them.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdlib>

#include "support/random_expressions.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/process_map.hpp"
#include "unidyn/symbolic/textbook_form.hpp"
#include "unidyn/symbolic/zero_test.hpp"

namespace unidyn {
namespace {

// UNIDYN_PROCESSES set for one scope.
struct Processes {
  explicit Processes(const char* n) { ::setenv("UNIDYN_PROCESSES", n, 1); }
  ~Processes() { ::unsetenv("UNIDYN_PROCESSES"); }
};

// Expressions with sines and cosines of angle sums, as the book's equations have them.
std::vector<Expr> trigonometric_sums(int count) {
  using test::L;
  using test::m;
  using test::q1;
  using test::q2;
  std::vector<Expr> out;
  for (int k = 1; k <= count; ++k) {
    out.push_back(m * L * L *
                  (GiNaC::sin(q1 + k * q2) * GiNaC::sin(q1) +
                   GiNaC::cos(q1) * GiNaC::cos(q1 + k * q2) + k * GiNaC::pow(GiNaC::sin(q2), 2) +
                   k * GiNaC::pow(GiNaC::cos(q2), 2)));
  }
  return out;
}

Expr simplified_here(const Expr& e) {
  return simplify(e);
}

TEST(ProcessMap, ResultsAreTheFunctionsOwnInOrder) {
  const std::vector<Expr> inputs = trigonometric_sums(12);
  std::vector<Expr> serial;
  for (const Expr& e : inputs) serial.push_back(simplify(e));
  for (const char* n : {"1", "2", "5"}) {
    const Processes processes(n);
    const std::vector<Expr> shared = map_in_processes(inputs, simplified_here);
    ASSERT_EQ(shared.size(), inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      EXPECT_TRUE(shared[i].is_equal(serial[i])) << n << " processes, " << i;
    }
  }
}

TEST(ProcessMap, TextbookFormsEqualTheInputsAndCombineAngleSums) {
  const std::vector<Expr> inputs = trigonometric_sums(8);
  const Processes processes("2");
  const std::vector<Expr> all = textbook_simplify_all(inputs);
  ASSERT_EQ(all.size(), inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    EXPECT_EQ(vanishes_identically(all[i] - inputs[i]), true) << i;
    // sin q1 sin(q1 + k q2) + cos q1 cos(q1 + k q2) = cos(k q2): no sin q1 or cos q1 left
    EXPECT_FALSE(all[i].has(GiNaC::sin(test::q1)) || all[i].has(GiNaC::cos(test::q1))) << all[i];
  }
}

// e, plus 1 when computed by a copy of the process (slowly: 20 ms each, so that every copy starts
// before the queue is empty).
pid_t parent_pid = 0;
Expr marked_by_copies(const Expr& e) {
  ::usleep(20000);
  return ::getpid() == parent_pid ? e : e + 1;
}

TEST(ProcessMap, TheCopiesShareTheWork) {
  parent_pid = ::getpid();
  const std::vector<Expr> inputs = trigonometric_sums(10);
  const Processes processes("2");
  const std::vector<Expr> results = map_in_processes(inputs, marked_by_copies);
  int by_copies = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const bool copied = results[i].is_equal(inputs[i] + 1);
    EXPECT_TRUE(copied || results[i].is_equal(inputs[i])) << i;
    by_copies += copied ? 1 : 0;
  }
  EXPECT_GE(by_copies, 2);
  EXPECT_LE(by_copies, 8);
}

// Fails on the inputs that hold u; the others map to themselves.
Expr fails_on_u(const Expr& e) {
  if (e.has(test::u)) throw std::runtime_error("u in " + to_text(e));
  return e;
}

TEST(ProcessMap, TheFirstFailureInOrderIsRaised) {
  const std::vector<Expr> inputs{test::q1, test::u * 2, test::q2, test::u * 3, test::m};
  const Processes processes("3");
  try {
    map_in_processes(inputs, fails_on_u);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "u in 2*u");
  }
}

TEST(ProcessMap, ProcessesAsGivenOrRefused) {
  {
    const Processes processes("3");
    EXPECT_EQ(worker_processes(), 3u);
  }
  for (const char* bad : {"0", "-2", "two", "2x", ""}) {
    const Processes processes(bad);
    EXPECT_THROW(worker_processes(), std::invalid_argument) << bad;
  }
  EXPECT_GE(worker_processes(), 1u);
}

}  // namespace
}  // namespace unidyn
