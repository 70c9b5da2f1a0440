#!/usr/bin/env bash
# Every bad input gives one line "gtlab: <file>: <problem>", exit status 1, and
# no output file — or, where the input is usable, a warning and a good render.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"
out=$work/out.exr
assimp=/usr/share/assimp/models/glTF2

render_gbuffer() { echo render gbuffer --scene "$1" --width 32 --height 32 -o "$out"; }

# glTF 1.0 files (assimp-testmodels keeps a few): refused as what they are.
gltf1=/usr/share/assimp/models/glTF
expect_error gltf-1 "BoxTextured.gltf: glTF 1.0 is not supported: gtlab reads glTF 2.0" "$out" -- $(render_gbuffer $gltf1/BoxTextured-glTF/BoxTextured.gltf)
expect_error glb-1 "BoxTextured.glb: GLB version 1 is not supported" "$out" -- $(render_gbuffer $gltf1/BoxTextured-glTF-Binary/BoxTextured.glb)
printf '{"scenes":{"s":{"nodes":[]}},"meshes":{}}' >"$work/old-layout.gltf"
expect_error gltf-1-without-asset "old-layout.gltf: glTF 1.0 is not supported" "$out" -- $(render_gbuffer "$work/old-layout.gltf")

# The deliberately broken files of Debian's assimp-testmodels.
expect_error infinites "BoxWithInfinites.glb: .*not finite" "$out" -- $(render_gbuffer $assimp/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb)
expect_error index-out-of-range "IndexOutOfRange.gltf: .*out of range" "$out" -- $(render_gbuffer $assimp/IndexOutOfRange/IndexOutOfRange.gltf)
expect_error missing-bin "BoxTextured.gltf: .*BoxTextured0.bin" "$out" -- $(render_gbuffer $assimp/MissingBin/BoxTextured.gltf)
expect_error recursive-nodes "RecursiveNodes.gltf: .*cycle" "$out" -- $(render_gbuffer $assimp/RecursiveNodes/RecursiveNodes.gltf)
expect_error incorrect-vertex-arrays "Cube.gltf: " "$out" -- $(render_gbuffer $assimp/IncorrectVertexArrays/Cube.gltf)

# BoxBadNormals is usable: a warning, then a render with recomputed normals.
run render gbuffer --scene $assimp/BoxBadNormals-glTF-Binary/BoxBadNormals.glb --width 32 --height 32 -o "$out"
if [ "$status" -eq 0 ] && grep -q "^gtlab: warning: .*BoxBadNormals.glb: .*normals" "$work/stderr" && [ -s "$out" ]; then
  pass
else
  fail "BoxBadNormals: expected a warning and a render (status $status): $(cat "$work/stderr")"
fi

# Our own broken files.
"$gtlab" scene write plane -o "$work/plane.glb" || fail "scene write"
head -c 300 "$work/plane.glb" >"$work/truncated.glb"
expect_error truncated-glb "truncated.glb: " "$out" -- $(render_gbuffer "$work/truncated.glb")
printf '{"asset":{"version":"2.0"},"scenes":[{"nodes":[]}],"scene":0}' >"$work/empty.gltf"
expect_error empty-scene "empty.gltf: .*no triangles" "$out" -- $(render_gbuffer "$work/empty.gltf")
printf '{"asset":{"version":"2.0"},"scenes":[{"nodes":[0' >"$work/broken-json.gltf"
expect_error invalid-json "broken-json.gltf: " "$out" -- $(render_gbuffer "$work/broken-json.gltf")
expect_error missing-file "nowhere.glb: " "$out" -- $(render_gbuffer "$work/nowhere.glb")

# A triangle given as three floats each, base64: vertex 1 holds a NaN.
triangle_gltf() { # $1 = base64 of 36 bytes of positions, $2 = mode
  cat <<JSON
{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":$2}]}],
 "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,$1"}],
 "bufferViews":[{"buffer":0,"byteLength":36}],
 "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]}
JSON
}
good=$(printf '\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x80\x3f\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x80\x3f\x00\x00\x00\x00' | base64 -w0)
nan=$(printf '\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\xc0\x7f\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x80\x3f\x00\x00\x00\x00' | base64 -w0)
triangle_gltf "$nan" 4 >"$work/nan.gltf"
expect_error nan-position "nan.gltf: .*not finite" "$out" -- $(render_gbuffer "$work/nan.gltf")
triangle_gltf "$good" 0 >"$work/points.gltf"
expect_error points-only "points.gltf: .*no triangles" "$out" -- $(render_gbuffer "$work/points.gltf")

