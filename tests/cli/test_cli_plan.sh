#!/usr/bin/env bash
# gtlab plan (issue 20): one render split into a Slurm job array and a merge.
# The scripts pass `bash -n`; submitted to a stand-in sbatch that runs each
# job of the array here, they produce the merged reference, the same file as
# the render in one process; and gtlab merge --expect-blocks refuses parts
# that do not belong to the plan (other scene, camera, settings, seed,
# overlapping or missing blocks), each with one line naming the file.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/cli_test_lib.sh"
cd "$work" || exit 1

common=(--scene builtin:cornell --width 24 --height 16 --seed 7 --threads 1)
expect_ok whole render ao "${common[@]}" --spp 40 -o whole.exr
expect_ok plan plan --jobs 3 -o plan -- render ao "${common[@]}" --spp 40 -o merged.exr
for script in job.sh merge.sh submit.sh; do
  bash -n "plan/$script" && pass || fail "plan/$script does not pass bash -n"
done
[ "$(wc -l <plan/jobs.txt)" -eq 3 ] && pass || fail "jobs.txt: $(wc -l <plan/jobs.txt) lines, expected 3"

# A stand-in for Slurm's sbatch: runs the script, each task of its
# "#SBATCH --array=A-B" with SLURM_ARRAY_TASK_ID set, here and now; logs
# its arguments; prints a job id as `sbatch --parsable` does (the jobs'
# output goes to stderr).
mkdir -p stub
cat >stub/sbatch <<'STUB'
#!/bin/bash
echo "$*" >>"$(dirname "$0")/sbatch.log"
script=${!#}
range=$(sed -n 's/^#SBATCH --array=//p' "$script")
if [ -z "$range" ]; then bash "$script" >&2 || exit 1; fi
for ((task = ${range%-*}; task <= ${range#*-}; ++task)); do
  SLURM_ARRAY_TASK_ID=$task bash "$script" >&2 || exit 1
done
echo 4242
STUB
chmod +x stub/sbatch
if PATH="$work/stub:$PATH" bash plan/submit.sh >submit.out 2>&1; then pass; else fail "submit.sh: $(tail -c 500 submit.out)"; fi
grep -q -- "--dependency=afterok:4242 .*merge.sh" stub/sbatch.log && pass || fail "merge not submitted after the array: $(cat stub/sbatch.log)"
# The same file as one process: pixels and header (the merged blocks read 7:0+40).
cmp -s whole.exr merged.exr && pass || fail "the merged plan differs from the render in one process"
for j in 0 1 2; do [ -s "plan/part-$j.exr" ] && pass || fail "no plan/part-$j.exr"; done
# Another scheduler runs a job by its index.
expect_ok plan-2 plan --jobs 2 -o plan2 -- render ao "${common[@]}" --spp 40 -o merged2.exr
bash plan2/job.sh 1 >/dev/null 2>&1 && [ -s plan2/part-1.exr ] && pass || fail "job.sh 1 did not render part 1"
bash plan2/job.sh 2 >/dev/null 2>&1 && fail "job.sh 2 of 2 jobs ran" || pass

# Parts that do not belong to the plan: refused, naming the file.
expect="--expect-blocks 7:0+40"
p=(plan/part-0.exr plan/part-1.exr plan/part-2.exr)
part1=(--spp 13 --sample-offset 13)
expect_ok other-scene render ao --scene builtin:boxes --width 24 --height 16 --seed 7 --threads 1 "${part1[@]}" -o scene.exr
expect_error scene "scene.exr: its gtlab.scene_hash differs" m.exr -- merge "${p[0]}" scene.exr "${p[2]}" $expect -o m.exr
sed 's/"yfov_deg": *[0-9.e+-]*/"yfov_deg": 31/' whole.camera.json >cam.json
expect_ok other-camera render ao "${common[@]}" --camera cam.json "${part1[@]}" -o camera.exr
expect_error camera "camera.exr: its gtlab.camera differs" m.exr -- merge "${p[0]}" camera.exr "${p[2]}" $expect -o m.exr
expect_ok other-settings render ao "${common[@]}" --max-distance 0.5 "${part1[@]}" -o settings.exr
expect_error settings "settings.exr: its gtlab.settings differs" m.exr -- merge "${p[0]}" settings.exr "${p[2]}" $expect -o m.exr
expect_ok other-seed render ao "${common[@]}" --seed 8 "${part1[@]}" -o seed.exr
expect_error seed "seed.exr: samples 13..25 of seed 8 are not in the planned blocks" m.exr -- merge "${p[0]}" seed.exr "${p[2]}" $expect -o m.exr
expect_error overlap "part-0.exr: samples 0..12 of seed 7 are already in an earlier input" m.exr -- merge "${p[0]}" "${p[1]}" "${p[0]}" -o m.exr
expect_error missing "merge: no input holds samples 13..25 of seed 7 of the planned blocks" m.exr -- merge "${p[0]}" "${p[2]}" $expect -o m.exr
# And what plan itself refuses.
expect_error adaptive "--target-stderr: adaptive parts do not merge" "" -- plan --jobs 2 -o p3 -- render ao "${common[@]}" --target-stderr 0.01 -o x.exr
expect_error too-many-jobs "--jobs: 50 jobs for 40 samples" "" -- plan --jobs 50 -o p3 -- render ao "${common[@]}" --spp 40 -o x.exr
expect_error no-render "give the render to split after '--'" "" -- plan --jobs 2 -o p3

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
