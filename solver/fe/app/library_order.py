#!/usr/bin/env python3
"""The order in which the `compliant` executable names its shared libraries, for a faster start.

Debian's deal.II loads about 200 shared libraries (Trilinos, PETSc, OpenCASCADE through gmsh, ...).
The dynamic loader resolves each of their ~330k symbol references by walking the global scope
(the executable, then its libraries breadth-first) until one defines the symbol: on average 32
libraries deep with the order the linker leaves, most of `compliant --help`'s 0.4-0.5 s. Naming the
libraries in the executable in order of how many references they resolve, as far as the rule
below allows, makes it 24 deep and the start about 0.06 s shorter (README, Speed).

A symbol defined by several libraries binds to the first in the scope, so reordering could change
which definition wins (BLAS routines in libblas.so.3 and libopenblas.so.0, copysign in libm and
libc, template instances in many C++ libraries). The order is therefore a topological one: every
library defining a symbol keeps its place relative to the other definers (so the winner stays the
winner), except for C++ symbols that every definer defines weak with one size, none linked
-Bsymbolic (template instances, inline functions, typeinfo: the same code in each library by the
one-definition rule). The libraries' initialisers may run in another order among libraries that do
not depend on each other, which ELF leaves open anyway.
`case.library_order_bindings` checks the result: the same binding for every symbol.

Usage: library_order.py PLAIN_EXECUTABLE OUTPUT_RESPONSE_FILE OUTPUT_DEPFILE
  PLAIN_EXECUTABLE: the executable linked in the default order (it is run once with --help).
  Writes the libraries' paths in the new order, one per line, as a linker response file, and a
  make depfile naming them (an updated library orders again). Any failure writes an empty file
  (the default order) and says why on stderr: never a failed build.
"""
import collections
import heapq
import os
import re
import signal
import subprocess
import sys


def loader_report(executable):
    """The global scope and the number of references each library resolves (all bound now).
    The environment's preloads and library path are dropped: only the executable's own
    dependencies may enter the order."""
    env = dict(os.environ, LD_DEBUG="scopes,bindings", LD_BIND_NOW="1")
    for name in ("LD_DEBUG_OUTPUT", "LD_PRELOAD", "LD_AUDIT", "LD_LIBRARY_PATH"):
        env.pop(name, None)
    child = subprocess.Popen([executable, "--help"], env=env, stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True, errors="replace", start_new_session=True)
    try:
        _, stderr = child.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        os.killpg(child.pid, signal.SIGKILL)  # with anything it started that holds stderr open
        child.communicate()
        raise RuntimeError(executable + " --help did not finish in 120 s")
    scope, counts = None, collections.Counter()
    binding = re.compile(r"binding file \S+ \[\d+\] to (\S+) \[\d+\]")
    for line in stderr.splitlines():
        if scope is None and "scope 0:" in line:
            scope = line.split("scope 0:", 1)[1].split()
            continue
        match = binding.search(line)
        if match:
            counts[match.group(1)] += 1
    if not scope:
        raise RuntimeError("the loader printed no global scope")
    return scope, counts


def defined_symbols(library):
    """The dynamic symbols a library defines: name (any version) -> (nm type, size); a name
    defined in several versions counts as strong (conservative)."""
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
            symbols[name] = ("T", "") if name in symbols else (fields[1], fields[3] if len(fields) >= 4 else "")
    return symbols


def binds_to_itself(library):
    """Whether the library was linked -Bsymbolic: its own references skip the global scope."""
    out = subprocess.run(["readelf", "-d", library], stdout=subprocess.PIPE,
                         stderr=subprocess.DEVNULL, text=True, errors="replace", timeout=120)
    return re.search(r"\(SYMBOLIC\)|Flags:.*\bSYMBOLIC\b", out.stdout) is not None


def interchangeable(symbol, definitions):
    """A C++ symbol (template instance, inline function, typeinfo) that every definer defines weak,
    none of them -Bsymbolic, objects of one size everywhere: the same code or object in each library
    by the one-definition rule, so any definer will do. (A function's size differs with the
    compiler's inlining in each library; an object's would mean another layout.)"""
    objects = {size for kind, size, _ in definitions if kind in "Vvu"}
    return symbol.startswith("_Z") and len(objects) <= 1 and \
        all(kind in "VWuvw" and not symbolic for kind, _, symbolic in definitions)


def ordered(scope, counts):
    """Libraries most referenced first, each definer of a symbol in its place among the others."""
    libraries = scope[1:]  # the executable stays first
    definers = collections.defaultdict(list)  # symbol -> its definers in scope order
    definitions = collections.defaultdict(list)
    for library in libraries:
        symbolic = binds_to_itself(library)
        for symbol, (kind, size) in defined_symbols(library).items():
            definers[symbol].append(library)
            definitions[symbol].append((kind, size, symbolic))
    # Every definer keeps its place relative to the others: the winner stays the winner, and so
    # does the next one for a lookup that skips it (dlsym(RTLD_NEXT), another version).
    must_follow = collections.defaultdict(set)  # library -> libraries that must come after it
    for symbol, libs in definers.items():
        if len(libs) > 1 and not interchangeable(symbol, definitions[symbol]):
            for earlier, later in zip(libs, libs[1:]):
                must_follow[earlier].add(later)
    waiting = collections.Counter()
    for earlier, later in must_follow.items():
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
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    executable, response, depfile = sys.argv[1], sys.argv[2], sys.argv[3]
    lines = []
    try:
        scope, counts = loader_report(executable)
        preloaded = set()
        if os.path.isfile("/etc/ld.so.preload"):
            with open("/etc/ld.so.preload") as preload:
                preloaded = {os.path.realpath(p) for p in preload.read().split()}
        scope = [lib for lib in scope if os.path.realpath(lib) not in preloaded]
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
    # A library updated or switched (update-alternatives) orders again at the next build.
    with open(depfile, "w") as out:
        out.write(response.replace(" ", "\\ ") + ": " + " ".join(line.replace(" ", "\\ ") for line in lines) + "\n")


if __name__ == "__main__":
    main()
