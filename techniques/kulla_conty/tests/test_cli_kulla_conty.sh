#!/usr/bin/env bash
# gtlab lut kulla-conty as a user runs it: bad options give one line and exit
# 1 with nothing written; a good run writes the three files, the C header
# compiles and holds N values that fall with roughness from near 1.
gtlab=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
source "$(dirname "$0")/../../../tests/cli/cli_test_lib.sh"
out=$work/luts

expect_error size-range "--size: 3 is out of range" "" -- lut kulla-conty --size 3 -o "$out"
expect_error size-word "--size" "" -- lut kulla-conty --size many -o "$out"
[ -e "$out" ] && fail "a rejected command left $out"
expect_ok help lut kulla-conty --help
grep -q "^usage: gtlab lut kulla-conty" "$work/stdout" || fail "lut kulla-conty --help prints no usage"

expect_ok table lut kulla-conty --size 16 --threads 2 -o "$out"
for f in kulla_conty_eavg_16.exr kulla_conty_eavg_16.png kulla_conty_eavg_16.h; do
  [ -s "$out/$f" ] || fail "$f not written"
done
cat >"$work/use_header.c" <<C
#include "kulla_conty_eavg_16.h"
#include <stdio.h>
int main(void)
{
    int falling = KULLA_CONTY_EAVG_16_SIZE == 16 && KULLA_CONTY_EAVG_16[0] > 0.999f;
    for (int j = 1; j < KULLA_CONTY_EAVG_16_SIZE; ++j)
        falling = falling && KULLA_CONTY_EAVG_16[j] < KULLA_CONTY_EAVG_16[j - 1] && KULLA_CONTY_EAVG_16[j] > 0.0f;
    return falling ? 0 : 1;
}
C
if cc -std=c11 -Wall -Werror -I"$out" "$work/use_header.c" -o "$work/use_header" 2>"$work/cc.log"; then
  "$work/use_header" || fail "the header's E_avg does not start near 1 and fall with roughness"
else
  fail "kulla_conty_eavg_16.h does not compile: $(cat "$work/cc.log")"
fi
no_leftovers "$out"
finish
