#!/usr/bin/env bash
# gtlab fit sg-ndf as a user runs it: bad options give one line and exit 1;
# a good run writes the lobe tables, whose C header compiles, and whose
# 3-lobe sum at the normal matches Ward's D(n) = 1 / (pi ax ay) within the
# fit's own max error (reported relative to max D = D(n) for Ward).
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"
out=$work/sg

expect_error alpha-range "--alpha-x: 0 is out of range" "" -- fit sg-ndf --alpha-x 0 -o "$out"
expect_error unknown-ndf "--ndf: 'beckmann' is neither ward nor ggx" "" -- fit sg-ndf --ndf beckmann -o "$out"
expect_error lobes-range "--lobes: 20 is out of range" "" -- fit sg-ndf --lobes 20 -o "$out"
[ -e "$out" ] && fail "a rejected command left $out"
expect_ok help fit sg-ndf --help
grep -q "^usage: gtlab fit sg-ndf" "$work/stdout" || fail "fit sg-ndf --help prints no usage"

expect_ok fit fit sg-ndf --ndf ward --alpha-x 0.3 --alpha-y 0.15 --lobes 3 --threads 2 -o "$out"
for f in sg_ndf_lobes.json sg_ndf_lobes.h sg_ndf_error.dat; do [ -s "$out/sg_ndf/$f" ] || fail "$f not written"; done
grep -q "^k=3 ok" "$work/stdout" || fail "no checked 3-lobe fit: $(cat "$work/stdout")"
cat >"$work/use_header.c" <<C
#include "sg_ndf_lobes.h"
#include <math.h>
#include <stdio.h>
int main(void)
{
    double s = 0.0;
    for (int j = 0; j < 3; ++j)
        s += ward_0_30_0_15_k3[j].amplitude * exp(ward_0_30_0_15_k3[j].sharpness * (ward_0_30_0_15_k3[j].axis[2] - 1.0));
    printf("%.9g\n", s);
    return 0;
}
C
if cc -std=c11 -Wall -Werror -I"$out/sg_ndf" "$work/use_header.c" -o "$work/use_header" -lm 2>"$work/cc.log"; then
  s=$("$work/use_header")
  python3 - "$s" "$out/sg_ndf/sg_ndf_lobes.json" <<'PY' || fail "3-lobe sum at the normal $s is not Ward's D(n) within the fit's max error"
import json, math, sys
s = float(sys.argv[1])
fit = json.load(open(sys.argv[2]))["materials"][0]["fits"][2]
d = 1.0 / (math.pi * 0.3 * 0.15)
sys.exit(0 if abs(s - d) <= fit["max_error"] * d * 1.001 + 1e-5 * d else 1)
PY
else
  fail "sg_ndf_lobes.h does not compile: $(cat "$work/cc.log")"
fi
no_leftovers "$out/sg_ndf"
finish
