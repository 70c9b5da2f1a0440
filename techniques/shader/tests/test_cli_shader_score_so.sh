#!/usr/bin/env bash
# gtlab shader score --quantity specular-occlusion (issue 15, items 3 and 5)
# and a project's specular-occlusion files in `gtlab all` (item 6), as a user
# runs them (the multi-bounce side: test_cli_shader_score.sh). On a small
# specular-occlusion reference and the AO reference of its view: the
# template (GTSO's cone/cone) within float rounding of gtlab's
# cone-exact:exp2-alpha (|dRMSE| <= max |gpu - c| <= 2e-3,
# test_gpu_so_function_score.c), the example plug-in (Lagarde's)
# exactly like gtlab's lagarde. Bad input: one line, exit 1. A project
# listing files of both quantities gets both sections, each with the files
# implementing its quantity; a function file implementing neither is refused.
gtlab=$1
work=$2
source_dir=$3
mb_plugin=$4
so_plugin=$5
rm -rf "$work" && mkdir -p "$work/out/multibounce"
if [ -n "$GTLAB_VULKAN_PRELOAD" ]; then  # under ASan: the Vulkan driver kept resident (cmake/gtlab_test.cmake)
  printf '#!/bin/sh\nLD_PRELOAD="%s" exec "%s" "$@"\n' "$GTLAB_VULKAN_PRELOAD" "$gtlab" >"$work/gtlab"
  chmod +x "$work/gtlab"
  gtlab=$work/gtlab
fi
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"
plugin=$mb_plugin
"$gtlab" render multibounce --scene builtin:corner --albedo 0.2,0.5,0.8 --width 24 --height 24 --spp 16 \
  -o "$work/out/multibounce/corner.exr" 2>/dev/null || fail "render corner"
cp "$source_dir/shaders/template_multibounce.glsl" "$work/mine.glsl"
cp "$plugin" "$work/libmine.so"

# Specular occlusion: a reference and the AO reference of its view.
"$gtlab" render specular-occlusion --scene builtin:corner --roughness 0.5 --width 24 --height 24 --spp 16 \
  -o "$work/so.exr" 2>/dev/null || fail "render specular-occlusion"
"$gtlab" render ao --scene builtin:corner --width 24 --height 24 --spp 16 -o "$work/so_ao.exr" 2>/dev/null ||
  fail "render ao"
cp "$source_dir/shaders/template_specular_occlusion.hlsl" "$work/gtso.hlsl"
expect_ok so-score shader score --quantity specular-occlusion --function "$work/gtso.hlsl" --plugin "$so_plugin" \
  --ao "$work/so_ao.exr" "$work/so.exr"
python3 - "$work/stdout" <<'PY' && pass || fail "shader score --quantity specular-occlusion: $(cat "$work/stdout")"
import sys
lines = open(sys.argv[1]).read().splitlines()
head, rows = lines[1].split(), [l.split() for l in lines[2:]]
assert head[1] == "roughness" and head[6] == "cone-exact:e" and head[9:11] == ["gtso.hlsl", "libgtlab_exa"], head
assert len(rows) == 2 and rows[0][1] == "0.50" and rows[-1][0] == "mean", rows
for r in rows:
    dssim, rmse = r[3:10], r[11:18]  # ao lagarde cone-exact cone-oat sg function plug-in
    assert dssim[6] == dssim[1] and rmse[6] == rmse[1], r     # the plug-in: lagarde's figures exactly
    assert abs(float(rmse[5]) - float(rmse[2])) <= 2e-3, r    # the template: within the float bound
print("mean RMSE cone-exact", rows[-1][13], "template", rows[-1][16], "lagarde", rows[-1][12], "plug-in", rows[-1][17])
PY
expect_error so-no-ao "1 references and 0 --ao files" "" -- shader score --quantity specular-occlusion \
  --function "$work/gtso.hlsl" "$work/so.exr"
expect_error so-mb-plugin "exports no gtlab_specular_occlusion_v1" "" -- shader score --quantity specular-occlusion \
  --plugin "$plugin" --ao "$work/so_ao.exr" "$work/so.exr"
expect_error so-mb-function "mine.glsl: defines no gtlab_specular_occlusion" "" -- shader score \
  --quantity specular-occlusion --function "$work/mine.glsl" --ao "$work/so_ao.exr" "$work/so.exr"
printf 'float f(float x) { return x; }\n' >"$work/neither.glsl"

# A project listing both quantities' files (preview: the study's 96^2 references, one scene).
cp "$so_plugin" "$work/libso.so"
printf '{"scenes": [{"path": "builtin:corner"}], "shaders": ["mine.glsl", "gtso.hlsl"], "plugins": ["libmine.so", "libso.so"]}' \
  >"$work/both.json"
expect_ok so-project all --quality preview --project "$work/both.json" --stages shader-scores -o "$work/out"
python3 - "$work/out/summary.json" <<'PY' && pass || fail "summary.json: $(head -c 900 "$work/out/summary.json")"
import json, sys
s = json.load(open(sys.argv[1]))
mb, so = s["shader_scores"], s["shader_scores_specular_occlusion"]
assert [x["name"] for x in mb["variants"]] == ["V_d", "talk", "mine.glsl", "libmine.so"], mb
v = {x["name"]: x for x in so["variants"]}
assert list(v) == ["ao", "lagarde", "cone-exact:exp2-alpha", "cone-oat:exp2-alpha", "sg", "gtso.hlsl", "libso.so"], v
assert so["references"] == 3, so
assert v["libso.so"]["rmse"] == v["lagarde"]["rmse"] and v["libso.so"]["dssim"] == v["lagarde"]["dssim"], v
assert abs(v["gtso.hlsl"]["rmse"] - v["cone-exact:exp2-alpha"]["rmse"]) <= 2e-3, v
assert v["libso.so"]["kind"] == "plug-in" and v["gtso.hlsl"]["kind"] == "function", v
PY
grep -q "Your shaders and plug-ins: specular occlusion" "$work/out/report.md" && pass ||
  fail "report.md has no specular-occlusion section"
[ -f "$work/out/shader_scores/corner_r0.50.exr" ] && pass || fail "no rendered reference: $(ls "$work/out/shader_scores")"
printf '{"scenes": [{"path": "builtin:corner"}], "shaders": ["neither.glsl"]}' >"$work/neither.json"
run all --quality preview --project "$work/neither.json" --stages shader-scores -o "$work/out"  # stderr: progress, then the error
[ "$status" = 1 ] && [ "$(grep -c '^gtlab: ' "$work/stderr")" = 1 ] &&
  grep -q "^gtlab: .*neither.glsl: defines neither gtlab_multibounce nor gtlab_specular_occlusion" "$work/stderr" &&
  pass || fail "project-neither: status $status: $(cat "$work/stderr")"

finish
