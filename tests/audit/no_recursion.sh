#!/usr/bin/env bash
# Audit (issue 21): no C function of gtlab calls itself, directly or through
# others, except those listed in ALLOWED with the bound on their depth. A
# recursion whose depth an input sets can overflow the stack, as the JSON
# parsers did. Every C source of the libraries and the CLI is compiled to
# LLVM bitcode with the flags of the build (compile_commands.json; not the
# tests, in tests/ or a technique's tests/: each has its own main), linked
# into one module, and LLVM's call graph is split into strongly connected
# components: a component of two functions or more, or one with a self-loop,
# is a recursion. The example plug-ins (examples/) are shared libraries of
# their own, each exporting the same ABI symbols: each is a module apart.
# Calls through function pointers are not in that graph; the
# C++ adapters (eight files) are audited by reading (docs/design.md, "Input
# is hostile"). Run by .ci/run (about a minute on 2 cores):
#   tests/audit/no_recursion.sh BUILD_DIR
set -euo pipefail
build=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# "function: why its depth is bounded", one cycle each.
ALLOWED=(
  "adapt: adaptive Gauss-Kronrod bisection, depth at most MAX_DEPTH = 30 (core/sampling/quadrature.c), no input sets it"
  "vector_adapt: the vector Gauss-Kronrod's bisection, the same MAX_DEPTH = 30 (core/sampling/quadrature.c), no input sets it"
)

python3 - "$build/compile_commands.json" "$root" "$work" >"$work/commands" <<'PY'
import json, shlex, sys
commands, root, work = json.load(open(sys.argv[1])), sys.argv[2], sys.argv[3]
seen = set()
for i, c in enumerate(commands):
    source = c["file"]
    if not source.endswith(".c") or not source.startswith(root + "/") or "/tests/" in source[len(root):] \
            or "/build" in source[len(root):] or source in seen:
        continue
    seen.add(source)
    args, flags = shlex.split(c["command"]), []
    for a, b in zip(args[1:], args[2:] + [""]):
        if a in ("-I", "-isystem", "-D"):
            flags += [a, b]
        elif a.startswith(("-I", "-D", "-std", "-f")) and "sanitize" not in a:
            flags.append(a)
    out = f"{work}/plugins/{i}.bc" if source.startswith(root + "/examples/") else f"{work}/{i}.bc"
    print(shlex.join(["clang", *flags, "-O0", "-w", "-emit-llvm", "-c", source, "-o", out]))
PY
[ -s "$work/commands" ] || { echo "no C sources in $build/compile_commands.json" >&2; exit 1; }
mkdir -p "$work/plugins"
xargs -d '\n' -P 2 -I{} sh -c {} <"$work/commands"
llvm-link "$work"/*.bc -o "$work/gtlab.bc"
opt -enable-new-pm=0 -print-callgraph-sccs -disable-output "$work/gtlab.bc" 2>"$work/sccs"
for plugin in "$work"/plugins/*.bc; do
  if [ -e "$plugin" ]; then opt -enable-new-pm=0 -print-callgraph-sccs -disable-output "$plugin" 2>>"$work/sccs"; fi
done
# "SCC #n : f,  (Has self-loop)." or "SCC #n : f, g, "
found=$(grep -E '^SCC #[0-9]+ : ' "$work/sccs" | sed 's/^SCC #[0-9]* : //' |
  awk '/Has self-loop/ || gsub(/, /, ", ") >= 2' | sed 's/ *(Has self-loop)\.//; s/, *$//')
for allowed in "${ALLOWED[@]+"${ALLOWED[@]}"}"; do
  found=$(printf '%s\n' "$found" | grep -vx "${allowed%%:*}" || true)
done
count=$(grep -c '^SCC #' "$work/sccs")
if [ -n "$found" ]; then
  echo "recursive C functions in gtlab (each line one cycle):"
  printf '  %s\n' "$found"
  exit 1
fi
echo "no recursion among the C functions of gtlab ($count call-graph components, $(wc -l <"$work/commands") files)"
