#!/usr/bin/env python3
"""Audit (issue 43): no two source files of gtlab call each other in a circle,
and no file of a shared folder knows a technique's or the command line's.

A file "knows" another when its object file refers to a symbol the other
defines (a call, or a function's or variable's address taken). Every C and
C++ source of the libraries and the CLI is read from the build's
compile_commands.json; `nm` lists what each object defines and refers to; the
graph's strongly connected components of two files or more are the circles.
Tests and the example plug-ins are left out (they are leaves).

The include paths keep a lower layer from including a higher one's headers
(cmake/gtlab_layers.cmake, tests/layering), but a static library may still
refer to a symbol only a higher library defines (a declaration of its own
and the final link resolve it). So a file of a shared folder (core/,
raytracer/, project/, ...) that refers to a symbol defined under techniques/
or cli/ fails the audit too: the render registry, for one, is handed down
from cli/ (cli/render_quantities.h), never named by the ray tracer.

Circles that existed when the audit was written (issue 43 takes them apart
as it moves the techniques into their folders) are listed in KNOWN; a circle not listed, or a listed one that no
longer exists (remove it from KNOWN), fails the audit.

  tests/audit/file_call_circles.py BUILD_DIR
"""
import json
import os
import shlex
import subprocess
import sys

# Each circle as the sorted files it joins, relative to the repository.
KNOWN = [
]


def objects(build, root):
    """(source, object) for every library and CLI source of the build."""
    seen = {}
    for c in json.load(open(os.path.join(build, "compile_commands.json"))):
        source = os.path.realpath(c["file"])
        rel = os.path.relpath(source, root)
        if (rel.startswith(("tests/", "examples/", "build")) or "/tests/" in rel
                or not rel.endswith((".c", ".cpp"))):
            continue
        args = shlex.split(c["command"])
        obj = args[args.index("-o") + 1]
        seen[rel] = os.path.join(c["directory"], obj)
    return seen


def symbols(obj):
    """(defined, referred) global symbols of one object file."""
    out = subprocess.run(["nm", "-P", obj], check=True, capture_output=True, text=True).stdout
    defined, referred = set(), set()
    for line in out.splitlines():
        parts = line.split()
        if len(parts) < 2:
            continue
        name, kind = parts[0], parts[1]
        if kind == "U":
            referred.add(name)
        elif kind in "TDBRVW" and kind.isupper():
            defined.add(name)
    return defined, referred


def strongly_connected(graph):
    """Tarjan's components of a {node: set(node)} graph, iteratively."""
    index, low, on_stack, stack, components = {}, {}, set(), [], []
    counter = [0]
    for start in graph:
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = counter[0]
        counter[0] += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            advanced = False
            for child in children:
                if child not in index:
                    index[child] = low[child] = counter[0]
                    counter[0] += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                    advanced = True
                    break
                if child in on_stack:
                    low[node] = min(low[node], index[child])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                components.append(sorted(component))
    return components


# The folders above every shared one: the techniques and the command line.
ABOVE_SHARED = ("techniques/", "cli/")


def upward_references(graph):
    """1 (and a line each) if a shared folder's file knows a file above them."""
    status = 0
    for rel in sorted(graph):
        if rel.startswith(ABOVE_SHARED):
            continue
        for known in sorted(graph[rel]):
            if known.startswith(ABOVE_SHARED):
                print("file_call_circles: %s (a shared folder) refers to %s, above it" % (rel, known))
                status = 1
    return status


def main():
    build = sys.argv[1]
    root = os.path.realpath(os.path.join(os.path.dirname(__file__), "..", ".."))
    files = objects(build, root)
    missing = [obj for obj in files.values() if not os.path.exists(obj)]
    if missing:
        print("file_call_circles: %s is not built (build %s first)" % (missing[0], build))
        return 1
    defined, referred = {}, {}
    for rel, obj in files.items():
        defined[rel], referred[rel] = symbols(obj)
    owner = {}
    for rel, names in defined.items():
        for name in names:
            owner.setdefault(name, rel)
    graph = {rel: {owner[n] for n in referred[rel] if n in owner and owner[n] != rel} for rel in files}
    status = upward_references(graph)
    circles = [c for c in strongly_connected(graph) if len(c) > 1]
    known = [sorted(k) for k in KNOWN]
    for c in circles:
        if c not in known:
            print("file_call_circles: these files call each other in a circle: " + ", ".join(c))
            status = 1
    for k in known:
        if k not in circles:
            print("file_call_circles: a listed circle is gone (remove it from KNOWN): " + ", ".join(k))
            status = 1
    print("file_call_circles: %d files, %d circles (%d listed in KNOWN)" % (len(files), len(circles), len(known)))
    return status


if __name__ == "__main__":
    sys.exit(main())
