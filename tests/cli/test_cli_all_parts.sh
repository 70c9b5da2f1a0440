#!/usr/bin/env bash
# The report assembled from the stages' parts (report/report_part.h): a rerun
# of some stages into a folder keeps the other stages' sections (issue 41);
# --assemble alone rewrites the report of the parts byte for byte; a part of
# another quality is left out with a warning; a stage reading another's
# output without that stage's part is refused before any work; a malformed
# part is refused before any work, naming its file.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"

out=$work/out
stages=hdr-precision,bloom
expect_ok first all --quality preview --stages "$stages" -o "$out" --threads 2
cp "$out/report.md" "$work/first.md"
cp "$out/report.html" "$work/first.html"
for key in hdr-precision bloom; do
  [ -s "$out/parts/$key.json" ] && pass || fail "no part of stage $key"
done

# --assemble: no stage runs, the same report.
expect_ok assemble all --quality preview --stages "$stages" --assemble -o "$out"
cmp -s "$out/report.md" "$work/first.md" && pass || fail "--assemble changed report.md: $(diff "$work/first.md" "$out/report.md" | head -5)"
cmp -s "$out/report.html" "$work/first.html" && pass || fail "--assemble changed report.html"
grep -q "gtlab all: " "$work/stderr" && fail "--assemble ran a stage: $(head -3 "$work/stderr")" || pass

# A rerun of one stage keeps the other's section, and says where it came from.
expect_ok rerun all --quality preview --stages bloom -o "$out" --threads 2
sections() { grep '^## ' "$1" | grep -v '^## \(At a glance\|Contents\)'; }
[ "$(sections "$out/report.md")" = "$(sections "$work/first.md")" ] && pass ||
  fail "the rerun's sections: $(sections "$out/report.md" | tr '\n' ';') (before: $(sections "$work/first.md" | tr '\n' ';'))"
grep -q "The sections of the stages hdr-precision come from earlier runs" "$out/report.md" && pass ||
  fail "the rerun's report does not say which sections came from earlier runs"
python3 - "$out/summary.json" <<'PY' && pass || fail "summary.json of the rerun lacks a stage"
import json, sys
s = json.load(open(sys.argv[1]))
assert "hdr_precision" in s and "bloom" in s, sorted(s)
assert set(s["stage_seconds"]) == {"hdr-precision", "bloom", "total"}, s["stage_seconds"]
PY

# Another quality: the preview parts are left out, with a warning each.
other=$work/other
cp -r "$out" "$other"
expect_ok production all --quality production --stages bloom -o "$other" --threads 2
grep -q "warning: .*hdr-precision in parts/ was made at preview quality: its section is left out" "$work/stderr" &&
  pass || fail "no warning for the preview part: $(head -3 "$work/stderr")"
grep -q '^## Colour precision' "$other/report.md" && fail "a preview section in a production report" || pass

# gtao reads ao's references: without ao's part here, refused before any work.
expect_error needs "stage gtao reads what stage ao writes here.*add ao to --stages" "" -- \
  all --quality preview --stages gtao -o "$out"

expect_error assemble-none "--assemble: no part of stage dither" "" -- \
  all --quality preview --stages dither --assemble -o "$out"

# A malformed part: refused before any work, naming it; nothing rewritten.
echo '{"stage": "bloom"}' >"$out/parts/bloom.json"
before=$(md5sum "$out/report.md")
expect_error malformed "parts/bloom.json: not the part of stage bloom" "" -- \
  all --quality preview --stages hdr-precision -o "$out"
[ "$(md5sum "$out/report.md")" = "$before" ] && pass || fail "a refused run rewrote report.md"

echo "cli_all_parts: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
