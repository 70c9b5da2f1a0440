#!/usr/bin/env bash
# Projects (issue 14, item 1): `gtlab init` writes an example project file
# that `gtlab all --project` accepts as written and that the schema
# (docs/gtlab.schema.json) accepts; it never overwrites. A user's glTF, made
# by `gtlab scene write`, named in a project with a label and a glTF camera:
# `gtlab all --project` puts that label's rows in every section it runs (the
# report and each section of summary.json) and no built-in scene's; the
# command line overrides the file's quality, stages and output; two cameras
# of one scene are two labelled entries. Bad projects: one line naming the
# file and the JSON path, exit 1, nothing written.
gtlab=$1
work=$2
schema=$3
stages=${4:-ao}  # the slower scene-driven stages (gtao: a minute of CPU per scene) by hand: ... ao,gtao
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"

# init: written once, refused the second time, the file unchanged.
expect_ok init init -o "$work/gtlab.json"
before=$(md5sum <"$work/gtlab.json")
expect_error init-twice "gtlab.json: already exists" "" -- init -o "$work/gtlab.json"
[ "$(md5sum <"$work/gtlab.json")" = "$before" ] && pass || fail "init overwrote gtlab.json"
if python3 -c 'import jsonschema' 2>/dev/null; then
  python3 - "$schema" "$work/gtlab.json" <<'PY' && pass || fail "gtlab init's file does not follow docs/gtlab.schema.json"
import json, sys, jsonschema
schema, doc = (json.load(open(p)) for p in sys.argv[1:3])
jsonschema.validate(doc, schema)
# The schema can fail: a misspelt key and a bad label are refused.
for bad in ({**doc, "stage": []}, {**doc, "scenes": [{"path": "a.glb", "label": "a b"}]}):
    try:
        jsonschema.validate(bad, schema)
        sys.exit("the schema accepted " + json.dumps(bad))
    except jsonschema.ValidationError:
        pass
PY
else
  echo "python3-jsonschema not installed: the schema check is skipped"
fi
# As written (its scene, quality and output), the stages overridden to one.
expect_ok init-runs all --project "$work/gtlab.json" --stages ao --threads 2
[ -s "$work/gtlab-results/ao/my-scene.exr" ] && pass || fail "the example's scene was not rendered into its output folder"

# A user's glTF with a label and its glTF camera.
expect_ok scene-write scene write sphere-on-plane -o "$work/user.glb"
label=user-shop
cat >"$work/project.json" <<JSON
{"_comment": "a test project", "quality": "production", "stages": ["specular-occlusion"], "output": "unused",
 "scenes": [{"path": "user.glb", "label": "$label", "cameras": [{"gltf": 0}]}]}
JSON
expect_ok project all --project "$work/project.json" --quality preview --stages "$stages" --threads 2 -o "$work/out"
[ ! -e "$work/unused" ] && pass || fail "-o did not override the project's output"
json_is quality == "'preview'" "$work/out/summary.json" && pass || fail "--quality did not override the project's quality"
python3 - "$work/out/summary.json" "$label" "$stages" <<'PY' && pass || fail "summary.json: $(tail -c 400 "$work/stdout")"
import json, sys
summary, label, stages = json.load(open(sys.argv[1])), sys.argv[2], sys.argv[3]
meta = {"gtlab_version", "quality", "project", "claims", "stage_seconds"}
times = summary["stage_seconds"]  # each stage's wall time, by its --stages key, and the total
assert set(times) == set(stages.split(",")) | {"total"}, times
assert all(t >= 0 for t in times.values()) and times["total"] >= max(times.values()) - 1e-9, times
sections = [k for k in summary if k not in meta]
def strings(v):
    if isinstance(v, dict):
        for x in v.values(): yield from strings(x)
    elif isinstance(v, list):
        for x in v: yield from strings(x)
    elif isinstance(v, str):
        yield v
