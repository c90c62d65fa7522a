// `derive --format latex --standalone` is a document pdflatex compiles (-halt-on-error: any LaTeX
// error fails), for twelve bundled models by every method and in both forms. pdflatex comes from
// Debian's texlive-latex-base (scripts/setup.sh test); without it the test is skipped, saying so.
#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli_support.hpp"

namespace unidyn {
namespace {

using namespace cli_test;

bool have_pdflatex() {
  return std::system("command -v pdflatex >/dev/null 2>&1") == 0;
}

TEST(LatexDocuments, PdflatexCompilesEveryForm) {
#ifdef UNIDYN_SANITIZED
  // the documents are the same bytes in both builds; pdflatex's 20 s are spent once, in the plain
  // one
  GTEST_SKIP() << "pdflatex reads these documents in the plain build";
#endif
  if (!have_pdflatex()) GTEST_SKIP() << "pdflatex is not installed (texlive-latex-base)";
  const std::string directory = temp_path("latex");
  std::filesystem::create_directories(directory);
  for (const char* model : {"spherical-pendulum", "double-pendulum", "heavy-top", "rolling-disk",
                            "pendulum-cart", "kepler", "rotating-hoop", "helix", "chaplygin-car",
                            "two-body", "rotating-cone", "compound-pendulum"}) {
    for (const char* how :
         {"--method lagrange", "--method lagrange --form matrix", "--method lagrange --form zees",
          "--method newton-euler", "--method second-form"}) {
      const Outcome r =
          run("derive " + std::string(model) + " " + how + " --format latex --standalone");
      ASSERT_EQ(r.status, 0) << model << " " << how << ": " << r.err;
      EXPECT_TRUE(r.out.starts_with("\\documentclass{article}")) << r.out;
      write_file(directory + "/equations.tex", r.out);
      const std::string command = "cd '" + directory +
                                  "' && pdflatex -interaction=nonstopmode -halt-on-error "
                                  "equations.tex >compile.log 2>&1";
      EXPECT_EQ(std::system(command.c_str()), 0)
          << model << " " << how << ":\n"
          << read_file(directory + "/compile.log").substr(0, 3000);
    }
  }
  std::filesystem::remove_all(directory);
}

// `linearize` and `modes --format latex` (with M, C, K in closed form where there are) set in a
// document compile too.
TEST(LatexDocuments, PdflatexCompilesTheLinearisations) {
  if (!have_pdflatex()) GTEST_SKIP() << "pdflatex is not installed (texlive-latex-base)";
  const std::string directory = temp_path("latex-analysis");
  std::filesystem::create_directories(directory);
  for (const char* command :
       {"linearize sleeping-top --at 'der(gamma)=spin'", "modes double-pendulum --at theta1=0",
        "modes bicycle --at 'der(thR)=v/rR' 'der(phi)=0' 'der(delta)=0' 'der(psi)=0'",
        "linearize rotating-hoop --at 'phi=acos(-g/(R0*Omega^2))'",
        "linearize rolling-disk --at 'theta=pi/2' 'der(phi)=10'"}) {
    const Outcome r = run(std::string(command) + " --format latex");
    ASSERT_EQ(r.status, 0) << command << ": " << r.err;
    write_file(directory + "/linearised.tex",
               "\\documentclass{article}\n\\usepackage{amsmath}\n\\begin{document}\n" + r.out +
                   "\\end{document}\n");
    const std::string compile = "cd '" + directory +
                                "' && pdflatex -interaction=nonstopmode -halt-on-error "
                                "linearised.tex >compile.log 2>&1";
    EXPECT_EQ(std::system(compile.c_str()), 0)
        << command << ":\n"
        << read_file(directory + "/compile.log").substr(0, 3000);
  }
  std::filesystem::remove_all(directory);
}

// --standalone is for LaTeX only.
TEST(LatexDocuments, StandaloneNeedsLatex) {
  const Outcome r = run("derive double-pendulum --standalone");
  expect_bad_input(r, "--standalone without --format latex");
  EXPECT_TRUE(contains(r.err, "--standalone makes a LaTeX document")) << r.err;
}

}  // namespace
}  // namespace unidyn
