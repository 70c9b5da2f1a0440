#!/usr/bin/env bash
# Resume under mpirun (issue 20, raytracer/render_checkpoint_files.h): each
# rank of `mpirun -n 2 gtlab render` checkpoints its own share in
# F.checkpoint.rank<r>-of-2.exr. A job stopped after a block (the test hook
# GTLAB_STOP_AFTER_BLOCKS, as SIGTERM would), one whose mpirun gets SIGTERM,
# and one with a rank killed (SIGKILL, a lost node; checkpoints after
# every block) leave both ranks' checkpoints and no F.exr; `mpirun -n 2 ...
# --resume` then writes the uninterrupted single-process file, byte for
# byte, and removes the checkpoints. Resuming on 3 ranks, or in one
# process, is refused in one line naming the checkpoint. A render with a
# stopping target (rows shared among the ranks) resumes alike, and so do
# multibounce, specular-occlusion, sphere-light and fog.
# PART: "stops" (the test hook, the refusals, the stopping target),
# "signals" (SIGTERM, SIGKILL) or "types" (the other reference types):
# three tests, each a few mpirun start-ups.
gtlab=$1
work=$2
mpirun=$3
part=$4
# Under AddressSanitizer Open MPI's run-time components leak as unknown
# modules (see test_cli_mpi.sh): the ranks run without leak detection.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"
cd "$work" || exit 1

# mpi_command N [NAME=VALUE ...] -- ARGS...: in cmd, gtlab ARGS on N ranks
# with the variables set; mpi ...: runs it.
mpi_command() {
  local n=$1 env=(-x ASAN_OPTIONS)
  shift
  while [ "$1" != -- ]; do env+=(-x "$1"); shift; done
  shift
  cmd=("$mpirun" "${env[@]}" --allow-run-as-root --oversubscribe --mca pml ob1 --mca btl self,vader -n "$n" "$gtlab" "$@")
}
mpi() { mpi_command "$@" && "${cmd[@]}"; }
checkpoints() { ls r.checkpoint.rank*-of-*.exr 2>/dev/null | tr "\n" " "; } # (a SIGKILL may leave a temporary beside them)
both="r.checkpoint.rank0-of-2.exr r.checkpoint.rank1-of-2.exr "

# stopped NAME: the job must have failed, left both checkpoints, no r.exr.
stopped() {
  [ "$status" -ne 0 ] && pass || fail "$1: the job exited 0 (finished before it was stopped?)"
  [ ! -e r.exr ] && [ "$(checkpoints)" = "$both" ] && pass || fail "$1: r.exr written, or checkpoints '$(checkpoints)'"
}
# resumed NAME REFERENCE ARGS...: --resume on 2 ranks gives REFERENCE's bits, no checkpoint left.
resumed() {
  local name=$1 reference=$2
  shift 2
  mpi 2 -- render "$@" --resume -o r.exr >resume.log 2>&1 && pass || fail "$name: resume failed: $(tail -c 600 resume.log)"
  cmp -s "$reference" r.exr && pass || fail "$name: resumed on 2 ranks, not the uninterrupted file"
  [ -z "$(checkpoints)" ] && pass || fail "$name: checkpoints left: $(checkpoints)"
  rm -f r.exr r.camera.json
}

