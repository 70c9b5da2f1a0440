#!/usr/bin/env python3
"""Audit (issue 42): every quote in the claims table is the talk's own words.

Each claim of a gtlab summary.json ("claims") that carries a quote names the
transcript it comes from ("seed": "001" is SEEDS/001_*.txt). The quote must
stand in that transcript verbatim, up to white space (a run of spaces and
line breaks is one space: line breaks of a transcript are not words) and up
to elisions: "..." or "…" in a quote separates fragments that must appear in
that order. Prints one line per quote that does not, and exits 1; exits 0
when every quote is found (and says how many). The transcripts are not the
project's to ship: CI reads them from ../shared/seeds.

    tests/audit/claims_quotes.py SUMMARY.json SEEDS_DIR
"""
import glob
import json
import re
import sys


def normalise(text):
    return re.sub(r"\s+", " ", text).strip()


def fragments(quote):
    return [normalise(f) for f in re.split(r"\.\.\.|…", quote) if normalise(f)]


def found_in_order(parts, text):
    at = 0
    for part in parts:
        at = text.find(part, at)
        if at < 0:
            return False
        at += len(part)
    return bool(parts)


def transcript(seeds, seed, cache):
    if seed not in cache:
        paths = sorted(glob.glob(f"{seeds}/{seed}_*.txt"))
        cache[seed] = normalise(open(paths[0], encoding="utf-8").read()) if len(paths) == 1 else None
    return cache[seed]


def main(summary_path, seeds):
    claims = json.load(open(summary_path, encoding="utf-8")).get("claims", [])
    cache, failures, checked = {}, 0, 0
    for number, claim in enumerate(claims, 1):
        quote, seed = claim.get("quote"), claim.get("seed")
        if quote is None:
            continue
        checked += 1
        text = transcript(seeds, seed, cache)
        if text is None:
            print(f"{summary_path}: claim {number}: no single transcript {seeds}/{seed}_*.txt")
            failures += 1
        elif not found_in_order(fragments(quote), text):
            print(f"{summary_path}: claim {number}: not verbatim in transcript {seed}: \"{quote[:100]}\"")
            failures += 1
    print(f"claims quotes: {checked - failures} of {checked} found verbatim in the transcripts")
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: claims_quotes.py SUMMARY.json SEEDS_DIR")
    sys.exit(main(sys.argv[1], sys.argv[2]))
