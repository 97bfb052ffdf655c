#!/usr/bin/env python3
"""The order in which the `compliant` executable names its shared libraries, for a faster start.

Debian's deal.II loads about 200 shared libraries (Trilinos, PETSc, OpenCASCADE through gmsh, ...).
The dynamic loader resolves each of their ~330k symbol references by walking the global scope
(the executable, then its libraries breadth-first) until one defines the symbol: on average 38
libraries deep with the order the linker leaves, 0.1 s of every process start on this machine.
Naming the libraries in the executable in order of how many references they resolve makes the
walk ~3 times shorter.

A symbol defined by several libraries binds to the first in the scope, so reordering could change
which definition wins (BLAS routines in libblas.so.3 and libopenblas.so.0, copysign in libm and
libc, template instances in many C++ libraries). The order is therefore a topological one: every
library that wins a symbol today stays ahead of every other library defining it, except for C++
symbols that every definer defines weak (template instances and inline functions, the same code in
each library by the one-definition rule).
`case.library_order_bindings` checks the result: the same binding for every symbol.

Usage: library_order.py PLAIN_EXECUTABLE OUTPUT_RESPONSE_FILE
  PLAIN_EXECUTABLE: the executable linked in the default order (it is run once with --help).
  Writes the libraries' paths in the new order, one per line, as a linker response file. Any
  failure writes an empty file (the default order) and says why on stderr: never a failed build.
"""
import collections
import heapq
import os
import re
import subprocess
import sys


def loader_report(executable):
    """The global scope and the number of references each library resolves (all bound now)."""
    env = dict(os.environ, LD_DEBUG="scopes,bindings", LD_BIND_NOW="1")
    env.pop("LD_DEBUG_OUTPUT", None)
    run = subprocess.run([executable, "--help"], env=env, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, text=True, errors="replace", timeout=120)
    scope, counts = None, collections.Counter()
    binding = re.compile(r"binding file \S+ \[\d+\] to (\S+) \[\d+\]")
    for line in run.stderr.splitlines():
        if scope is None and "scope 0:" in line:
            scope = line.split("scope 0:", 1)[1].split()
            continue
        match = binding.search(line)
        if match:
            counts[match.group(1)] += 1
    if not scope:
        raise RuntimeError("the loader printed no global scope")
    return scope, counts


def interchangeable(name, kind):
    """A C++ symbol every definer defines weak (a template instance or inline function, emitted
    alike in each library that uses it, by the one-definition rule): any definer will do."""
    return name.startswith("_Z") and kind in "VWuvw"


def defined_symbols(library):
    """The dynamic symbols a library defines (version suffixes dropped: conservative), each with
    whether it is an interchangeable weak C++ definition."""
    out = subprocess.run(["nm", "-D", "--defined-only", "--format=posix", library],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                         errors="replace", timeout=120)
    if out.returncode != 0:
        raise RuntimeError("nm failed on " + library)
    symbols = {}
    for line in out.stdout.splitlines():
        fields = line.split()
        if len(fields) >= 2:
            name = fields[0].split("@", 1)[0]
            symbols[name] = symbols.get(name, True) and interchangeable(name, fields[1])
    return symbols


def ordered(scope, counts):
    """Libraries most referenced first, each winner ahead of the other definers of its symbols."""
    libraries = scope[1:]  # the executable stays first
    definers = collections.defaultdict(list)  # symbol -> its definers in scope order
    weak_everywhere = {}
    for library in libraries:
        for symbol, weak in defined_symbols(library).items():
            definers[symbol].append(library)
            weak_everywhere[symbol] = weak_everywhere.get(symbol, True) and weak
    must_follow = collections.defaultdict(set)  # winner -> libraries that must come after it
    for symbol, libs in definers.items():
        if len(libs) > 1 and not weak_everywhere[symbol]:
            must_follow[libs[0]].update(libs[1:])
    waiting = collections.Counter()
    for winner, later in must_follow.items():
        for library in later:
            waiting[library] += 1
    position = {library: i for i, library in enumerate(libraries)}
    ready = [(-counts[lib], position[lib], lib) for lib in libraries if waiting[lib] == 0]
    heapq.heapify(ready)
    order = []
    while ready:
        _, _, library = heapq.heappop(ready)
        order.append(library)
        for later in must_follow[library]:
            waiting[later] -= 1
            if waiting[later] == 0:
                heapq.heappush(ready, (-counts[later], position[later], later))
    if len(order) != len(libraries):
        raise RuntimeError("the definers' constraints form a cycle")
    return order, position


def mean_depth(order, counts):
    total = sum(counts.values())
    return sum(counts[lib] * (i + 2) for i, lib in enumerate(order)) / max(total, 1)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    executable, response = sys.argv[1], sys.argv[2]
    lines = []
    try:
        scope, counts = loader_report(executable)
        order, position = ordered(scope, counts)
        before = mean_depth(sorted(order, key=position.get), counts)
        after = mean_depth(order, counts)
        lines = [path for path in order if os.path.isfile(path)]
        if len(lines) != len(order):
            raise RuntimeError("a library of the scope is not a file")
        print(f"library order: {len(order)} libraries, references resolved {before:.1f} -> "
              f"{after:.1f} libraries deep", file=sys.stderr)
    except Exception as error:  # the default order: slower, never wrong
        lines = []
        print(f"library order: kept the linker's ({error})", file=sys.stderr)
    with open(response, "w") as out:
        out.write("".join(line + "\n" for line in lines))


if __name__ == "__main__":
    main()
