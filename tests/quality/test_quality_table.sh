#!/usr/bin/env bash
# The quality table's reader (cmake/gtlab_quality.cmake): a good table becomes
# a header that compiles and holds each column's values; each kind of bad row
# is refused naming the file and line.
set -euo pipefail
cc=$1 source_dir=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
read_table() { cmake -DTABLE="$1" -DTECHNIQUE=demo -DOUT="$dir/demo_quality.h" -P "$source_dir/tests/quality/read_table.cmake"; }

cat > "$dir/good.txt" <<'TABLE'
# a comment, then a blank line

demo   reference_spp   32    1024   spp     the reference's samples per pixel
demo   noise_budget    0.01  2.5e-3 stderr  the reference's target standard error
TABLE
read_table "$dir/good.txt"
mkdir -p "$dir/include/project"
printf 'typedef enum { QUALITY_PREVIEW, QUALITY_PRODUCTION } study_quality;\n' > "$dir/include/project/study_context.h"
cat > "$dir/main.c" <<'C'
#include "demo_quality.h"
int main(void)
{
    const demo_quality *p = demo_quality_of(QUALITY_PREVIEW), *q = demo_quality_of(QUALITY_PRODUCTION);
    return !(p->reference_spp == 32 && q->reference_spp == 1024 && p->noise_budget == 0.01 && q->noise_budget == 2.5e-3);
}
C
"$cc" -std=c11 -Wall -Werror -I"$dir" -I"$dir/include" "$dir/main.c" -o "$dir/main"
"$dir/main"

refuse() { # table line, expected message
  printf '%s\n' "demo a 1 2 spp fine" "$1" > "$dir/bad.txt"
  if read_table "$dir/bad.txt" 2> "$dir/err.txt"; then echo "accepted: $1" >&2; exit 1; fi
  tr -s ' \n' ' ' < "$dir/err.txt" | grep -qF "bad.txt:2: $2" || { echo "for '$1' expected '$2', got:" >&2; cat "$dir/err.txt" >&2; exit 1; }
}
refuse "demo b 1 spp too few columns"   "expected: technique setting preview production unit"
refuse "demo b 1.5 2 spp not integers"  "b is counted in spp, so its values must be integers"
refuse "demo b 1 2 parsecs unknown"     "unknown unit 'parsecs'"
refuse "demo b 1-2 2 stderr not a number" "b: '1-2' and '2' must be numbers"
refuse "demo b 1 2 spp this; that"      "a row cannot hold ';' or '|'"
refuse "demo b 1 2 spp this | that"     "a row cannot hold ';' or '|'"
echo "quality table: good table read, 6 bad rows refused"
