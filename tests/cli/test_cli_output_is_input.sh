#!/usr/bin/env bash
# An input given as an output is refused, never destroyed (issue 41, defect 2):
# for every verb that writes and reads a file, an output (or a sidecar the
# verb derives from it) that is one of the run's inputs, spelled the same,
# with ./, through sub/../, as a symbolic link or as a hard link to it, makes
# gtlab exit 1 with one line "gtlab: <output>: is also an input of this run
# (...)" before any work, and the input's bytes stay what they were.
#
# Verbs and subcommands that write but read no file (lut *, check sphere-noh,
# fit sphere-light, fit sg-ndf, approx volumetric-light, bench convergence, init,
# scene write of a built-in scene) have no input to lose; shader score and the
# other benchmarks write nothing.
#
# Usage: test_cli_output_is_input.sh GTLAB WORK SOURCE_DIR K/N: runs the
# cases whose index is K modulo N (ctest runs the parts side by side), and
# with part 0 also the cases after the table.
gtlab=$1
work=$2
source_dir=$3
part=${4:-0/1}
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"
inputs=$work/inputs
mkdir -p "$inputs"

# The inputs, made once: a camera, a glTF scene, two AO renders, a
# multi-bounce render, a G-buffer, a shader, a project.
small="--width 6 --height 6 --spp 2"
"$gtlab" render ao --scene builtin:plane $small -o "$inputs/exr" >/dev/null 2>&1 || fail "render ao"
"$gtlab" render ao --scene builtin:plane $small --seed 2 -o "$inputs/exr2.exr" >/dev/null 2>&1 || fail "render ao 2"
cp "$inputs/exr.camera.json" "$inputs/cam"
"$gtlab" render gbuffer --scene builtin:plane --width 6 --height 6 -o "$inputs/gbuffer" >/dev/null 2>&1 || fail "render gbuffer"
"$gtlab" render multibounce --scene builtin:corner --albedo 0.3,0.6 $small -o "$inputs/mb" >/dev/null 2>&1 ||
  fail "render multibounce"
"$gtlab" scene write plane -o "$inputs/scene.glb" >/dev/null || fail "scene write"
cp "$source_dir/techniques/gtao/gtao.glsl" "$inputs/glsl"
"$gtlab" init -o "$inputs/project" >/dev/null || fail "init"
cp "$inputs/exr2.exr" "$inputs/exr2.camera.json" "$work/"

# One case per line: name | input kind (a file of $inputs) | W, the file the
# run would write over the input | where the input lives for the link
# variants ("-": real.<W's extension>) | the command, with @IN@ for the input
# and @OUT@ for the output. A case whose W is a sidecar (the command names no
# @OUT@ for it) varies the input's spelling instead of the output's.
cases=(
  "render-output|cam|cam.json|-|render ao --scene builtin:plane --camera @IN@ $small -o @OUT@"
  "render-camera-sidecar|cam|out.camera.json|-|render ao --scene builtin:plane --camera @IN@ $small -o out.exr"
  "render-checkpoint|cam|out.checkpoint.exr|-|render ao --scene builtin:plane --camera @IN@ $small -o out.exr"
  "render-scene|scene.glb|s.glb|-|render ao --scene @IN@ $small -o @OUT@"
  "render-environment|exr|env.exr|-|render env-diffuse --scene builtin:plane --albedo 0.5 --environment @IN@ $small -o @OUT@"
  "render-frames|scene.glb|s.glb|-|render frames --scene @IN@ --frames 1 -o @OUT@"
  "merge|exr|a.exr|-|merge @IN@ exr2.exr -o @OUT@"
  "merge-second|exr|a.exr|-|merge exr2.exr @IN@ -o @OUT@"
  "compare-heatmap|exr|a.exr|-|compare @IN@ exr2.exr --heatmap @OUT@"
  "approx-gtao|gbuffer|g.exr|-|approx gtao --gbuffer @IN@ -o @OUT@"
  "approx-hbao-camera|cam|cam.json|-|approx hbao --gbuffer exr2.exr --camera @IN@ -o @OUT@"
  "approx-vo|gbuffer|g.exr|-|approx vo --gbuffer @IN@ -o @OUT@"
  "approx-alchemy|gbuffer|g.exr|-|approx alchemy --gbuffer @IN@ -o @OUT@"
  "approx-crytek|gbuffer|g.exr|-|approx crytek --gbuffer @IN@ -o @OUT@"
  "approx-specular-occlusion|exr|ao.exr|-|approx specular-occlusion --gbuffer exr2.exr --ao @IN@ -o @OUT@"
  "approx-height-fog|gbuffer|g.exr|-|approx height-fog --gbuffer @IN@ -o @OUT@"
  "approx-aa|scene.glb|s.glb|-|approx anti-aliasing --scene @IN@ -o @OUT@"
  "fit-multibounce|mb|mb.exr|-|fit multibounce --data @IN@ -o @OUT@"
  "fit-multibounce-argument|mb|mb.exr|-|fit multibounce --data exr2.exr @IN@ -o @OUT@"
  "fit-multibounce-header|mb|fit.h|-|fit multibounce --data @IN@ -o fit.json"
  "fit-multibounce-hlsl-sidecar|mb|fit.hlsl|-|fit multibounce --data @IN@ -o fit.json"
  "fit-multibounce-glsl|mb|g.glsl|-|fit multibounce --data @IN@ -o fit.json --glsl @OUT@"
  "fit-aperture|exr|r.exr|-|fit aperture --reference @IN@ --ao exr2.exr -o @OUT@"
  "fit-aperture-plot|exr|ao.exr|-|fit aperture --reference exr2.exr --ao @IN@ --plot @OUT@ -o fit.json"
  "fit-gtao-params|exr|refs/scene.exr|refs/scene.exr|fit gtao-params --refs refs -o @OUT@"
  "shader-run|glsl|gtao.glsl|-|shader run --shader @IN@ --gbuffer exr2.exr -o @OUT@"
  "shader-run-gbuffer|gbuffer|g.exr|-|shader run --shader $source_dir/techniques/gtao/gtao.glsl --gbuffer @IN@ -o @OUT@"
  "shader-run-reference|exr|r.exr|-|shader run --shader $source_dir/techniques/gtao/gtao.glsl --gbuffer exr2.exr --reference @IN@ -o @OUT@"
  "plan|scene.glb|s.glb|-|plan --jobs 2 -o @OUT@ -- render ao --scene @IN@ $small -o part.exr"
  "all-project|project|out/summary.json|-|all --stages dfg --project @IN@ -o out"
  "all-output-folder|project|p.json|-|all --stages dfg --project @IN@ -o @OUT@"
)

