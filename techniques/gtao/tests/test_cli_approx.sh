#!/usr/bin/env bash
# gtlab approx gtao|hbao|vo|alchemy|crytek and gtlab render heightfield-ao as a user runs them:
# help, outputs a comparison can read, and one-line errors for bad input.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"
g=$work/g.exr

expect_ok render-heightfield render heightfield-ao --scene builtin:corner --width 32 --height 32 --spp 16 -o "$g"
for t in gtao hbao vo alchemy crytek; do
  expect_ok "$t-help" approx "$t" --help
  grep -q -- "--gbuffer" "$work/stdout" || fail "$t --help does not list --gbuffer"
  expect_ok "$t-run" approx "$t" --gbuffer "$g" --radius 2 -o "$work/$t.exr"
  expect_ok "$t-compare" compare "$g" "$work/$t.exr" --channel ao.V --json
done
expect_ok approx-help approx --help
expect_ok gtao-bent compare "$work/gtao.exr" "$work/gtao.exr" --channel bent.Z --json
expect_ok gtao-reference approx gtao --gbuffer "$g" --preset reference --slices 4 --radius 100 -o "$work/ref.exr"
grep -q "gtlab.technique" "$work/ref.exr" || fail "gtao output header lacks gtlab.technique"
grep -q "preset=reference" "$work/ref.exr" || fail "gtao output header lacks its settings"

out=$work/out.exr
expect_error missing-file "nowhere.exr: " "$out" -- approx gtao --gbuffer "$work/nowhere.exr" -o "$out"
expect_error not-a-gbuffer "gtao.exr: missing channel depth.Z" "$out" -- approx vo --gbuffer "$work/gtao.exr" -o "$out"
expect_error bad-preset "--preset: unknown preset 'fast'" "$out" -- approx gtao --preset fast --gbuffer "$g" -o "$out"
expect_error bad-steps "--steps: " "$out" -- approx gtao --steps 1000 --gbuffer "$g" -o "$out"
expect_error crytek-odd "--samples: '7' is odd" "$out" -- approx crytek --samples 7 --gbuffer "$g" -o "$out"
expect_error bad-switch "--denoise: 'maybe' is neither on nor off" "$out" -- approx hbao --denoise maybe --gbuffer "$g" -o "$out"
expect_error no-output "gtao: no output given" "" -- approx gtao --gbuffer "$g"
expect_error unknown-technique "ssao: unknown technique" "$out" -- approx ssao --gbuffer "$g" -o "$out"
printf '{"position":[1,1,1],"target":[0,0,0],"yfov_deg":45,"width":64,"height":64}' >"$work/cam.json"
expect_error camera-size "cam.json: camera is 64x64 but the G-buffer is 32x32" "$out" -- approx gtao --gbuffer "$g" --camera "$work/cam.json" -o "$out"

# gtlab fit gtao-params on two tiny references: Ceres only takes steps that
# lower the training cost, so with one training scene its error under the
# objective (DSSIM by default, or RMSE) cannot rise.
mkdir -p "$work/refs"
expect_ok ref-corner render ao --scene builtin:corner --width 24 --height 24 --spp 32 -o "$work/refs/corner.exr"
expect_ok ref-boxes render ao --scene builtin:boxes --width 24 --height 24 --spp 32 -o "$work/refs/boxes.exr"
expect_ok fit-help fit gtao-params --help
expect_ok fit fit gtao-params --refs "$work/refs" --train corner --test boxes --preset low -o "$work/fit.json"
expect_ok fit-rmse fit gtao-params --refs "$work/refs" --train corner --test boxes --preset low --objective rmse -o "$work/fit_rmse.json"
python3 - "$work/fit.json" "$work/fit_rmse.json" <<'PY' || fail "fit.json: training error rose or fields missing"
import json, sys
for path, objective in zip(sys.argv[1:], ("dssim", "rmse")):
    f = json.load(open(path))
    assert f["objective"] == objective, f["objective"]
    t = f["train_scores"][0]
    assert t[objective + "_after"] <= t[objective + "_before"] + 1e-9, t
    assert set(f["values"]) == {"radius_over_camera_distance", "falloff", "thickness"}
    assert f["test_scores"][0]["scene"] == "boxes"
    # objective_per_scene is the training scene's own score after the fit
    after = t["dssim_after"] if objective == "dssim" else t["rmse_after"] ** 2
    assert abs(f["objective_per_scene"] - after) < 1e-6 * max(1.0, after), (f["objective_per_scene"], after)
PY
expect_error fit-bad-objective "--objective: 'ssim' is neither dssim nor rmse" "$work/fit3.json" -- fit gtao-params --refs "$work/refs" --objective ssim -o "$work/fit3.json"
expect_error fit-missing-refs "nowhere/boxes.exr: " "$work/fit2.json" -- fit gtao-params --refs "$work/nowhere" -o "$work/fit2.json"
finish
