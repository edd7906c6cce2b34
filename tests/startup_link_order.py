#!/usr/bin/python3
"""glissade, linked with its shared libraries in the order that starts it
fastest (scripts/order_shared_libraries.py), binds every symbol reference
of every library to the definition the usual link binds it to, except
where both definitions are copies of one C++ entity (weak definitions of
a template's instance, an inline function or a vtable, which the language
makes one).

The dynamic loader reports each binding (LD_DEBUG=bindings); LD_BIND_NOW
makes it bind the references that would wait for a first call too, so the
comparison covers all of them.

Usage: startup_link_order.py USUAL_PROGRAM ORDERED_PROGRAM WORK_DIRECTORY
"""

import functools
import os
import re
import subprocess
import sys

BINDING = re.compile(
    r"binding file (\S+) \[\d+\] to (\S+) \[\d+\]: normal symbol `([^']+)'")


def bindings(program, work, tag):
    """{(referencing object, symbol): defining object} at `--version`."""
    prefix = os.path.join(work, tag)
    for name in os.listdir(work):
        if name.startswith(tag + "."):
            os.remove(os.path.join(work, name))
    environment = dict(os.environ, LD_DEBUG="bindings", LD_BIND_NOW="1",
                       LD_DEBUG_OUTPUT=prefix)
    subprocess.run([program, "--version"], env=environment, check=True,
                   stdout=subprocess.DEVNULL)
    found = {}
    for name in os.listdir(work):
        if not name.startswith(tag + "."):
            continue
        with open(os.path.join(work, name)) as log:
            for line in log:
                match = BINDING.search(line)
                if match:
                    # The program itself under either name.
                    user, definer, symbol = match.groups()
                    user = "program" if user == program else user
                    definer = "program" if definer == program else definer
                    found[(user, symbol)] = definer
    return found


@functools.lru_cache(maxsize=None)
def weak_definitions(path):
    out = subprocess.run(["nm", "-D", "--defined-only", path],
                         capture_output=True, text=True).stdout
    return {parts[2].split("@")[0]
            for parts in (line.split() for line in out.splitlines())
            if len(parts) >= 3 and parts[1] in "WVu"}


def load_order(program):
    """The libraries in the loader's order (ldd lists them so)."""
    out = subprocess.run(["ldd", program], capture_output=True, text=True,
                         check=True).stdout
    return [line.split()[2] for line in out.splitlines() if " => /" in line]


def main():
    usual_program, ordered_program, work = sys.argv[1:]
    os.makedirs(work, exist_ok=True)
    # The order must have been applied (the same libraries, loaded in
    # another order), or there would be nothing to compare.
    usual_order, ordered_order = (load_order(usual_program),
                                  load_order(ordered_program))
    print(f"libraries: {len(usual_order)} in both, "
          f"{sum(a != b for a, b in zip(usual_order, ordered_order))} "
          "at another place in the load order")
    failures = []
    if sorted(usual_order) != sorted(ordered_order):
        failures.append("the two programs load different libraries")
    if usual_order == ordered_order:
        failures.append("the ordered program loads its libraries in the "
                        "usual order: the link order was not applied")
    usual = bindings(usual_program, work, "usual")
    ordered = bindings(ordered_program, work, "ordered")
    print(f"bindings: usual link {len(usual)}, ordered link {len(ordered)}")
    if set(usual) != set(ordered):
        failures.append(f"{len(set(usual) ^ set(ordered))} references are "
                        "bound in one program and not the other")
    moved = [key for key in usual if key in ordered
             and usual[key] != ordered[key]]
    copies, rebound = 0, []
    for user, symbol in moved:
        first, second = usual[(user, symbol)], ordered[(user, symbol)]
        if (symbol.startswith("_Z")
                and symbol in weak_definitions(first)
                and symbol in weak_definitions(second)):
            copies += 1
        else:
            rebound.append(f"{user}: {symbol} bound to {second}, "
                           f"not {first}")
    print(f"bound to another copy of the same C++ entity: {copies}")
    print(f"bound to another definition: {len(rebound)}")
    failures += rebound
    for failure in failures[:20]:
        print("  " + failure)
    # (LD_DEBUG is read by glibc's loader; with another, nothing is said)
    if len(usual) < 1000:
        failures.append("too few bindings reported: is LD_DEBUG ignored?")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