if [ "$part" = stops ]; then
  # Stopped after one block of 64 samples (each rank has 160), refused on 3
  # ranks and in one process, resumed on 2.
  small=(ao --scene builtin:cornell --width 24 --height 16 --spp 320 --seed 9 --threads 1)
  expect_ok whole render "${small[@]}" -o whole.exr
  mpi 2 GTLAB_STOP_AFTER_BLOCKS=1 -- render "${small[@]}" -o r.exr >/dev/null 2>&1
  status=$?
  stopped hook
  mpi 3 -- render "${small[@]}" --resume -o r.exr >/dev/null 2>three.log
  [ "$(grep -c '^gtlab: ' three.log)" -eq 1 ] &&
    grep -q '^gtlab: r.checkpoint.rank0-of-2.exr: a checkpoint of this output from a run on 2 process(es), this one has 3' three.log &&
    [ ! -e r.exr ] && pass || fail "resumed on 3 ranks: not refused in one line: $(cat three.log)"
  # A rank's checkpoint in another rank's place is refused (every rank stops; none waits).
  mkdir -p saved && cp r.checkpoint.* saved/ && cp saved/r.checkpoint.rank1-of-2.exr r.checkpoint.rank0-of-2.exr
  mpi_command 2 -- render "${small[@]}" --resume -o r.exr
  timeout 120 "${cmd[@]}" >/dev/null 2>swapped.log
  status=$?
  [ "$status" -ne 0 ] && [ "$status" -ne 124 ] && [ ! -e r.exr ] &&
    grep -q "^gtlab: r.checkpoint.rank0-of-2.exr: a checkpoint of another process (its gtlab.checkpoint_rank is '1/2', this one's '0/2')" swapped.log &&
    pass || fail "a rank's checkpoint in another's place (status $status): $(cat swapped.log)"
  cp saved/r.checkpoint.* .
  expect_error one-process "r.checkpoint.rank0-of-2.exr: a checkpoint of this output from a run on 2 process(es), this one has 1" \
    r.exr -- render "${small[@]}" --resume -o r.exr
  resumed hook whole.exr "${small[@]}"

  # A stopping target: rows r, r + 2, ... per rank, 8 rows a block; stopped after one.
  adaptive=(ao --scene builtin:cornell --width 24 --height 20 --spp 4096 --target-stderr 0.02 --seed 9 --threads 1)
  expect_ok adaptive-whole render "${adaptive[@]}" -o adaptive.exr
  mpi 2 GTLAB_STOP_AFTER_BLOCKS=1 -- render "${adaptive[@]}" -o r.exr >/dev/null 2>&1
  status=$?
  stopped adaptive
  resumed adaptive adaptive.exr "${adaptive[@]}"
fi

if [ "$part" = signals ]; then
  # Real signals once both ranks have a checkpoint (written after every
  # block): SIGTERM to mpirun (it passes it to the ranks), SIGKILL to one rank.
  big=(ao --scene builtin:cornell --width 48 --height 32 --spp 12800 --seed 4 --threads 1)
  expect_ok big-whole render "${big[@]}" -o big.exr
  for signal in TERM KILL; do
    rm -f r.*
    mpi_command 2 GTLAB_CHECKPOINT_SECONDS=0 -- render "${big[@]}" -o r.exr
    "${cmd[@]}" >/dev/null 2>&1 &
    pid=$! # mpirun's; its children are the ranks
    for _ in $(seq 600); do [ "$(checkpoints)" = "$both" ] && break; sleep 0.05; done
    ranks=$(pgrep -P "$pid" | paste -sd,)
    if [ "$signal" = TERM ]; then kill -s TERM "$pid"; else kill -s KILL "${ranks##*,}"; fi
    wait "$pid"
    status=$?
    # every rank ended (gone, or a zombie nobody reaps) before the checkpoints are looked at
    for _ in $(seq 200); do ps -o stat= -p "$ranks" | grep -qv Z || break; sleep 0.05; done
    stopped "SIG$signal"
    resumed "SIG$signal" big.exr "${big[@]}"
  done
fi

if [ "$part" = types ]; then
  # Each other reference type (several quantities, listed in another order
  # than the checkpoint's channels) stopped after one block of 64 samples
  # (each rank has 65), resumed on 2 ranks.
  size=(--width 20 --height 14 --seed 3 --threads 1 --spp 130)
  for name in "${!other_references[@]}"; do
    read -r -a args <<<"${other_references[$name]}"
    expect_ok "$name-whole" render "${args[@]}" "${size[@]}" -o "$name.exr"
    mpi 2 GTLAB_STOP_AFTER_BLOCKS=1 -- render "${args[@]}" "${size[@]}" -o r.exr >/dev/null 2>&1
    status=$?
    stopped "$name"
    resumed "$name" "$name.exr" "${args[@]}" "${size[@]}"
  done
fi

echo "$passed passed, $failed failed"
[ "$passed" -gt 0 ] && [ "$failed" -eq 0 ]