# A texture that is not there: a warning, and the base-colour factor is used.
cat >"$work/missing-texture.gltf" <<JSON
{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],
 "materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1],"baseColorTexture":{"index":0}}}],
 "textures":[{"source":0}],"images":[{"uri":"no-such-image.png"}],
 "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,$good"}],
 "bufferViews":[{"buffer":0,"byteLength":36}],
 "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]}
JSON
run render gbuffer --scene "$work/missing-texture.gltf" --width 32 --height 32 -o "$out"
if [ "$status" -eq 0 ] && grep -q "^gtlab: warning: .*missing-texture.gltf: .*no-such-image.png" "$work/stderr" && [ -s "$out" ]; then
  pass
else
  fail "missing texture: expected a warning and a render (status $status): $(cat "$work/stderr")"
fi

# Options and paths.
expect_error spp-zero "--spp: 0 is out of range" "$out" -- render ao --scene builtin:plane --spp 0 -o "$out"
expect_error spp-text "--spp: 'many' is not a whole number" "$out" -- render ao --scene builtin:plane --spp many -o "$out"
expect_error unwritable "/nonexistent/folder/out.exr: cannot write: the folder /nonexistent/folder does not exist" "" -- render ao --scene builtin:plane -o /nonexistent/folder/out.exr
printf x >"$work/plain-file"
expect_error output-under-a-file "plain-file/out.exr: cannot write: a part of .*plain-file is a file, not a folder" "" -- render ao --scene builtin:plane -o "$work/plain-file/out.exr"
mkdir -p "$work/a-folder"
expect_error output-is-folder "a-folder: cannot write: is a folder" "" -- render ao --scene builtin:plane -o "$work/a-folder"
expect_error unknown-builtin "builtin:teapot: unknown built-in scene" "$out" -- render ao --scene builtin:teapot -o "$out"
expect_error unknown-quantity "unknown quantity 'smoke'" "$out" -- render smoke --scene builtin:plane -o "$out"
expect_error bad-control-variate "--control-variate: 'gtao' is not none or heightfield" "$out" -- render ao --scene builtin:plane --control-variate gtao -o "$out"
expect_error control-variate-not-ao "--control-variate: applies to ao only" "$out" -- render heightfield-ao --scene builtin:plane --control-variate heightfield -o "$out"
expect_error unknown-verb "frobnicate: unknown verb" "" -- frobnicate
expect_error unknown-option "render: unknown option '--colour' (see 'gtlab render --help')" "$out" -- render ao --scene builtin:plane --colour red -o "$out"
expect_error misspelt-option "render: unknown option '--sppp' (did you mean '--spp'?)" "$out" -- render ao --scene builtin:plane --sppp 4 -o "$out"
expect_error option-without-value "render: --spp needs a value" "$out" -- render ao --scene builtin:plane -o "$out" --spp
expect_error normal-mode "--normal: 'bumpy'" "$out" -- render ao --scene builtin:plane --normal bumpy -o "$out"

# Environments: a name that is neither a built-in nor a file, and an LDR image.
env_render() { echo render env-diffuse --scene builtin:plane --albedo 0.5 --spp 1 --width 8 --height 8 --environment "$1" -o "$out"; }
expect_error environment-unknown "--environment: 'sunset' is not white, sky or sun, nor a file" "$out" -- $(env_render sunset)
oiiotool --pattern constant:color=0.5,0.5,0.5 64x32 3 -d uint8 -o "$work/ldr.jpg"
expect_error environment-ldr "ldr.jpg: stores integer (8- or 16-bit, display-referred) texels, not radiance" "$out" -- $(env_render "$work/ldr.jpg")
oiiotool --pattern constant:color=0.5,0.5,0.5 64x32 3 -d half -o "$work/hdr.exr"
expect_ok environment-half-float $(env_render "$work/hdr.exr")

