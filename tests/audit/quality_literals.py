#!/usr/bin/env python3
"""Audit (issue 43 item 4, issue 46 item 1): what a quality means is said once,
in techniques/quality_table.txt.

A technique's study and section (the STUDY and SECTION parts its
CMakeLists.txt names) never compare a quality
(`quality == QUALITY_PREVIEW`, `ctx->quality ? ... : ...`) and never types a
samples-per-pixel count (`.spp = 64`), nor a quality's value in prose
("128 samples (preview)"): it reads its settings from the table
through <name>_quality_of(quality) (cmake/gtlab_quality.cmake). Passing a
quality along (`study_context ctx = {dir, QUALITY_PRODUCTION, ...}`) is not a
comparison and is allowed.

  tests/audit/quality_literals.py SOURCE_DIR
"""
import os
import re
import sys

RULES = [
    ("compares a quality", re.compile(
        r"[!=]=\s*QUALITY_(PREVIEW|PRODUCTION)|QUALITY_(PREVIEW|PRODUCTION)\s*[!=]="
        r"|\bquality\s*(\?|[!=]=|[<>])|!\s*[\w>.-]*quality\b")),
    ("types a sample count", re.compile(r"\bspp\s*=\s*[0-9]")),
    # prose that says a quality's value ("128 samples (preview)", "48x48
    # (preview)"): it goes stale when the table changes (issue 46 item 1)
    ("types a quality's value in prose", re.compile(r"[0-9]+[^\"()]{0,40}\((preview|production)\)")),
]


def offences(path):
    """(line number, rule) for each offending line of the file."""
    found = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            code = line.split("//")[0]
            for what, rule in RULES:
                if rule.search(code):
                    found.append((number, what))
    return found


PARTS = re.compile(r"\b(NAME|USES|QUANTITIES|LUTS|REALTIME|REFERENCE|FIT|STUDY|SECTION|CLI|LINKS)\b")


def part_files(cmake_text, wanted):
    """The files gtlab_technique(...) names under the parts in `wanted`."""
    call = re.search(r"gtlab_technique\((.*?)\)", cmake_text, re.S)
    if not call:
        return []
    tokens = PARTS.split(call.group(1))
    files = []
    for keyword, names in zip(tokens[1::2], tokens[2::2]):
        if keyword in wanted:
            files += [n for n in names.split() if n.endswith((".c", ".h", ".cpp"))]
    return files


def technique_sources(root):
    """Every study and section source of every technique's folder."""
    techniques = os.path.join(root, "techniques")
    for name in sorted(os.listdir(techniques)):
        cmake = os.path.join(techniques, name, "CMakeLists.txt")
        if os.path.isfile(cmake):
            for file in part_files(open(cmake, encoding="utf-8").read(), ("STUDY", "SECTION")):
                yield f"techniques/{name}/{file}"


def main():
    root = sys.argv[1]
    failed = False
    for path in technique_sources(root):
        for number, what in offences(os.path.join(root, path)):
            failed = True
            print(f"{path}:{number}: {what}: read it from techniques/quality_table.txt instead")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
