#!/bin/bash
# Fuzzes the case files' list grammar and the closed forms it names (tests/fuzz/grammar_fuzz.cc)
# with libFuzzer (clang, Debian package 'clang'), AddressSanitizer and UBSan.
#   bash tests/fuzz/run_fuzz.sh [RUNS]      # default 100000 inputs; exit 0 when nothing was found
# The seed corpus in tests/fuzz/corpus (entries from the shipped cases) is kept; inputs the run
# finds interesting go to a scratch copy, crashes to tests/fuzz/crash-* (a reproducer to keep).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
runs="${1:-100000}"
command -v clang++ > /dev/null || { echo "run_fuzz.sh: clang++ missing (apt-get install clang)" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -I "$root/solver/fe" -I "$root/solver" \
  "$here/grammar_fuzz.cc" "$root/solver/fe/input/spec_list.cc" "$root"/solver/closed_forms/*.cc \
  -o "$work/grammar_fuzz"
cp -r "$here/corpus" "$work/corpus"
cd "$here"
"$work/grammar_fuzz" -runs="$runs" -max_len=512 -timeout=10 -artifact_prefix="$here/" "$work/corpus" 2>&1 | tail -5