# Camera JSON.
printf '{"position":[0,1,5],"target":[0,0' >"$work/cam-malformed.json"
expect_error camera-malformed "cam-malformed.json: JSON text ends early" "$out" -- render ao --scene builtin:plane --camera "$work/cam-malformed.json" -o "$out"
printf '{"position":[0,1,5],"target":[0,0,0],"yfov_deg":45,"width":64}' >"$work/cam-no-height.json"
expect_error camera-missing-key 'cam-no-height.json: camera JSON lacks "height"' "$out" -- render ao --scene builtin:plane --camera "$work/cam-no-height.json" -o "$out"
printf '{"position":[0,1,5],"target":[0,1,5],"yfov_deg":45,"width":64,"height":64}' >"$work/cam-degenerate.json"
expect_error camera-degenerate "cam-degenerate.json: camera position and target coincide" "$out" -- render ao --scene builtin:plane --camera "$work/cam-degenerate.json" -o "$out"
printf '{"position":[0,1,5],"target":[0,0,0],"yfov_deg":190,"width":64,"height":64}' >"$work/cam-fov.json"
expect_error camera-fov "cam-fov.json: yfov_deg must be in" "$out" -- render ao --scene builtin:plane --camera "$work/cam-fov.json" -o "$out"
printf '{"position":[0,1,5],"target":[0,0,0],"yfov_deg":45,"width":1e20,"height":64}' >"$work/cam-huge.json"
expect_error camera-huge 'cam-huge.json: "width" must be a whole number' "$out" -- render ao --scene builtin:plane --camera "$work/cam-huge.json" -o "$out"
printf '{"position":[0,1,5],"target":[0,0,0],"yfov_deg":45,"width":64,"height":64,"width":8}' >"$work/cam-twice.json"
expect_error camera-duplicate-key "cam-twice.json: duplicate key 'width' at . (a key may appear once" "$out" -- render ao --scene builtin:plane --camera "$work/cam-twice.json" -o "$out"
printf '{"quality":"preview","scenes":[{"path":"builtin:plane","path":"builtin:boxes"}]}' >"$work/project-twice.json"
expect_error project-duplicate-key "project-twice.json: duplicate key 'path' at ..scenes.0. " "$work/project-twice-out/report.md" -- all --project "$work/project-twice.json" --stages ao -o "$work/project-twice-out"
expect_error camera-missing "no-camera.json: cannot open" "$out" -- render ao --scene builtin:plane --camera "$work/no-camera.json" -o "$out"

