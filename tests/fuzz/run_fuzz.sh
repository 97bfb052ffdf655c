#!/bin/bash
# Fuzzing with libFuzzer (clang, Debian package 'clang'), AddressSanitizer and UBSan.
#   bash tests/fuzz/run_fuzz.sh [grammar] [RUNS]   # the list grammar and the closed forms it names
#                                                  # (tests/fuzz/grammar_fuzz.cc); default 100000
#   bash tests/fuzz/run_fuzz.sh case [RUNS]        # whole case files through read_case
#                                                  # (tests/fuzz/case_reader_fuzz.cc); needs build/
# Exit 0 when nothing was found. Seed corpora: tests/fuzz/corpus (list entries from the shipped
# cases) for grammar; every shipped .prm plus tests/fuzz/case_corpus (hostile files: BOM, CRLF,
# binary, empty) for case. They are kept; inputs a run finds interesting go to a scratch copy,
# crashes to tests/fuzz/crash-* (a reproducer to keep). The case target checks no leaks: gmsh
# leaks a few bytes per gmsh::initialize (strsave), not ours.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
target="grammar"
if [ "${1:-}" = "case" ] || [ "${1:-}" = "grammar" ]; then target="$1"; shift; fi
runs="${1:-100000}"
command -v clang++ > /dev/null || { echo "run_fuzz.sh: clang++ missing (apt-get install clang)" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
sanitize="-fsanitize=address,undefined -fno-sanitize-recover=undefined"
if [ "$target" = "grammar" ]; then
  clang++ -std=c++17 -g -O1 -fsanitize=fuzzer $sanitize \
    -I "$root/solver/fe" -I "$root/solver" \
    "$here/grammar_fuzz.cc" "$root/solver/fe/input/spec_list.cc" "$root"/solver/closed_forms/*.cc \
    -o "$work/grammar_fuzz"
  cp -r "$here/corpus" "$work/corpus"
  cd "$here"
  status=0
  "$work/grammar_fuzz" -runs="$runs" -max_len=512 -timeout=10 -artifact_prefix="$here/" "$work/corpus" \
    > "$work/log" 2>&1 || status=$?
  tail -5 "$work/log"
  exit "$status"
fi

# case: the reader and the list grammar instrumented; the rest of the solver library as built.
build="$root/build/solver/fe"
[ -f "$build/libcompliant_fe.a" ] || { echo "run_fuzz.sh: build the solver first (bash scripts/setup.sh build)" >&2; exit 2; }
includes="$(sed -n 's/^CXX_INCLUDES = //p' "$build/CMakeFiles/compliant_fe.dir/flags.make")"
flags="-std=c++17 -g -O1 $sanitize -DBOOST_NO_AUTO_PTR -DNDEBUG -DCOMPLIANT_SOURCE_DIR=\"$root\" $includes"
clang++ $flags -fsanitize=fuzzer -c "$here/case_reader_fuzz.cc" -o "$work/harness.o"
clang++ $flags -fsanitize=fuzzer-no-link -c "$root/solver/fe/input/case_file.cc" -o "$work/case_file.o"
clang++ $flags -fsanitize=fuzzer-no-link -c "$root/solver/fe/input/spec_list.cc" -o "$work/spec_list.o"
(cd "$build" && clang++ -fsanitize=fuzzer $sanitize "$work/harness.o" "$work/case_file.o" "$work/spec_list.o" \
  $(sed 's/.*-o compliant //' CMakeFiles/compliant.dir/link.txt) -o "$work/case_fuzz")
mkdir -p "$work/corpus"
cp "$here"/case_corpus/* "$work/corpus/"
n=0
while IFS= read -r f; do n=$((n + 1)); cp "$f" "$work/corpus/shipped_$n.prm"; done \
  < <(find "$root/cases" "$root/tests/cases" -name '*.prm' | sort)
cd "$here"
status=0
ASAN_OPTIONS=detect_leaks=0:quarantine_size_mb=16 "$work/case_fuzz" -runs="$runs" -max_len=4096 -timeout=20 -detect_leaks=0 -rss_limit_mb=6000 \
  -artifact_prefix="$here/" "$work/corpus" > "$work/log" 2>&1 || status=$?
grep -E "^#[0-9]+|^Done|ERROR|deadly|crash|timeout" "$work/log" | tail -5 || true
exit "$status"