# run_case NAME KIND W REAL COMMAND VARIANT: in a fresh folder, places the
# input and runs the command with the variant's spellings.
run_case() {
  local name=$1 kind=$2 written=$3 real=$4 command=$5 variant=$6
  local dir=$work/$name-$variant in out sidecar=0
  rm -rf "$dir" && mkdir -p "$dir/sub" "$dir/out" "$dir/refs"
  cp "$work/exr2.exr" "$work/exr2.camera.json" "$dir/"
  [[ $command == *@OUT@* ]] || sidecar=1
  [ "$real" = - ] && real=real.${written##*.}
  case $variant in
  path | dot | dotdot) real=$written ;;
  esac
  [ "$real" = "$written" ] && [ "$variant" = symlink -o "$variant" = hardlink ] && written=link.${written##*.}
  cp "$inputs/$kind" "$dir/$real"
  cp "$inputs/$kind" "$dir/expected"
  in=$real out=$written
  case $variant in
  dot) if [ $sidecar = 1 ]; then in=./$real; else out=./$written; fi ;;
  dotdot) if [ $sidecar = 1 ]; then in=sub/../$real; else out=sub/../$written; fi ;;
  symlink) ln -s "$dir/$real" "$dir/$written" ;;
  hardlink) ln "$dir/$real" "$dir/$written" ;;
  esac
  command=${command//@IN@/$in}
  command=${command//@OUT@/$out}
  # shellcheck disable=SC2086
  (cd "$dir" && timeout 60 "$gtlab" $command >"$work/stdout" 2>"$work/stderr")
  status=$?
  local lines
  lines=$(wc -l <"$work/stderr")
  if [ "$status" -ne 1 ]; then
    fail "$name ($variant): exit status $status, expected 1: $(head -c 300 "$work/stderr") [gtlab $command]"
  elif [ "$lines" -ne 1 ]; then
    fail "$name ($variant): $lines lines on stderr, expected 1: $(head -c 500 "$work/stderr")"
  elif ! grep -q "^gtlab: .*: \(is also an input of this run\|holds an input of this run\)" "$work/stderr"; then
    fail "$name ($variant): not refused as an input: $(cat "$work/stderr")"
  elif ! cmp -s "$dir/$real" "$dir/expected"; then
    fail "$name ($variant): the input $real was changed"
  else
    pass
  fi
  no_leftovers "$dir"
}

# The spelling of "the same path" alternates between ./x and sub/../x.
for index in "${!cases[@]}"; do
  [ $((index % ${part#*/})) -eq "${part%/*}" ] || continue
  IFS='|' read -r name kind written real command <<<"${cases[$index]}"
  same=dot
  [ $((index % 2)) -eq 1 ] && same=dotdot
  for variant in path $same symlink hardlink; do
    run_case "$name" "$kind" "$written" "$real" "$command" "$variant"
  done
done
if [ "${part%/*}" != 0 ]; then
  finish
  exit
fi

# gtlab all: a scene the project names, inside a folder a stage writes.
dir=$work/all-stage-folder
mkdir -p "$dir/out/luts"
cp "$inputs/scene.glb" "$dir/out/luts/s.glb"
cp "$dir/out/luts/s.glb" "$dir/expected"
printf '{"scenes": [{"path": "out/luts/s.glb"}]}\n' >"$dir/p.json"
(cd "$dir" && "$gtlab" all --stages dfg --project p.json -o out >"$work/stdout" 2>"$work/stderr")
status=$?
if [ "$status" -ne 1 ] || [ "$(wc -l <"$work/stderr")" -ne 1 ] ||
   ! grep -q "^gtlab: out/luts: holds an input of this run (p.json: scenes\[0\]" "$work/stderr"; then
  fail "all-stage-folder: status $status: $(cat "$work/stderr")"
elif ! cmp -s "$dir/out/luts/s.glb" "$dir/expected"; then
  fail "all-stage-folder: the scene was changed"
else
  pass
fi

# An output that is no input is written as before (the check names no
# innocent file): a render beside the camera it was given.
(cd "$work" && cp "$inputs/cam" cam.json &&
  "$gtlab" render ao --scene builtin:plane --camera cam.json $small -o out.exr >/dev/null 2>"$work/stderr") &&
  [ -s "$work/out.exr" ] && [ -s "$work/out.camera.json" ] && cmp -s "$work/cam.json" "$inputs/cam" && pass ||
  fail "a render beside its camera: $(cat "$work/stderr")"

finish
