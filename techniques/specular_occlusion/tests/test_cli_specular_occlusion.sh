#!/usr/bin/env bash
# Specular occlusion as a user runs it: reference, approximation, compare,
# LUT, aperture fit and the reference's benchmark end to end, and their bad
# inputs (one error line, exit 1, no output).
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"

expect_ok "lut specular-occlusion --help" lut specular-occlusion --help
expect_ok "approx specular-occlusion --help" approx specular-occlusion --help
expect_ok "fit aperture --help" fit aperture --help
expect_ok "bench specular-occlusion --help" bench specular-occlusion --help
grep -q "^usage: gtlab bench specular-occlusion \[--scene S\] \[--width W\] \[--height H\] \[--threads T\] \[--repeats R\]" \
  "$work/stdout" && pass || fail "bench specular-occlusion --help: $(head -c 300 "$work/stdout")"

so=$work/so.exr ao=$work/ao.exr
expect_ok render-so render specular-occlusion --scene builtin:corner --width 40 --height 32 --spp 32 --roughness 0.4 -o "$so"
expect_ok render-ao render ao --scene builtin:corner --width 40 --height 32 --spp 32 -o "$ao"
for variant in lagarde lut cone-oat:phong-u; do
  expect_ok "approx $variant" approx specular-occlusion --gbuffer "$so" --ao "$ao" --variant $variant --lut-size 8 -o "$work/approx.exr"
  expect_ok "compare $variant" compare "$so" "$work/approx.exr" --channel specocc.V --json
done
# merge recomputes the ratio and split channels from the merged sums: same
# bits as one render (the sky adds channels, and changes none of the others)
expect_ok render-sky render specular-occlusion --scene builtin:corner --width 40 --height 32 --spp 32 --roughness 0.4 --environment sky -o "$work/sky.exr"
expect_ok render-block-1 render specular-occlusion --scene builtin:corner --width 40 --height 32 --spp 16 --roughness 0.4 --environment sky -o "$work/b1.exr"
expect_ok render-block-2 render specular-occlusion --scene builtin:corner --width 40 --height 32 --spp 16 --sample-offset 16 --roughness 0.4 --environment sky -o "$work/b2.exr"
expect_ok merge merge "$work/b1.exr" "$work/b2.exr" -o "$work/merged.exr"
for pair in "$so specocc.V.stderr" "$so specocc_phong.V" "$work/sky.exr split_truth.V.stderr" "$work/sky.exr split_two.V" "$work/sky.exr split_three.V"; do
  set -- $pair
  run compare "$1" "$work/merged.exr" --channel "$2" --json
  cp "$work/stdout" "$work/merged.json"
  json_is max_abs == 0 "$work/merged.json" && pass || fail "merged $2 differs: $(cat "$work/merged.json")"
done
expect_error bad-environment "--environment: 'dusk' is neither white nor sky" "$work/x.exr" -- render specular-occlusion --scene builtin:corner --environment dusk -o "$work/x.exr"
expect_error environment-ao "--environment: applies to specular-occlusion, env-diffuse and env-specular only" "$work/x.exr" -- render ao --scene builtin:corner --environment sky -o "$work/x.exr"
expect_ok lut lut specular-occlusion --size 8 -o "$work/lut"
for ext in exr png h json; do
  [ -s "$work/lut/specular_occlusion_ggx_8.$ext" ] && pass || fail "lut: no .$ext"
done
expect_ok fit fit aperture --reference "$so" --ao "$ao" -o "$work/fit.json"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if 0 < d['u'] < 1 and len(d['curve']) > 50 else 1)" "$work/fit.json" && pass || fail "fit.json"

expect_error bad-variant "--variant: unknown variant" "$work/x.exr" -- approx specular-occlusion --gbuffer "$so" --ao "$ao" --variant cone-exact:nope -o "$work/x.exr"
expect_error missing-ao "ao.exr" "$work/x.exr" -- approx specular-occlusion --gbuffer "$so" --ao "$work/ao.exr.missing" -o "$work/x.exr"
# GTAO's output (one weighting, no ao.Vuniform) feeds the cosine weighting, and
# only that: the uniform weighting names the missing channel.
expect_ok gtao approx gtao --gbuffer "$ao" --preset high -o "$work/gtao.exr"
expect_ok approx-on-gtao approx specular-occlusion --gbuffer "$so" --ao "$work/gtao.exr" --variant lut --lut-size 8 -o "$work/on_gtao.exr"
expect_error gtao-uniform "gtao.exr: no ao.Vuniform channel" "$work/x.exr" -- approx specular-occlusion --gbuffer "$so" --ao "$work/gtao.exr" --ao-weighting uniform -o "$work/x.exr"
expect_error not-ao "no channel ao.V" "$work/x.exr" -- approx specular-occlusion --gbuffer "$so" --ao "$so" -o "$work/x.exr"
expect_error bad-roughness "--roughness" "$work/x.exr" -- render specular-occlusion --scene builtin:plane --roughness 1.5 -o "$work/x.exr"
expect_error roughness-elsewhere "--roughness: applies to specular-occlusion and env-specular only" "$work/x.exr" -- render ao --scene builtin:plane --roughness 0.5 -o "$work/x.exr"
expect_error bad-size "--size" "" -- lut specular-occlusion --size 1 -o "$work/lut2"
expect_error unknown-table "unknown table" "" -- lut nope -o "$work/lut2"
expect_error fit-unpaired "one --ao per --reference" "$work/f.json" -- fit aperture --reference "$so" -o "$work/f.json"
# The benchmark: its table's rows on a tiny view (the figures are timings,
# not checked), and its options' bounds.
expect_ok bench bench specular-occlusion --scene builtin:corner --width 16 --height 16 --threads 2 --repeats 1
grep -q "^specular-occlusion reference on builtin:corner, 16x16, 64 spp, roughness 0.5 (best of 1)" "$work/stdout" &&
  grep -q "^samples/s " "$work/stdout" && grep -q "^speed-up threads / 1 thread " "$work/stdout" && pass ||
  fail "bench specular-occlusion: $(head -c 500 "$work/stdout")"
# Named after the options, as the verb has always taken it: the same run.
expect_ok bench-named-last bench --scene builtin:corner --width 16 --height 16 --threads 2 --repeats 1 specular-occlusion
grep -q "^specular-occlusion reference on builtin:corner, 16x16, 64 spp, roughness 0.5 (best of 1)" "$work/stdout" && pass ||
  fail "bench ... specular-occlusion: $(head -c 500 "$work/stdout")"
expect_error bench-width "--width" "" -- bench specular-occlusion --width 8
expect_error bench-scene "no-such-scene" "" -- bench specular-occlusion --scene builtin:no-such-scene --width 16 --height 16
expect_error fit-not-so "no channel specocc.V" "$work/f.json" -- fit aperture --reference "$ao" --ao "$ao" -o "$work/f.json"
finish
