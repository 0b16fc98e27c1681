#!/usr/bin/env bash
# Runs the unit and error suites of a GLINT_SANITIZE=ON build (docs/testing.md "Sanitizers") and fails
# on any AddressSanitizer, LeakSanitizer or UBSan report. Reports go to files in
# BUILD/sanitizer-logs rather than to stderr, so that one from a glint process whose exit code a
# test does not look at (or whose stderr it swallows) still fails the run; every report found is
# printed at the end. Extra arguments go to ctest (e.g. -R pov_ to run fewer tests).
# Usage: tests/sanitize/run_suites.sh BUILD_DIR [ctest args...]
set -euo pipefail
build=$(cd "${1:?usage: run_suites.sh BUILD_DIR [ctest args...]}" && pwd)
shift
here=$(cd "$(dirname "$0")" && pwd)
logs=$build/sanitizer-logs
rm -rf "$logs"
mkdir -p "$logs"

# halt_on_error: the first report ends the process with a non-zero exit (UB is already fatal:
# -fno-sanitize-recover=undefined). Leak detection is on (ASan's default on Linux, made explicit).
# check_initialization_order catches static-initialisation-order bugs as well.
# intercept_tls_get_addr=0: with it on, clang 14's LeakSanitizer crashes in its own tracer at
# the exit of a process that has dlopen()ed a library with thread-local storage (glint loads
# OpenImageIO as a module) while other threads live ("Tracer caught signal 11 ... LeakSanitizer
# has encountered a fatal error": ReportCli.WritesCsvPlotAndSummaryWithAPeer, every time with
# both cores busy; a runtime bug fixed in later LLVM). Off, dynamic TLS is simply not scanned
# as a root, which could only add false leak reports, never hide one.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:intercept_tls_get_addr=0:print_stacktrace=1:check_initialization_order=1:strict_init_order=1:detect_odr_violation=2:log_path=$logs/report"
export LSAN_OPTIONS="print_suppressions=0:suppressions=$here/lsan.supp"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:log_path=$logs/report"

status=0
ctest --test-dir "$build" --output-on-failure -j2 -L "unit|errors" "$@" || status=$?

if compgen -G "$logs/*" > /dev/null; then
    echo "sanitizer reports ($(ls "$logs" | wc -l) processes):"
    for f in "$logs"/*; do
        echo "==== $f"
        cat "$f"
    done
    status=1
fi
exit $status
