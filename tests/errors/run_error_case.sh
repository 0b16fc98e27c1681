#!/usr/bin/env bash
# One error-suite case: `glint render` on a broken scene must exit with the expected code,
# print the expected first error line (file:line:col: error: message) followed by the source
# line and a caret, and leave no output file (not even a temporary one).
# A case whose expectation is a warning (`file:line:col: warning: ...`, exit 0) must print that
# warning first and render: the output file must then exist.
# The scene is cases/NAME.pov or cases/NAME.obj; cases/NAME.args, when present, holds extra
# command-line flags (one line, split on spaces).
# Usage: run_error_case.sh GLINT CASES_DIR NAME OUT_DIR
set -euo pipefail
glint=$1 cases=$2 name=$3 out_root=$4

expected_file="$cases/$name.expected"
[[ -f $expected_file ]] || { echo "missing $expected_file"; exit 1; }
expected_line=$(sed -n 1p "$expected_file")
expected_exit=$(sed -n 2p "$expected_file" | sed -n 's/^exit \([0-9]*\)$/\1/p')
[[ -n $expected_exit ]] || { echo "$expected_file: line 2 must be 'exit N'"; exit 1; }
scene="$name.pov"
[[ -f $cases/$scene ]] || scene="$name.obj"
[[ -f $cases/$scene ]] || { echo "no $name.pov or $name.obj in $cases"; exit 1; }
extra=()
[[ -f $cases/$name.args ]] && read -r -a extra < "$cases/$name.args"

severity=error
[[ $expected_line =~ (^|: )warning:\  ]] && severity=warning
# What the location in the expected line promises: a source line when it has a line number,
# a caret under it when it also has a column (errors from the command line have neither).
has_line=0 has_column=0
if [[ $expected_line =~ ^[^:]+:([0-9]+):([0-9]+|\{col\}):\  ]]; then
    [[ ${BASH_REMATCH[1]} != 0 ]] && has_line=1
    [[ $has_line == 1 && ${BASH_REMATCH[2]} != 0 ]] && has_column=1
elif [[ $expected_line =~ ^[^:]+:([0-9]+):\  ]]; then
    [[ ${BASH_REMATCH[1]} != 0 ]] && has_line=1
fi

out="$out_root/$name"
rm -rf "$out"
mkdir -p "$out"
# Run from the cases folder with a relative scene path: messages name files as the user did.
cd "$cases"
set +e
timeout 30 "$glint" render "$scene" -o "$out/$name.png" --progress=none "${extra[@]}" \
    2> "$out/stderr" > "$out/stdout"
rc=$?
set -e
stderr="$out/stderr"
fail=0
if [[ $rc != "$expected_exit" ]]; then
    echo "exit code $rc, expected $expected_exit"
    fail=1
fi
# The first error (or, for a warning case, warning) line; warnings may come before an error.
line_no=$(grep -n -m1 -E "(^|: )$severity: " "$stderr" | cut -d: -f1 || true)
if [[ -z $line_no ]]; then
    echo "no '$severity: ' line on stderr"
    fail=1
else
    actual=$(sed -n "${line_no}p" "$stderr")
    # `{col}` in the expectation stands for any column (the deep_* cases stop where the
    # parser's stack budget runs out, which depends on the compiler's frame sizes).
    if [[ $expected_line == *"{col}"* ]]; then
        actual=$(sed -E 's/^([^:]+:[0-9]+:)[0-9]+:/\1{col}:/' <<< "$actual")
    fi
    if [[ $actual != "$expected_line" ]]; then
        echo "first $severity line differs"
        echo "  expected: $expected_line"
        echo "  actual:   $actual"
        fail=1
    fi
    source_line=$(sed -n "$((line_no + 1))p" "$stderr")
    caret_line=$(sed -n "$((line_no + 2))p" "$stderr")
    if [[ $has_line == 1 && $source_line != "  "* ]]; then
        echo "no source line after the $severity line"
        fail=1
    fi
    if [[ $has_column == 1 ]] && ! [[ $caret_line =~ ^[[:space:]]*\^$ ]]; then
        echo "no caret line after the source line"
        fail=1
    fi
fi
leftover=$(ls -A "$out" | grep -v -x -e stderr -e stdout || true)
if [[ $severity == error && -n $leftover ]]; then
    echo "output files left behind: $leftover"
    fail=1
fi
if [[ $severity == warning && $leftover != "$name.png" ]]; then
    echo "a warning must not stop the render: expected $name.png alone, found: ${leftover:-nothing}"
    fail=1
fi
if [[ $fail != 0 ]]; then
    echo "--- stderr of: glint render $scene ${extra[*]}"
    cat "$stderr"
    exit 1
fi
echo "ok: $name (exit $rc)"
