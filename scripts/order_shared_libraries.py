#!/usr/bin/python3
"""The shared libraries of a deal.II program in the order that makes its
start-up cheapest, for the linker (applications/CMakeLists.txt).

Why: a program linked with Debian's deal.II loads some 200 shared libraries
(Trilinos, PETSc, OpenCASCADE, Gmsh, ...) and the dynamic loader resolves
about 190,000 symbol references among them before main(). Each reference is
looked up in the libraries one after the other, in the order of the global
scope (the program, then its needed libraries breadth first), until one
defines the symbol: in the natural order a lookup visits 39 libraries on
average, and that walk is most of the 0.23 s a glissade process took to
start (doc/performance.md, "Start-up"). Listing the libraries that are
looked up most first shortens the walk without changing what is loaded.

What may move: the loader binds a symbol to its first definition in the
scope, so reordering must not change which definition that is, except where
the definitions are copies of one C++ entity (a template's instance, an
inline function, a vtable: weak symbols, one definition by the language's
rule). A symbol with a strong definition in two libraries keeps its order
(the library that defines it first stays before the other).

Usage: order_shared_libraries.py PROGRAM OUTPUT
PROGRAM is the program linked the usual way; OUTPUT becomes a response file
for the compiler driver that names its libraries in the new order
(`-Wl,--no-as-needed LIB ... -Wl,--as-needed`). OUTPUT is rewritten only
when its content changes (so that a relink follows only then), and is left
empty, which links the usual way, if a tool this needs is missing.
"""

import collections
import hashlib
import heapq
import os
import re
import subprocess
import sys

# Vague linkage in `nm -D`: weak (W, V) and unique (u) definitions.
WEAK_TYPES = set("WVu")


def run(arguments):
    return subprocess.run(arguments, capture_output=True, text=True,
                          check=True).stdout


def load_order(program):
    """The libraries `program` loads, in the order of the loader's global
    scope (ldd prints the link map in load order: breadth first)."""
    order = []
    for line in run(["ldd", program]).splitlines():
        match = re.match(r"\s*\S+ => (/\S+) \(0x", line)
        if match:
            path = os.path.realpath(match.group(1))
            if path not in order:
                order.append(path)
    return order


def defined_symbols(path):
    """{name: nm type} of the dynamic symbols `path` defines."""
    symbols = {}
    for line in run(["nm", "-D", "--defined-only", path]).splitlines():
        parts = line.split()
        if len(parts) >= 3:
            symbols[parts[2].split("@")[0]] = parts[1]
    return symbols


def startup_references(path):
    """{symbol: count} of the relocations the loader resolves by name when
    `path` is loaded: every symbol relocation but the lazy PLT slots
    (resolved at first call), unless the library asks to bind now."""
    dynamic = run(["readelf", "-dW", path])
    bind_now = "BIND_NOW" in dynamic or re.search(r"FLAGS.*\bNOW\b", dynamic)
    counts = collections.Counter()
    for line in run(["readelf", "-rW", path]).splitlines():
        parts = line.split()
        if len(parts) < 5 or not parts[2].startswith("R_"):
            continue
        if parts[2].endswith("JUMP_SLOT") and not bind_now:
            continue
        counts[parts[4].split("@")[0]] += 1
    return counts


def write_if_changed(path, text):
    try:
        with open(path) as existing:
            if existing.read() == text:
                return
    except OSError:
        pass
    with open(path + ".tmp", "w") as output:
        output.write(text)
    os.replace(path + ".tmp", path)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    program, output = sys.argv[1:]
    try:
        scope = [path for path in load_order(program)
                 if not os.path.basename(path).startswith("ld-linux")]
        # The same libraries give the same order: skip the 10 s of reading
        # them again (the key is this script, the scope and the libraries'
        # times).
        with open(__file__, "rb") as script:
            key = f"# {hashlib.sha256(script.read()).hexdigest()}\n"
        key += "".join(f"# {path} {os.stat(path).st_mtime_ns}\n"
                       for path in scope)
        try:
            with open(output + ".key") as previous:
                if previous.read() == key:
                    return
        except OSError:
            pass
        defines = {path: defined_symbols(path) for path in scope}
        references = {path: startup_references(path) for path in scope}
    except (OSError, subprocess.CalledProcessError) as error:
        print(f"order_shared_libraries.py: {error}; the usual link order",
              file=sys.stderr)
        write_if_changed(output, "")
        return
    position = {path: k for k, path in enumerate(scope)}

    definers = collections.defaultdict(list)
    for path in scope:
        for name in defines[path]:
            definers[name].append(path)

    # Lookups each library answers at start-up.
    answered = collections.Counter()
    for path in scope:
        for name, count in references[path].items():
            if name in definers:
                answered[min(definers[name], key=position.get)] += count

    # The order that a symbol defined twice imposes, whether it is looked
    # up at start-up or at a first call: its first definer stays before
    # the others, unless all are copies of one C++ entity.
    must_precede = collections.defaultdict(set)
    for name, candidates in definers.items():
        if len(candidates) < 2:
            continue
        first = min(candidates, key=position.get)
        for other in candidates:
            if other == first:
                continue
            if (name.startswith("_Z") and defines[first][name] in WEAK_TYPES
                    and defines[other][name] in WEAK_TYPES):
                continue
            must_precede[first].add(other)

    # The most asked first, within those constraints (a topological order).
    waiting = collections.Counter()
    for first, others in must_precede.items():
        for other in others:
            waiting[other] += 1
    ready = [(-answered[p], position[p], p) for p in scope if waiting[p] == 0]
    heapq.heapify(ready)
    order = []
    while ready:
        _, _, path = heapq.heappop(ready)
        order.append(path)
        for other in must_precede[path]:
            waiting[other] -= 1
            if waiting[other] == 0:
                heapq.heappush(ready, (-answered[other], position[other], other))
    if len(order) != len(scope):
        print("order_shared_libraries.py: the definitions' order has a "
              "cycle; the usual link order", file=sys.stderr)
        order = []
    write_if_changed(output, "-Wl,--no-as-needed\n" + "".join(
        f"{path}\n" for path in order) + "-Wl,--as-needed\n" if order else "")
    write_if_changed(output + ".key", key)


if __name__ == "__main__":
    main()
