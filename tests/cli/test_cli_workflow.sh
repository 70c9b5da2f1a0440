#!/usr/bin/env bash
# What a user does with gtlab, end to end: help, scenes, renders, the camera
# written beside them, merge, compare; and the promises: same bits for any
# thread count, merge of halves = the whole, a written .glb renders like the
# built-in scene it came from.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"

for verb in scene render merge compare bench all; do
  run "$verb" --help
  if [ "$status" -eq 0 ] && grep -q "usage: gtlab $verb" "$work/stdout"; then pass; else fail "$verb --help"; fi
done
expect_ok help --help

run scene list
for name in plane sphere-on-plane corner menger boxes cornell; do
  if grep -q "^$name" "$work/stdout"; then pass; else fail "scene list lacks $name"; fi
done

# Same inputs and seed: the same file, byte for byte, with 1 and 2 threads.
common=(--scene builtin:cornell --width 40 --height 30 --spp 32 --seed 5)
expect_ok render-1-thread render ao "${common[@]}" --threads 1 -o "$work/t1.exr"
expect_ok render-2-threads render ao "${common[@]}" --threads 2 -o "$work/t2.exr"
if cmp -s "$work/t1.exr" "$work/t2.exr"; then pass; else fail "1 and 2 threads give different files"; fi

# The camera used is written beside the output, and reproduces the render.
if [ -s "$work/t1.camera.json" ]; then pass; else fail "no t1.camera.json"; fi
expect_ok render-with-camera render ao --scene builtin:cornell --camera "$work/t1.camera.json" --spp 32 --seed 5 -o "$work/t3.exr"
run compare "$work/t1.exr" "$work/t3.exr" --json
json_is max_abs == 0 "$work/stdout" && pass || fail "render from the written camera differs: $(cat "$work/stdout")"

# Two halves merged = the whole render.
expect_ok half-1 render ao "${common[@]}" --spp 16 -o "$work/h1.exr"
expect_ok half-2 render ao "${common[@]}" --spp 16 --sample-offset 16 -o "$work/h2.exr"
expect_ok merge merge "$work/h1.exr" "$work/h2.exr" -o "$work/merged.exr"
for channel in ao.V ao.V.stderr ao.Vuniform bent.X; do
  run compare "$work/t1.exr" "$work/merged.exr" --channel $channel --json
  json_is max_abs == 0 "$work/stdout" && pass || fail "merged $channel differs from the whole: $(cat "$work/stdout" "$work/stderr")"
done

# The control variate's halves merge into its whole render; a plain half
# and a control-variate half do not merge (one line naming the file).
expect_ok cv-whole render ao "${common[@]}" --control-variate heightfield -o "$work/cv.exr"
expect_ok cv-half-1 render ao "${common[@]}" --spp 16 --control-variate heightfield -o "$work/cv1.exr"
expect_ok cv-half-2 render ao "${common[@]}" --spp 16 --sample-offset 16 --control-variate heightfield -o "$work/cv2.exr"
expect_ok cv-merge merge "$work/cv1.exr" "$work/cv2.exr" -o "$work/cv_merged.exr"
for channel in ao.V ao.V.stderr ao.Vuniform bent.X; do
  run compare "$work/cv.exr" "$work/cv_merged.exr" --channel $channel --json
  json_is max_abs == 0 "$work/stdout" && pass || fail "merged control-variate $channel differs: $(cat "$work/stdout" "$work/stderr")"
done
expect_error cv-mixed "h1.exr: its gtlab.control_variate is none" "$work/mixed.exr" -- merge "$work/cv2.exr" "$work/h1.exr" -o "$work/mixed.exr"

# A built-in scene written as .glb renders as the built-in does.
expect_ok scene-write scene write sphere-on-plane -o "$work/sop.glb"
expect_ok render-builtin render ao --scene builtin:sphere-on-plane --width 48 --height 48 --spp 16 -o "$work/b.exr"
expect_ok render-glb render ao --scene "$work/sop.glb" --width 48 --height 48 --spp 16 -o "$work/g.exr"
run compare "$work/b.exr" "$work/g.exr" --json
json_is max_abs == 0 "$work/stdout" && pass || fail "glb render differs from built-in: $(cat "$work/stdout")"

