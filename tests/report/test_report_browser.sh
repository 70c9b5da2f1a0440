#!/usr/bin/env bash
# The report in a real browser (issue 14, item 5): a small 'gtlab all' run's
# report.html loaded by Debian's headless Chromium must log nothing to the
# console (the report's script logs nothing, so any line is an error or a
# stray message), load every image (naturalWidth > 0: the plots' SVGs, the
# heatmaps, the previews), resolve every #anchor link, and run its
# comparison views' script; screenshots of its top, of a technique's
# section and of the claims table are kept beside it. The checker
# (report_check.html) reports from a frame, which file:// allows with
# --allow-file-access-from-files; a copy of the report with a missing image,
# a dangling anchor and a console error must fail it (the check can fail).
# Skipped (77) without chromium.
gtlab=$1
work=$2
checker=$3
command -v chromium >/dev/null || { echo "chromium not found (Debian package chromium): skipped"; exit 77; }
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/../cli/cli_test_lib.sh"
out=$work/out

browser() {
  timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$work/profile" \
    --enable-logging=stderr --v=0 "$@"
}

# check PAGE: loads PAGE through the checker; the console lines in $work/console.
check() {
  sed "s|src=\"report.html\"|src=\"$1\"|" "$checker" >"$out/check_$1"
  browser --allow-file-access-from-files --virtual-time-budget=20000 --dump-dom "file://$out/check_$1" \
    >"$work/dom" 2>"$work/log"
  grep -a 'INFO:CONSOLE' "$work/log" >"$work/console" || true
}

expect_ok all all --stages ao,hdr-precision,best-fit-normals --quality preview --threads 2 -o "$out"
check report.html
strays=$(grep -v 'GTLAB-CHECK' "$work/console")
[ -z "$strays" ] && pass || fail "report.html logged to the console: $strays"
grep -q 'GTLAB-CHECK: PASS' "$work/console" && pass || fail "$(grep -o 'GTLAB-CHECK: [^"]*' "$work/console")"
summary=$(grep -o 'GTLAB-CHECK: PASS[^"]*' "$work/console")
echo "$summary"
# What was checked is there: the AO previews and standard-error heatmaps
# with their colour bars, their comparison views, the HDR section's plot as
# SVG, the contents' and the summary's links, the best-fit normals' ranked
# table's best row.
for what in 'images=[1-9][0-9]' 'svg=[1-9]' 'bars=[1-9]' 'views=[1-9]' 'anchors=[1-9]' 'best=[1-9]'; do
  echo "$summary" | grep -q "$what" && pass || fail "expected $what in: $summary"
done

# The check fails on a broken copy.
sed -e 's|</body>|<img src="figures/no_such.png"><a href="#no-such-anchor">x</a><script>console.error("broken")</script></body>|' \
  "$out/report.html" >"$out/broken.html"
check broken.html
grep -q 'GTLAB-CHECK: image not loaded: figures/no_such.png' "$work/console" && pass || fail "missing image not caught"
grep -q 'GTLAB-CHECK: anchor does not resolve: #no-such-anchor' "$work/console" && pass || fail "dangling anchor not caught"
grep -v 'GTLAB-CHECK' "$work/console" | grep -q '"broken"' && pass || fail "console error not caught"

# Screenshots of the report's top, of one technique's section and of the
# claims table (issue 41), each shown alone by section_only.js in a copy of
# the report; each must show something (not one colour: a hidden or
# unrendered page is blank).
shown() {
  local stddev
  stddev=$(oiiotool --stats "$1" 2>/dev/null | sed -n 's/.*Stats StdDev: *\([0-9.]*\).*/\1/p' | head -1)
  [ -n "$stddev" ] && awk -v s="$stddev" 'BEGIN { exit !(s > 1) }'
}
browser --screenshot="$out/report_screenshot.png" --window-size=1280,2400 "file://$out/report.html" >/dev/null 2>&1
shown "$out/report_screenshot.png" && pass || fail "blank or no screenshot of the report's top"
echo "screenshot: $out/report_screenshot.png"
sed "s|</body>|<script src=\"$(dirname "$checker")/section_only.js\"></script></body>|" "$out/report.html" >"$out/section.html"
for section in best-fit-normals-in-an-rgb8-g-buffer-cryengine-3 claims-of-the-talks; do
  grep -q "id=\"$section\"" "$out/report.html" || fail "no section $section in the report"
  rm -rf "$work/profile"
  browser --virtual-time-budget=10000 --screenshot="$out/screenshot_$section.png" --window-size=1280,1600 \
    "file://$out/section.html?$section" >/dev/null 2>&1
  shown "$out/screenshot_$section.png" && pass || fail "blank or no screenshot of the section $section"
  echo "screenshot: $out/screenshot_$section.png"
done
# The same for a report made from a project file on a user's glTF: its
# scene's previews load, and its label is in the report.
out=$work/project
mkdir -p "$out"
"$gtlab" scene write sphere-on-plane -o "$out/user.glb" >/dev/null || fail "scene write"
printf '{"scenes": [{"path": "user.glb", "label": "user-glb", "cameras": [{"gltf": 0}]}]}' >"$out/gtlab.json"
expect_ok project all --project "$out/gtlab.json" --stages ao --quality preview --threads 2 -o "$out"
check report.html
strays=$(grep -v 'GTLAB-CHECK' "$work/console")
[ -z "$strays" ] && pass || fail "the project's report.html logged to the console: $strays"
grep -q 'GTLAB-CHECK: PASS.*images=[1-9]' "$work/console" && pass || fail "project: $(grep -o 'GTLAB-CHECK: [^"]*' "$work/console")"
grep -q 'figures/ao_user-glb.png' "$out/report.html" && pass || fail "the project's report shows no preview of user-glb"
echo "passed $passed, failed $failed"
[ "$failed" -eq 0 ]
