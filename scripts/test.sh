#!/usr/bin/env bash
# Installs the dependencies, builds unidyn and runs every test with ctest.
# Usage: scripts/test.sh [--sanitize]   (--sanitize: under AddressSanitizer + UBSan)
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh test
build_dir=build
if [[ "${1:-}" == "--sanitize" ]]; then build_dir=build-sanitize; fi
bash scripts/build.sh "$@"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Under the sanitizers, the tests that check documents and long physics rather than new code paths
# are the plain run's: the docs' commands (108 s under the sanitizers; the command line's tests run
# the same code), the bicycle's benchmark eigenvalues and parameter sweeps, the Floquet tongues and
# CVODE's convergence study (100 s; shorter tests of each algorithm stay), the equations' texts in
# random layouts, pdflatex on the LaTeX forms and the progress notice that waits for its time (~70 s:
# texts, other programs and clocks).
excluded=()
if [[ "$build_dir" == build-sanitize ]]; then
  excluded=(-E '^(docs\.commands|cli\.GoldenEquations\.(RandomLayoutsGiveTheSameText|TheBicycleInAnyLayout|CodeAndRowsInAnyLayout)|cli\.LatexDocuments\.PdflatexCompiles(EveryForm|TheLinearisations)|cli\.ProgressNotices\.ALongCommandSaysItIsStillWorking|analysis\.(Linearization\.BicycleEigenvaluesAreTheBenchmarks|Floquet\.(MathieuTransitionCurves|DampingNarrowsAndClosesTheTongues)|ParameterSweep\.BicycleWeaveAndCapsizeSpeeds)|models\.CvodeRuns\.ConstrainedTopConvergesToDormandPrince)$')
fi
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" "${excluded[@]}"
