#!/usr/bin/env python3
"""The executable whose libraries are named in a faster order (solver/fe/app/library_order.py)
binds every symbol reference to the same definition as the one linked in the linker's order.

Both are started (alone, and as one rank under mpirun, which loads other Open MPI components)
with every reference bound at once (LD_BIND_NOW) and the loader's bindings compared: each (referencing object, symbol) must go to the same library, except C++ symbols that
both definers define weak (template instances and inline functions: the same code by the
one-definition rule), and such a symbol must still be bound to one copy only. Also asserted: the
reordered scope is shorter to walk (mean depth of a resolved reference), both executables exit 0
and print the same --help.

Usage: library_order_bindings.py ORDERED PLAIN
"""
import collections
import os
import re
import subprocess
import sys
import tempfile

BINDING = re.compile(r"binding file (\S+) \[\d+\] to (\S+) \[\d+\]: \S+ symbol `([^']+)'(?: \[([^\]]+)\])?")


def parse(text, executable, result, scopes):
    me = os.path.realpath(executable)
    normal = lambda path: "EXE" if os.path.realpath(path) == me else path
    for line in text.splitlines():
        if "scope 0:" in line and not scopes:
            scopes.append([normal(p) for p in line.split("scope 0:", 1)[1].split()])
        match = BINDING.search(line)
        if match:
            symbol = match.group(3) + ("@" + match.group(4) if match.group(4) else "")
            result[(normal(match.group(1)), symbol)] = normal(match.group(2))


def bindings(executable):
    """Every binding of `executable --help` alone and of one rank under mpirun (which loads other
    Open MPI components), with everything bound at load."""
    env = dict(os.environ, LD_DEBUG="scopes,bindings", LD_BIND_NOW="1")
    for name in ("LD_DEBUG_OUTPUT", "LD_PRELOAD", "LD_AUDIT"):
        env.pop(name, None)
    run = subprocess.run([executable, "--help"], env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, errors="replace", timeout=300)
    result, scopes = {}, []
    parse(run.stderr, executable, result, scopes)
    with tempfile.TemporaryDirectory() as out:
        ranked = subprocess.run(["mpirun", "-np", "1", "-x", "LD_DEBUG=scopes,bindings", "-x", "LD_BIND_NOW=1",
                                 "-x", "LD_DEBUG_OUTPUT=" + os.path.join(out, "rank"), executable, "--help"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, errors="replace",
                                timeout=300)
        for name in os.listdir(out):
            with open(os.path.join(out, name), errors="replace") as log:
                parse(log.read(), executable, result, [])
    return result, scopes[0] if scopes else None, run.stdout, run.returncode + ranked.returncode


def weak_definitions(library, cache={}):
    if library not in cache:
        out = subprocess.run(["nm", "-D", "--defined-only", "--format=posix", library],
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                             errors="replace")
        cache[library] = {f[0].split("@", 1)[0] for f in (l.split() for l in out.stdout.splitlines())
                          if len(f) >= 2 and f[1] in "VWuvw"}
    return cache[library]


def mean_depth(result, scope):
    depth = {lib: i for i, lib in enumerate(scope)}
    return sum(depth[t] for t in result.values() if t in depth) / max(len(result), 1)


def main():
    ordered, plain = sys.argv[1], sys.argv[2]
    new, new_scope, new_help, new_code = bindings(ordered)
    old, old_scope, old_help, old_code = bindings(plain)
    failures = []
    if new_code or old_code:
        failures.append(f"--help exited with {new_code} (ordered) and {old_code} (plain)")
    if len(old) < 1000 or not new_scope or not old_scope:
        failures.append(f"too few bindings read ({len(old)}): LD_DEBUG did not report")
    if new_help != old_help:
        failures.append("--help differs")
    if set(new_scope) != set(old_scope):
        failures.append(f"different libraries loaded: {sorted(set(new_scope) ^ set(old_scope))[:5]}")
    moved = collections.Counter()
    for key, target in old.items():
        other = new.get(key)
        if other is None:
            failures.append(f"{key} not bound in the reordered executable")
        elif other != target:
            symbol = key[1].split("@", 1)[0]
            if symbol.startswith("_Z") and "EXE" not in (target, other) and \
                    symbol in weak_definitions(target) and symbol in weak_definitions(other):
                moved[(target, other)] += 1
            else:
                failures.append(f"{key[0]}: {symbol} bound to {other}, was {target}")
    # A moved weak symbol still has one copy in use: every reference binds to the same library.
    def copies(result):
        targets = collections.defaultdict(set)
        for (_, symbol), target in result.items():
            targets[symbol].add(target)
        return {symbol for symbol, where in targets.items() if len(where) > 1}
    for symbol in sorted(copies(new) - copies(old))[:5]:
        failures.append(f"{symbol} is now bound to two copies")
    before, after = mean_depth(old, old_scope), mean_depth(new, new_scope)
    print(f"{len(old)} bindings; {sum(moved.values())} weak C++ instances bound to another copy; "
          f"mean depth {before:.1f} -> {after:.1f}")
    if after > 0.8 * before:
        failures.append(f"the reordered scope is not shorter ({before:.1f} -> {after:.1f})")
    for failure in failures[:20]:
        print("FAIL:", failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
