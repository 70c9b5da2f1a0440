#!/usr/bin/env bash
# gtlab shader score (issue 15, items 3 and 5) and the project's shaders and
# plug-ins in `gtlab all` (item 6), as a user runs them. On a small
# multi-bounce reference: the template function (shaders/template_multibounce
# .glsl, the talk's GTAOMultiBounce) and the example plug-in (the same in C)
# score as gtlab's built-in function does — the plug-in's printed figures
# equal the talk's column, the GLSL's within float rounding (the RMSE bound
# of test_gpu_function_score.c, 7.4e-6, below the 5 printed
# decimals' half unit only where it does not straddle one, so compared as
# numbers). Bad function files: one line, exit 1. A project listing the two
# gets the section beside V_d and the talk's; one that lists neither gets
# no section and no summary.json member (specular occlusion:
# test_cli_shader_score_so.sh).
gtlab=$1
work=$2
source_dir=$3
plugin=$4
rm -rf "$work" && mkdir -p "$work/out/multibounce"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"
vulkan_preload
ref=$work/out/multibounce/corner.exr
"$gtlab" render multibounce --scene builtin:corner --albedo 0.2,0.5,0.8 --width 24 --height 24 --spp 16 -o "$ref" \
  2>/dev/null || fail "render corner"
cp "$source_dir/shaders/template_multibounce.glsl" "$work/mine.glsl"

expect_ok score shader score --function "$work/mine.glsl" --plugin "$plugin" "$ref"
python3 - "$work/stdout" <<'PY' && pass || fail "shader score: $(cat "$work/stdout")"
import sys
lines = open(sys.argv[1]).read().splitlines()
head, rows = lines[1].split(), [l.split() for l in lines[2:]]
assert head[5:8] == ["talk", "mine.glsl", "libgtlab_exa"], head
assert len(rows) == 4 and rows[-1][0] == "mean", rows
for r in rows:
    dssim, rmse = r[3:7], r[8:12]  # V_d talk function plug-in, after scene albedo floor
    assert dssim[3] == dssim[1] and rmse[3] == rmse[1], r       # the plug-in: the talk's figures exactly
    assert abs(float(rmse[2]) - float(rmse[1])) <= 1e-5, r      # the function: within rounding
    assert abs(float(dssim[2]) - float(dssim[1])) <= 1e-3 * float(dssim[1]), r
print("mean RMSE talk", rows[-1][9], "function", rows[-1][10], "plug-in", rows[-1][11])
PY

printf '// mine\nfloat gtlab_multibounce(float visibility, float albedo)\n{\n    return visibilty;\n}\n' >"$work/broken.glsl"
expect_error compile-error "broken.glsl:4: error: 'visibilty' : undeclared identifier" "" -- \
  shader score --function "$work/broken.glsl" "$ref"
printf 'float gtlab_multibounce(float v) { return v; }\n' >"$work/signature.glsl"
expect_error signature "signature.glsl: gtlab cannot call float gtlab_multibounce(float visibility, float albedo)" "" -- \
  shader score --function "$work/signature.glsl" "$ref"
printf 'float f(float x) { return x; }\n' >"$work/none.hlsl"
expect_error no-function "none.hlsl: defines no gtlab_multibounce" "" -- shader score --function "$work/none.hlsl" "$ref"
printf 'float gtlab_multibounce(float v, float a) { return v > 0.5 ? uintBitsToFloat(0x7fc00000u) : v; }\n' >"$work/nan.glsl"
expect_error nan "nan.glsl: gtlab_multibounce(0\\.[5-9].*) is NaN" "" -- shader score --function "$work/nan.glsl" "$ref"
# An infinity is refused as a NaN is (issue 41: it reached the table as DSSIM -nan, exit 0).
printf 'float gtlab_multibounce(float v, float a) { return v > 0.5 ? uintBitsToFloat(0x7f800000u) : v; }\n' >"$work/inf.glsl"
expect_error infinite "inf.glsl: gtlab_multibounce(0\\.[5-9].*) is infinite" "" -- shader score --function "$work/inf.glsl" "$ref"
expect_error not-a-plugin "libm.so.6: not a gtlab plug-in" "" -- shader score --plugin libm.so.6 "$ref"
expect_error nothing "nothing to score" "" -- shader score "$ref"
expect_error quantity "--quantity: 'sphere-light'" "" -- shader score --quantity sphere-light --plugin "$plugin" "$ref"
"$gtlab" render ao --scene builtin:corner --width 16 --height 16 --spp 4 -o "$work/ao.exr" 2>/dev/null || fail "render ao"
expect_error not-multibounce "ao.exr: no multibounce channels" "" -- shader score --plugin "$plugin" "$work/ao.exr"

# A bare file name is the file in the working folder (dlopen alone would search the library path).
cp "$plugin" "$work/libbare.so"
(cd "$work" && "$gtlab" shader score --plugin libbare.so "$ref" >/dev/null 2>&1) && pass || fail "--plugin libbare.so in the working folder"

# The project's lists: the section beside gtlab's variants (the multibounce
# stage's references from an earlier run into the same folder).
cp "$plugin" "$work/libmine.so"
printf '{"shaders": ["mine.glsl"], "plugins": ["libmine.so"]}' >"$work/project.json"
expect_ok project all --project "$work/project.json" --stages shader-scores -o "$work/out"
python3 - "$work/out/summary.json" <<'PY' && pass || fail "summary.json: $(head -c 600 "$work/out/summary.json")"
import json, sys
s = json.load(open(sys.argv[1]))["shader_scores"]
v = {x["name"]: x for x in s["variants"]}
assert list(v) == ["V_d", "talk", "mine.glsl", "libmine.so"], list(v)
assert s["pairs"] == 3, s
assert v["libmine.so"]["rmse"] == v["talk"]["rmse"] and v["libmine.so"]["dssim"] == v["talk"]["dssim"], v
assert abs(v["mine.glsl"]["rmse"] - v["talk"]["rmse"]) <= 7.5e-6, v
assert v["mine.glsl"]["kind"] == "function" and v["libmine.so"]["kind"] == "plug-in" and v["talk"]["kind"] == "gtlab"
PY
grep -q "Your shaders and plug-ins" "$work/out/report.md" && pass || fail "report.md has no section"
grep -q "| libmine.so |" "$work/out/report.md" && pass || fail "report.md's table has no plug-in row"

# No lists: nothing added.
printf '{"shaders": [], "plugins": []}' >"$work/empty.json"
expect_ok empty-project all --project "$work/empty.json" --stages shader-scores -o "$work/out"
! grep -q "shader_scores" "$work/out/summary.json" && pass || fail "summary.json has shader_scores without lists"
! grep -q "Your shaders" "$work/out/report.md" && pass || fail "report.md has the section without lists"
! [ -d "$work/out/shader_scores" ] && pass || fail "specular-occlusion references rendered without such files"
finish