# compare and merge.
expect_ok small-render render ao --scene builtin:plane --width 16 --height 16 --spp 4 -o "$work/small.exr"
expect_ok other-render render ao --scene builtin:plane --width 24 --height 24 --spp 4 -o "$work/other.exr"
expect_error compare-size "other.exr: size 24x24 differs" "" -- compare "$work/small.exr" "$work/other.exr"
expect_error compare-channel "fog.V" "" -- compare "$work/small.exr" "$work/small.exr" --channel fog.V
expect_error compare-missing "absent.exr: " "" -- compare "$work/small.exr" "$work/absent.exr"
echo "not an exr" >"$work/fake.exr"
expect_error compare-not-exr "fake.exr: " "" -- compare "$work/small.exr" "$work/fake.exr"
expect_error merge-overlap "small.exr: .*counted twice" "$work/merged.exr" -- merge "$work/small.exr" "$work/small.exr" -o "$work/merged.exr"
expect_error merge-different "other.exr: size 24x24 differs" "$work/merged.exr" -- merge "$work/small.exr" "$work/other.exr" -o "$work/merged.exr"
expect_ok gbuffer-render render gbuffer --scene builtin:plane --width 16 --height 16 -o "$work/g.exr"
expect_ok other-seed render ao --scene builtin:plane --width 16 --height 16 --spp 4 --max-distance 2 -o "$work/limited.exr"
expect_error merge-settings "limited.exr: its gtlab.settings differs from the first input's ('max_distance=2.*' against 'max_distance=inf.*'): not parts of one render" "$work/merged.exr" -- merge "$work/small.exr" "$work/limited.exr" -o "$work/merged.exr"
expect_error merge-gbuffer "g.exr: no Monte Carlo accumulator" "$work/merged.exr" -- merge "$work/g.exr" "$work/small.exr" -o "$work/merged.exr"
# lut atmosphere: an axis size out of range is refused before any work.
expect_error lut-atmosphere-size "--theta-v: 0 is out of range" "$work/atmosphere/atmosphere_luts.h" -- lut atmosphere --theta-v 0 -o "$work/atmosphere"
expect_error lut-atmosphere-size-high "--weathers: 300 is out of range" "$work/atmosphere/atmosphere_luts.h" -- lut atmosphere --weathers 300 -o "$work/atmosphere"
# the nonlinear parametrizations' split view axis needs an even size of at least 4; an unknown one is refused
expect_error lut-atmosphere-yusov-odd "--theta-v: .*Yusov 2013 view axis needs an even size" "$work/atmosphere/atmosphere_inscatter_yusov2013.exr" -- lut atmosphere --parametrization yusov2013 --theta-v 63 -o "$work/atmosphere"
expect_error lut-atmosphere-unknown-parametrization "--parametrization" "$work/atmosphere/atmosphere_inscatter.exr" -- lut atmosphere --parametrization yusov -o "$work/atmosphere"
# --help names the parametrizations; yusov2013 writes its three EXRs only (the shaders' lookup is linear)
help=$("$gtlab" lut atmosphere --help)
grep -q "linear (default" <<<"$help" && grep -q "yusov2013 (the talk's \[Yus13\])" <<<"$help" && grep -q "bruneton2008 (Bruneton & Neyret 2008)" <<<"$help" && pass || fail "lut atmosphere --help does not name the parametrizations"
expect_ok lut-atmosphere-yusov lut atmosphere --parametrization yusov2013 --weathers 1 --light-theta-s 2 --threads 2 -o "$work/atmosphere-yusov"
ls "$work/atmosphere-yusov" | tr '\n' ' ' | grep -qx "atmosphere_inscatter_yusov2013.exr atmosphere_sky_yusov2013.exr atmosphere_sun_yusov2013.exr " && pass || fail "lut atmosphere yusov2013 wrote: $(ls "$work/atmosphere-yusov")"
# gtlab all --stages: unknown or empty lists are refused before any work;
# one stage gives a report with that section only.
expect_error all-unknown-stage "--stages: unknown stage 'smoke'" "" -- all --stages ao,smoke -o "$work/all"
# A stage's former name is refused with its name today (issue 43), in a project too (test_cli_project.sh).
expect_error all-renamed-stage "--stages: stage 'aa' is now 'anti-aliasing'" "" -- all --stages ao,aa -o "$work/all"
expect_error approx-renamed "approx raymarch: 'raymarch' is now 'volumetric-light'" "" -- approx raymarch -o "$work/v.exr"
expect_error bench-renamed "bench: 'fog' is now 'height-fog'" "" -- bench fog
expect_error all-no-stage "--stages: no stage named in ','" "" -- all --stages , -o "$work/all"
# A stage whose input another stage makes is refused when that input is absent.
expect_error all-missing-input "stage gtao reads what stage ao writes" "$work/all_empty/report.md" -- all --stages gtao -o "$work/all_empty"
expect_ok all-one-stage all --stages throughput -o "$work/all"
python3 - "$work/all" <<'PY' && pass || fail "all --stages throughput: report or summary.json holds other stages"
import json, sys
summary = json.load(open(sys.argv[1] + "/summary.json"))
assert set(summary) == {"gtlab_version", "quality", "study_scenes", "ray_throughput", "stage_seconds"}, set(summary)
assert set(summary["stage_seconds"]) == {"throughput", "total"}, summary["stage_seconds"]
sections = [l for l in open(sys.argv[1] + "/report.md") if l.startswith("## ")]
assert sections == ["## At a glance\n", "## Contents\n", "## Ray throughput\n"], sections
PY
# A camera inside geometry (inside box (0, 0) of builtin:boxes): the render is
# written, with a warning naming the mean AO and the camera (issue 41); the
# scene's own view gives none.
printf '{"position":[-10.5,1,-11],"target":[0,1,0],"up":[0,1,0],"yfov_deg":60,"width":32,"height":24}' >"$work/inside.json"
run render ao --scene builtin:boxes --camera "$work/inside.json" --spp 16 -o "$work/inside.exr"
if [ "$status" -eq 0 ] && [ -s "$work/inside.exr" ] &&
  grep -q "^gtlab: warning: builtin:boxes: mean AO 0.0000 .*is the camera (at -10.5, 1, -11) inside geometry" "$work/stderr"; then
  pass
else
  fail "camera inside a box: status $status, stderr: $(cat "$work/stderr")"
fi
run render ao --scene builtin:boxes --width 32 --height 24 --spp 16 -o "$work/outside.exr"
grep -q "inside geometry" "$work/stderr" && fail "the scene's own view warned: $(cat "$work/stderr")" || pass
finish
