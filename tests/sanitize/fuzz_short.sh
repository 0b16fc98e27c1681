#!/usr/bin/env bash
# CI's short fuzz check (fuzz/README.md "Short check (CI)"): each libFuzzer target of a
# GLINT_FUZZ=ON build runs SECONDS (default 60) from the seed corpus that fuzz/make_corpus.sh
# gathers, and the first finding (crash, sanitizer report, leak, an input slower than 10 s,
# more than 2 GiB) fails the check; the input is left in BUILD/fuzz-ci/art/TARGET/.
# The targets write a file per input under $TMPDIR: /dev/shm keeps that off the disk.
# Usage: tests/sanitize/fuzz_short.sh BUILD_DIR [SECONDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:?usage: fuzz_short.sh BUILD_DIR [SECONDS]}" && pwd)
seconds=${2:-60}
if [[ -d /dev/shm && -w /dev/shm ]]; then export TMPDIR=/dev/shm; fi
# Leaks are findings too (libFuzzer checks for them when the inputs run leak-free otherwise).
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:print_stacktrace=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"

work=$build/fuzz-ci
rm -rf "$work"
"$root/fuzz/make_corpus.sh" "$work/corpus"
status=0
for t in pov expr obj mtl; do
    dict=()
    case $t in pov|expr) dict=(-dict="$root/fuzz/pov.dict") ;; esac
    mkdir -p "$work/new/$t" "$work/art/$t"
    echo "== fuzz_$t: ${seconds} s"
    if ! "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
            -max_len=4096 "${dict[@]}" -print_final_stats=1 -artifact_prefix="$work/art/$t/" \
            "$work/new/$t" "$work/corpus/$t" 2> "$work/fuzz_$t.log"; then
        echo "fuzz_$t: FINDING (inputs in $work/art/$t/):"
        tail -n 60 "$work/fuzz_$t.log"
        status=1
    else
        grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb|^(#[0-9]+ +)?DONE' \
            "$work/fuzz_$t.log" || true
    fi
done
exit $status
