#!/usr/bin/env bash
# tests/audit/claims_quotes.py (issue 42) on a made-up transcript and
# summary: a quote found verbatim across line breaks and with an elision
# passes; one changed word, fragments out of order, or a missing transcript
# fail, each named on its own line.
set -euo pipefail
audit=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/seeds"
printf 'The horizon\nsearch is   conservative,\nand it is fast.\n' > "$work/seeds/007_abc.txt"
summary() { printf '{"claims": [%s]}' "$1" > "$work/summary.json"; }
claim() { printf '{"seed": "%s", "quote": "%s"}' "$1" "$2"; }

summary "$(claim 007 'horizon search is conservative'), $(claim 007 'The horizon ... it is fast.'), {\"quote\": null}"
out=$(python3 "$audit" "$work/summary.json" "$work/seeds")
[[ $out == *"2 of 2 found verbatim"* ]] || { echo "FAIL: verbatim quotes refused: $out"; exit 1; }

summary "$(claim 007 'horizon search is aggressive'), $(claim 007 'it is fast ... The horizon'), $(claim 008 'x')"
if out=$(python3 "$audit" "$work/summary.json" "$work/seeds"); then
  echo "FAIL: wrong quotes accepted: $out"; exit 1
fi
[ "$(grep -c '^.*: claim [0-9]*: ' <<<"$out")" -eq 3 ] || { echo "FAIL: not one line per bad quote: $out"; exit 1; }
[[ $out == *"claim 3: no single transcript"* ]] || { echo "FAIL: missing transcript not named: $out"; exit 1; }
echo "1 passed, 0 failed"
