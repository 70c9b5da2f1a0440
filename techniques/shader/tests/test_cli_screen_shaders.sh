#!/usr/bin/env bash
# The project's screen-space shaders in `gtlab all` (issue 15, item 6), as a
# user runs them: a project listing techniques/gtao/gtao.glsl and
# techniques/gtao/gtao.hlsl (one source, techniques/gtao/gtao.inc) on
# builtin:boxes' AO reference (the ao stage's file, from an earlier run into
# the same folder) gets the section:
# the two shader rows equal each other bit for bit (the same SPIR-V
# operations on the same device), and each is within the bound of
# tests/test_gpu_screen_pass.c of gtlab's C GTAO row (max |AO - C| <=
# 2e-3, hence |RMSE - RMSE(C)| <= 2e-3 by the triangle inequality). A shader
# that does not compile, an unknown parameter, a quantity other than ao: one
# line naming the project file, the JSON path and the shader, before any
# work, nothing written. A project without screen_shaders adds nothing.
gtlab=$1
work=$2
source_dir=$3
rm -rf "$work" && mkdir -p "$work/out/ao"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"
vulkan_preload
"$gtlab" render ao --scene builtin:boxes --width 48 --height 32 --spp 8 --threads 2 -o "$work/out/ao/boxes.exr" \
  2>/dev/null || fail "render ao"
cp "$source_dir/techniques/gtao/gtao.glsl" "$source_dir/techniques/gtao/gtao.hlsl" "$source_dir/techniques/gtao/gtao.inc" "$work/"

printf '{"scenes": [{"path": "builtin:boxes"}], "screen_shaders": [{"path": "gtao.glsl"}, %s]}' \
  '{"path": "gtao.hlsl", "quantity": "ao", "params": {"radius": 1.0}}' >"$work/project.json"
if python3 -c 'import jsonschema' 2>/dev/null; then  # the file follows docs/gtlab.schema.json; a bad entry does not
  python3 - "$source_dir/docs/gtlab.schema.json" "$work/project.json" <<'PY' && pass || fail "project.json vs the schema"
import json, sys, jsonschema
schema, doc = (json.load(open(p)) for p in sys.argv[1:3])
jsonschema.validate(doc, schema)
for bad in ({"path": "a.glsl", "quantity": "so"}, {"path": "a.glsl", "params": {"radius": "1"}}, {"params": {}}):
    try:
        jsonschema.validate(dict(doc, screen_shaders=[bad]), schema)
    except jsonschema.ValidationError:
        continue
    raise SystemExit("the schema accepts %r" % bad)
PY
fi
expect_ok project all --project "$work/project.json" --stages screen-shaders -o "$work/out"
python3 - "$work/out/summary.json" <<'PY' && pass || fail "summary.json: $(head -c 900 "$work/out/summary.json")"
import json, sys
summary = json.load(open(sys.argv[1]))
listed = summary["project"]["screen_shaders"]
assert [x["params"] for x in listed] == [{}, {"radius": 1.0}] and listed[1]["path"].endswith("gtao.hlsl"), listed
s = summary["screen_shader_scores"]
v = {x["name"]: x for x in s["variants"]}
assert list(v) == ["GTAO (C)", "gtao.glsl", "gtao.hlsl"], list(v)
assert s["scenes"] == 1 and v["GTAO (C)"]["kind"] == "gtlab" and v["gtao.glsl"]["kind"] == "shader", s
glsl, hlsl, c = v["gtao.glsl"], v["gtao.hlsl"], v["GTAO (C)"]
assert {k: glsl[k] for k in glsl if k != "name"} == {k: hlsl[k] for k in hlsl if k != "name"}, (glsl, hlsl)
assert 0 < glsl["max_diff_vs_gtao"] <= 2e-3, glsl
assert abs(glsl["rmse_3d"] - c["rmse_3d"]) <= glsl["max_diff_vs_gtao"], (glsl, c)
assert c["max_diff_vs_gtao"] == 0 and c["paired_mse_vs_gtao"] == 0, c
print("max |glsl - C| %.3g, RMSE C %.6f glsl %.6f" % (glsl["max_diff_vs_gtao"], c["rmse_3d"], glsl["rmse_3d"]))
PY
grep -q "^## Your screen-space shaders: ambient occlusion" "$work/out/report.md" && pass || fail "report.md has no section"
grep -q "^| gtao.hlsl | shader |" "$work/out/report.md" && pass || fail "report.md's table has no gtao.hlsl row"

# No screen_shaders: the stage reads nothing and adds nothing (the same folder, rewritten).
printf '{"scenes": [{"path": "builtin:boxes"}]}' >"$work/none.json"
expect_ok none all --project "$work/none.json" --stages screen-shaders -o "$work/out"
! grep -q "screen-space shaders" "$work/out/report.md" && ! grep -q screen_shader_scores "$work/out/summary.json" \
  && pass || fail "a project without screen_shaders got the section"

# Bad shaders: one line, before any work (the ao stage is in the run), nothing written.
printf '#version 450\n// gtlab.output ao.V\nlayout(local_size_x = 8, local_size_y = 8) in;\nvoid main() { undeclared = 1; }\n' \
  >"$work/broken.glsl"
bad() {  # NAME PATTERN SHADER-ENTRIES INDEX
  printf '{"scenes": [{"path": "builtin:boxes"}], "screen_shaders": [%s]}' "$3" >"$work/bad.json"
  expect_error "$1" "bad.json: screen_shaders\[$4\]$2" "$work/bad_out" -- \
    all --project "$work/bad.json" --stages ao,screen-shaders -o "$work/bad_out"
}
bad compile-error ".path: .*broken.glsl:4: error: 'undeclared' : undeclared identifier" '{"path": "gtao.glsl"}, {"path": "broken.glsl"}' 1
bad unknown-param ".path: .*gtao.glsl: .*radiuz.*radius, falloff" '{"path": "gtao.glsl", "params": {"radiuz": 2}}' 0
bad param-type ": params.radius: a number expected" '{"path": "gtao.glsl", "params": {"radius": "1"}}' 0
bad quantity ": quantity 'so'" '{"path": "gtao.glsl", "quantity": "so"}' 0
bad missing ".path: .*nowhere.glsl" '{"path": "nowhere.glsl"}' 0
bad unknown-key ": unknown key 'shader'" '{"path": "gtao.glsl", "shader": "x"}' 0
printf '#version 450\n// gtlab.output bent.X\nlayout(local_size_x = 8, local_size_y = 8) in;\nvoid main() {}\n' >"$work/noao.glsl"
bad no-ao ".path: .*noao.glsl: no 'gtlab.output ao.V' line" '{"path": "noao.glsl"}' 0
finish
