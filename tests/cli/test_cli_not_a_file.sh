#!/usr/bin/env bash
# Unbounded reads (issue 41, defect 4): a device, a FIFO or a folder given as
# any kind of input is refused at once (under `timeout 5`, so a reader that
# opens a FIFO and waits fails instead of blocking the test) with one line
# saying what it is; and an EXR whose 3 KB claim 16384 x 8192 pixels is
# refused before anything is allocated (under a 1 GB address-space limit,
# where allocating its 1.6 GB fails differently).
gtlab=$1
work=$2
source_dir=$3
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"
cd "$work" || exit 1

small="--width 6 --height 6 --spp 2"
"$gtlab" render ao --scene builtin:plane $small -o ao.exr >/dev/null 2>&1 || fail "render ao"
mkfifo fifo && mkdir folder || fail "mkfifo, mkdir"
# A .gltf whose buffer is the thing itself (tinygltf reads it by its uri).
gltf_naming() {
  printf '{"asset":{"version":"2.0"},"buffers":[{"uri":"%s","byteLength":36}],"bufferViews":[{"buffer":0,"byteLength":36}],' "$1"
  printf '"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],'
  printf '"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}\n'
}
# A project naming the thing as its scene's camera file.
project_naming() { printf '{"scenes": [{"path": "builtin:plane", "cameras": [{"file": "%s"}]}]}\n' "$1"; }

# kind: the words the message must hold.
declare -A what=([/dev/zero]="is a character device" [fifo]="is a FIFO (named pipe)" [folder]="is a directory")

# expect_refused NAME THING ARGS...: exit 1 within 5 s, one line naming THING
# and saying what it is.
expect_refused() {
  local name=$1 thing=$2
  shift 2
  timeout 5 "$gtlab" "$@" >stdout 2>stderr
  status=$?
  if [ "$status" -eq 124 ]; then
    fail "$name: still running after 5 s (blocked on $thing?)"
  elif [ "$status" -ne 1 ]; then
    fail "$name: exit status $status, expected 1: $(head -c 300 stderr)"
  elif [ "$(wc -l <stderr)" -ne 1 ]; then
    fail "$name: $(wc -l <stderr) lines on stderr: $(head -c 500 stderr)"
  elif ! grep -qF "$thing: ${what[$thing]}" stderr; then
    fail "$name: the message does not say '$thing: ${what[$thing]}': $(cat stderr)"
  else
    pass
  fi
}

for x in /dev/zero fifo folder; do
  gltf_naming "$x" >"buffer-$(basename $x).gltf"
  project_naming "$x" >"project-$(basename $x).json"
  expect_refused "scene $x" "$x" render ao --scene "$x" $small -o out.exr
  expect_refused "gltf buffer $x" "$x" render ao --scene "buffer-$(basename $x).gltf" $small -o out.exr
  expect_refused "camera $x" "$x" render ao --scene builtin:plane --camera "$x" $small -o out.exr
  expect_refused "project $x" "$x" all --project "$x" --stages dfg -o out
  expect_refused "project camera $x" "$x" all --project "project-$(basename $x).json" --stages ao -o out
  expect_refused "merge $x" "$x" merge ao.exr "$x" -o out.exr
  expect_refused "compare $x" "$x" compare "$x" ao.exr
  expect_refused "fit multibounce $x" "$x" fit multibounce --data "$x" -o fit.json
  expect_refused "fit aperture $x" "$x" fit aperture --reference "$x" --ao ao.exr -o fit.json
  expect_refused "approx --gbuffer $x" "$x" approx gtao --gbuffer "$x" -o out.exr
  expect_refused "approx --camera $x" "$x" approx gtao --gbuffer ao.exr --camera "$x" -o out.exr
  expect_refused "environment $x" "$x" render env-diffuse --scene builtin:plane --albedo 0.5 --environment "$x" $small -o out.exr
  expect_refused "shader $x" "$x" shader run --shader "$x" --gbuffer ao.exr -o out.exr
  expect_refused "shader reference $x" "$x" shader run --shader "$source_dir/techniques/gtao/gtao.glsl" --gbuffer ao.exr --reference "$x" -o out.exr
  expect_refused "function $x" "$x" shader score --function "$x" ao.exr
  expect_refused "plug-in $x" "$x" shader score --plugin "$x" ao.exr
  expect_refused "scene info $x" "$x" scene info "$x"
done

# A 3 KB EXR claiming 16384 x 8192 pixels of 3 half channels (ZIP: at most
# 1032:1, so at most 3 MB of pixels): refused from its size, before the 1.6 GB
# image is allocated (the limit makes that allocation fail as "out of memory").
python3 - big.exr <<'PY'
import struct, sys
def attr(name, type_, value):
    return name.encode() + b"\0" + type_.encode() + b"\0" + struct.pack("<i", len(value)) + value
chans = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", 1, 0, 1, 1) for c in "BGR") + b"\0"
box = struct.pack("<iiii", 0, 0, 16384 - 1, 8192 - 1)
header = (b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + attr("channels", "chlist", chans) +
          attr("compression", "compression", b"\x03") + attr("dataWindow", "box2i", box) +
          attr("displayWindow", "box2i", box) + attr("lineOrder", "lineOrder", b"\0") +
          attr("pixelAspectRatio", "float", struct.pack("<f", 1)) +
          attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
          attr("screenWindowWidth", "float", struct.pack("<f", 1)) + b"\0")
open(sys.argv[1], "wb").write(header + b"\0" * (3072 - len(header)))
PY
cmp -s big.exr "$source_dir/tests/fuzz/regressions/exr/oversized-data-window" || fail "big.exr is not the fuzz regression input"
# AddressSanitizer reserves terabytes of shadow memory, so under it the
# limit is left out (the refusal's message still shows it came first).
memory_limit=1000000
ldd "$gtlab" 2>/dev/null | grep -q libasan && memory_limit=unlimited
for verb in "compare big.exr ao.exr" "merge big.exr ao.exr -o out.exr" "approx gtao --gbuffer big.exr -o out.exr"; do
  # shellcheck disable=SC2086
  (ulimit -v $memory_limit && timeout 5 "$gtlab" $verb >stdout 2>stderr)
  status=$?
  if [ "$status" -ne 1 ] || [ "$(wc -l <stderr)" -ne 1 ] ||
     ! grep -q "^gtlab: big.exr: the header claims a data window of 134217728 pixels of 6 bytes, more than a file of 3072 bytes can hold (at most 1032:1 for its compression)" stderr; then
    fail "$verb: status $status: $(head -c 400 stderr)"
  else
    pass
  fi
done
# The bound refuses no real file: a 6x6 render read as a G-buffer.
expect_ok "a small EXR" approx gtao --gbuffer ao.exr -o out.exr

finish
