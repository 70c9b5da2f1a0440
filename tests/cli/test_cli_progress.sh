#!/usr/bin/env bash
# What a person at a terminal sees (issue 41, "Progress on a TTY"), under
# script(1)'s pseudo-terminal: a render's bar names its quantity and scene
# and, over a checkpointed render's many blocks, only moves forward; an
# interrupted render says where its samples are kept and how to go on, its
# bar left where it stopped; `gtlab all` numbers its stages, says how long
# each took last time, and an interrupted run says what it kept and the
# command that runs the rest, which then completes the same report.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"
cd "$work" || exit 1
command -v script >/dev/null || { echo "no script(1): skipped"; exit 77; }

# on_tty FILE COMMAND...: runs COMMAND with stderr on a pseudo-terminal, its bytes in FILE.
on_tty() {
  local file=$1
  shift
  script -qec "$(printf '%q ' "$@")" /dev/null >"$file" 2>&1
}
# percents FILE: the bar's percentages in order, one a line.
percents() { tr '\r' '\n' <"$1" | grep -o '[0-9.]*%' | tr -d '%'; }

render=(render ao --scene builtin:boxes --width 32 --height 24 --spp 1024 -o r.exr)
on_tty tty.txt "$gtlab" "${render[@]}"
grep -q 'ao boxes \[' tty.txt && pass || fail "the bar does not name the quantity and scene: $(tr '\r' '\n' <tty.txt | head -3)"
percents tty.txt | python3 -c '
import sys
p = [float(x) for x in sys.stdin]
sys.exit(0 if len(p) > 16 and p == sorted(p) and p[-1] == 100.0 else 1)' && pass ||
  fail "the bar goes back or does not end at 100% over 16 blocks: $(percents tty.txt | tr '\n' ' ' | head -c 400)"

# Stopped after 3 of 16 blocks (the scheduler's SIGTERM, as GTLAB_STOP_AFTER_BLOCKS does).
GTLAB_STOP_AFTER_BLOCKS=3 on_tty stopped.txt "$gtlab" "${render[@]}" -o s.exr
grep -q 'interrupted: s.checkpoint.exr keeps the 192 of 1024 samples per pixel done; the same command with --resume' \
  stopped.txt && pass || fail "no word of the checkpoint: $(tr '\r' '\n' <stopped.txt | tail -3)"
[ "$(percents stopped.txt | tail -1)" != "100.0" ] && pass || fail "the stopped bar says 100%"

# gtlab all: numbered stages; a rerun says what each took last time, and
# interrupted in its second stage, what it kept and the command for the rest.
stages=hdr-precision,dither
expect_ok first all --quality preview --stages "$stages" -o all
grep -q '^gtlab all: \[2/2\] dithering' "$work/stderr" && pass || fail "no stage number: $(head -3 "$work/stderr")"
"$gtlab" all --quality preview --stages "$stages" -o all >again.err 2>&1 &
pid=$!
for _ in $(seq 600); do grep -q '\[2/2\]' again.err 2>/dev/null && break; sleep 0.1; done
kill -TERM "$pid"
wait "$pid"
[ $? -eq 143 ] && pass || fail "the interrupted gtlab all did not exit 143"
grep -q 'last time; about .* left in all' again.err && pass || fail "no time from the last run: $(head -2 again.err)"
rest=$(grep -o "'gtlab all --quality preview --stages dither -o all'" again.err | tr -d "'")
[ -n "$rest" ] && pass || fail "no command for the rest: $(tail -2 again.err)"
read -r -a rest_args <<<"${rest#gtlab }"
expect_ok rest "${rest_args[@]}"
for title in '## Colour precision' '## Dithering'; do
  grep -q "^$title" all/report.md && pass || fail "the finished report lacks $title"
done

echo "cli_progress: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