assert summary["project"]["scenes"][0]["label"] == label, summary["project"]
assert summary["project"]["scenes"][0]["gltf_camera"] == 0, summary["project"]
assert len(sections) >= len(stages.split(",")), (sections, stages)
for k in sections:
    found = set(strings(summary[k]))
    assert label in found, f"section {k} has no row of {label}"
    for builtin in ("menger", "cornell", "boxes", "corner"):
        assert builtin not in found, f"section {k} names the built-in {builtin}"
print("sections with the label:", ", ".join(sections))
PY
grep -q "$label" "$work/out/report.md" && pass || fail "report.md does not name $label"
grep -q -- "--project" "$work/out/report.md" && pass || fail "report.md does not say how it was made"
[ -s "$work/out/ao/$label.exr" ] && pass || fail "no ao/$label.exr"

# Two cameras of one scene: two entries, <label>-cam0 (its own camera) and
# <label>-door (a camera JSON file, whose pose the reference keeps; the
# stage sets the width, the file's aspect ratio the height).
printf '{"position":[0.5,1.5,4],"target":[0,0,0],"up":[0,1,0],"yfov_deg":40,"width":64,"height":32}' >"$work/door.json"
printf '{"scenes": [{"path": "builtin:plane", "label": "floor", "cameras": [{}, {"file": "door.json", "label": "door"}]}]}' \
  >"$work/two.json"
expect_ok two-cameras all --project "$work/two.json" --stages ao --threads 2 -o "$work/two"
python3 - "$work/two" <<'PY' && pass || fail "two cameras: $(ls "$work/two/ao" 2>&1)"
import json, sys
rows = json.load(open(sys.argv[1] + "/summary.json"))["ao_references"]
assert [r["scene"] for r in rows] == ["floor-cam0", "floor-door"], rows
door = json.load(open(sys.argv[1] + "/ao/floor-door.camera.json"))
assert door["position"] == [0.5, 1.5, 4] and (door["width"], door["height"]) == (256, 128), door
own = json.load(open(sys.argv[1] + "/ao/floor-cam0.camera.json"))
assert own["position"] != door["position"], own
PY

# Bad projects: the file and the JSON path named, nothing written.
bad() {  # bad NAME PATTERN JSON
  printf '%s' "$3" >"$work/bad.json"
  expect_error "$1" "bad.json: $2" "$work/bad_out" -- all --project "$work/bad.json" -o "$work/bad_out"
}
bad missing-scene "scenes\[0\]\.path: .*missing.glb: No such file" '{"scenes": [{"path": "missing.glb"}]}'
bad unknown-stage "stages\[1\]: unknown stage 'nope'" '{"stages": ["ao", "nope"]}'
bad renamed-stage "stages\[1\]: stage 'normals' is now 'best-fit-normals'" '{"stages": ["ao", "normals"]}'
bad bad-label "scenes\[0\]\.label: label 'a b'" '{"scenes": [{"path": "user.glb", "label": "a b"}]}'
bad gltf-camera "scenes\[0\]\.cameras\[1\]: .*camera 4 does not exist" '{"scenes": [{"path": "user.glb", "cameras": [{}, {"gltf": 4}]}]}'
bad camera-name "scenes\[0\]\.cameras\[0\]: .*no camera named 'Top'" '{"scenes": [{"path": "user.glb", "cameras": [{"gltf": "Top"}]}]}'
bad camera-file "scenes\[0\]\.cameras\[0\]\.file: .*nocam.json" '{"scenes": [{"path": "user.glb", "cameras": [{"file": "nocam.json"}]}]}'
bad same-label "scenes\[1\]: label 'user' is used twice" '{"scenes": [{"path": "user.glb"}, {"path": "user.glb"}]}'
bad unknown-key ".*unknown key 'scene'" '{"scene": []}'
bad quality "quality: 'preview' or 'production'" '{"quality": "fast"}'
# The file's stages apply when the command line names none: gtao alone
# needs the ao stage's output, which a new folder does not have.
printf '{"stages": ["gtao"], "scenes": [{"path": "user.glb"}]}' >"$work/bad.json"
expect_error file-stages "stage gtao reads what stage ao writes" "$work/bad_out" -- all --project "$work/bad.json" -o "$work/bad_out"
bad not-json ".*at line 1, column 13" '{"scenes": ['
finish
