#!/usr/bin/env bash
# The main job on a cluster (issue 46 item 5, cli/all_plan.h): `gtlab all
# --plan --jobs 2` executed task by task in one shell, and `mpirun -n 2 gtlab
# all` (when MPI is built), give one process's bits: every file of the stages
# (images, tables, figures) byte-identical, summary.json equal but its
# timings, report.md equal but its timings.
gtlab=$1
work=$2
mpirun=${3:-}
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"
cd "$work" || exit 1

stages=hdr-precision,bloom,dither
expect_ok one-process all --quality preview --stages "$stages" -o one

# same DIR_A DIR_B NAME: the outputs agree as above.
same() {
  python3 - "$1" "$2" <<'PY' && pass || fail "$3 differs from one process"
import filecmp, json, os, re, sys
a, b = sys.argv[1:3]
skip = {"report.md", "report.html", "summary.json", "parts", "plan"}
def files(root):
    out = set()
    for d, subdirs, names in os.walk(root):
        subdirs[:] = [s for s in subdirs if os.path.relpath(os.path.join(d, s), root) not in skip]
        out |= {os.path.relpath(os.path.join(d, n), root) for n in names
                if os.path.relpath(os.path.join(d, n), root) not in skip and not n.startswith("job-")}
    return out
fa, fb = files(a), files(b)
assert fa == fb, ("files", sorted(fa ^ fb))
def agree(f):  # a gnuplot script names its folder
    pa, pb = os.path.join(a, f), os.path.join(b, f)
    if f.endswith(".gp"):
        return open(pa).read().replace(a + "/", b + "/") == open(pb).read()
    return filecmp.cmp(pa, pb, shallow=False)
bad = [f for f in sorted(fa) if not agree(f)]
assert not bad, ("differ", bad)
def untimed(o):
    if isinstance(o, dict):
        return {k: untimed(v) for k, v in o.items() if "second" not in k}
    return [untimed(v) for v in o] if isinstance(o, list) else o
sa, sb = (json.load(open(os.path.join(d, "summary.json"))) for d in (a, b))
assert untimed(sa) == untimed(sb), "summary.json"
mask = lambda d: re.sub(r"\d+(\.\d+)? s\b", "T s", open(os.path.join(d, "report.md")).read())
assert mask(a) == mask(b), "report.md"
PY
}

# The plan, then its tasks and its assembly run one after another here.
expect_ok plan all --quality preview --stages "$stages" --plan --jobs 2 -o planned
for f in jobs.txt job.sh assemble.sh submit.sh; do
  [ -s "planned/plan/$f" ] && pass || fail "the plan has no $f"
done
[ "$(wc -l <planned/plan/jobs.txt)" -eq 2 ] && pass || fail "jobs.txt: $(cat planned/plan/jobs.txt)"
grep -q "task 1" "$work/stdout" && pass || fail "the plan does not list its tasks: $(cat "$work/stdout")"
[ -e planned/report.md ] && fail "--plan ran the job" || pass
ok=1
for task in 0 1; do GTLAB=$gtlab bash planned/plan/job.sh "$task" >/dev/null 2>&1 || ok=0; done
[ -e planned/report.md ] && fail "a task wrote the report" || pass
GTLAB=$gtlab bash planned/plan/assemble.sh >/dev/null 2>&1 || ok=0
[ "$ok" -eq 1 ] && pass || fail "a task or the assembly failed"
same one planned "the plan run task by task"

# Refusals before any work.
expect_error jobs-alone "--jobs: is the plan's: add --plan" "" -- all --quality preview --jobs 2 -o x
expect_error plan-alone "--plan: needs --jobs N" "" -- all --quality preview --plan -o x
expect_error modes "exclude each other" "" -- all --quality preview --plan --jobs 2 --assemble -o x

if [ -n "$mpirun" ]; then
  # Open MPI's plug-ins keep allocations until exit and are unloaded before
  # LeakSanitizer reports ("<unknown module>"): the mpirun run goes without leak
  # detection, as in test_cli_mpi.sh (the stages' own code is leak-checked above).
  if ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" "$mpirun" -x ASAN_OPTIONS --allow-run-as-root --oversubscribe --mca pml ob1 --mca btl self,vader -n 2 \
    "$gtlab" all --quality preview --stages "$stages" -o mpi >"$work/mpi.log" 2>&1; then
    pass
    same one mpi "mpirun -n 2 gtlab all"
  else
    fail "mpirun -n 2 gtlab all: $(tail -5 "$work/mpi.log")"
  fi
fi

echo "cli_all_plan: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