# scene info: a primitive without normals (Debian's assimp Cameras.gltf) is
# said to be flat-shaded; a built-in scene's meshes have normals.
expect_ok scene-info-flat scene info /usr/share/assimp/models/glTF2/cameras/Cameras.gltf
grep -q "mesh 0: 2 triangles, 6 vertices, .*no normals: flat-shaded" "$work/stdout" && pass || fail "scene info: $(cat "$work/stdout")"
expect_ok scene-info-builtin scene info builtin:sphere-on-plane
grep -q "flat" "$work/stdout" && fail "scene info builtin: $(cat "$work/stdout")" || pass

# scene info says how a glTF file was read (issue 30): strips, Draco with its
# position grid step, skins in the default pose.
models=/usr/share/assimp/models/glTF2
expect_ok scene-info-strip scene info "$models/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf"
grep -q "^primitives: 0 triangle lists, 1 triangle strips, 0 triangle fans" "$work/stdout" && pass || fail "scene info strip: $(cat "$work/stdout")"
expect_ok scene-info-draco scene info "$models/draco/2CylinderEngine.gltf"
grep -q "^glTF extensions used: KHR_draco_mesh_compression$" "$work/stdout" && grep -q "Draco-compressed: 115 primitives" "$work/stdout" &&
  grep -q "^positions quantized to a grid of at most" "$work/stdout" && pass || fail "scene info draco: $(cat "$work/stdout")"
expect_ok scene-info-skin scene info "$models/simple_skin/simple_skin.gltf"
grep -q "skinned (default pose): 1 primitives; without normals (flat-shaded): 1 primitives" "$work/stdout" && pass || fail "scene info skin: $(cat "$work/stdout")"

# compare: identical files, heatmap, noise floor.
run compare "$work/t1.exr" "$work/t1.exr" --json --noise-floor --heatmap "$work/heat.png"
json_is ssim == 1 "$work/stdout" && pass || fail "self-compare SSIM is not 1: $(cat "$work/stdout")"
json_is noise_floor_dssim '>' 0 "$work/stdout" && pass || fail "noise floor is not positive"
[ -s "$work/heat.png" ] && pass || fail "no heatmap written"
json_is flip == 0 "$work/stdout" && pass || fail "self-compare FLIP is not 0: $(grep flip "$work/stdout")"
# compare prints FLIP beside DSSIM; --scale fixes the heatmap's full scale;
# its colour bar (default on) adds 2 max(4, h / 16) rows (issue 41).
"$gtlab" render ao --scene builtin:cornell --width 40 --height 30 --spp 4 --seed 7 -o "$work/t7.exr" >/dev/null 2>&1
run compare "$work/t1.exr" "$work/t7.exr" --heatmap "$work/bar.png" --scale 0.25
grep -q "^  FLIP          [0-9.e-]* (LDR-FLIP of B against A)" "$work/stdout" && pass || fail "no FLIP line: $(cat "$work/stdout")"
grep -q "full scale 0.25 (fixed by --scale).*colour bar below it" "$work/stdout" && pass || fail "scale: $(tail -1 "$work/stdout")"
python3 - "$work/bar.png" "$work/t7.exr" <<'PY' && pass || fail "the heatmap with its bar has the wrong size"
import subprocess, sys
size = lambda f: subprocess.run(["oiiotool", "--info", f], capture_output=True, text=True).stdout.split(":")[1].split(",")[0].split("x")
w, h = map(int, size(sys.argv[1])); W, H = map(int, size(sys.argv[2]))
assert w == W and h == H + 2 * max(4, H // 16), (w, h, W, H)
PY
run compare "$work/t1.exr" "$work/t7.exr" --json --heatmap "$work/nobar.png" --colour-bar off --scale 0.25
json_is flip '>' 0 "$work/stdout" && pass || fail "FLIP of two renders is 0"
python3 -c 'import json,sys; h=json.load(open(sys.argv[1]))["heatmap"]; sys.exit(0 if h["vmax"] == 0.25 and h["colour_bar"] is False else 1)' \
  "$work/stdout" && pass || fail "--scale/--colour-bar off in the JSON: $(cat "$work/stdout")"
expect_error scale-alone "--scale: sets the heatmap: add --heatmap F.png" "" -- compare "$work/t1.exr" "$work/t7.exr" --scale 0.25
no_leftovers "$work"
finish
