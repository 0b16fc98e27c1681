#!/usr/bin/env bash
# One error-suite case: `glint render` on a broken scene must exit with the expected code,
# print the expected first error line (file:line:col: error: message) followed by the source
# line and a caret, and leave no output file (not even a temporary one).
# Usage: run_error_case.sh GLINT CASES_DIR NAME OUT_DIR
set -euo pipefail
glint=$1 cases=$2 name=$3 out_root=$4

expected_file="$cases/$name.expected"
[[ -f $expected_file ]] || { echo "missing $expected_file"; exit 1; }
expected_line=$(sed -n 1p "$expected_file")
expected_exit=$(sed -n 2p "$expected_file" | sed -n 's/^exit \([0-9]*\)$/\1/p')
[[ -n $expected_exit ]] || { echo "$expected_file: line 2 must be 'exit N'"; exit 1; }

out="$out_root/$name"
rm -rf "$out"
mkdir -p "$out"
# Run from the cases folder with a relative scene path: messages name files as the user did.
cd "$cases"
set +e
"$glint" render "$name.pov" -o "$out/$name.png" --progress=none 2> "$out/stderr" > "$out/stdout"
rc=$?
set -e
stderr="$out/stderr"
fail=0
if [[ $rc != "$expected_exit" ]]; then
    echo "exit code $rc, expected $expected_exit"
    fail=1
fi
# The first error line (warnings may come before it).
line_no=$(grep -n -m1 ': error: ' "$stderr" | cut -d: -f1 || true)
if [[ -z $line_no ]]; then
    echo "no ': error: ' line on stderr"
    fail=1
else
    actual=$(sed -n "${line_no}p" "$stderr")
    if [[ $actual != "$expected_line" ]]; then
        echo "first error line differs"
        echo "  expected: $expected_line"
        echo "  actual:   $actual"
        fail=1
    fi
    source_line=$(sed -n "$((line_no + 1))p" "$stderr")
    caret_line=$(sed -n "$((line_no + 2))p" "$stderr")
    if [[ $source_line != "  "* ]]; then
        echo "no source line after the error line"
        fail=1
    fi
    if ! [[ $caret_line =~ ^[[:space:]]*\^$ ]]; then
        echo "no caret line after the source line"
        fail=1
    fi
fi
leftover=$(ls -A "$out" | grep -v -x -e stderr -e stdout || true)
if [[ -n $leftover ]]; then
    echo "output files left behind: $leftover"
    fail=1
fi
if [[ $fail != 0 ]]; then
    echo "--- stderr of: glint render $name.pov"
    cat "$stderr"
    exit 1
fi
echo "ok: $name (exit $rc)"
