#!/usr/bin/env python3
"""Audit (issue 43 item 4, issue 46 item 1): what a quality means is said once,
in techniques/quality_table.txt.

A technique's study and section (the STUDY and SECTION parts its
CMakeLists.txt names) never compare a quality
(`quality == QUALITY_PREVIEW`, `ctx->quality ? ... : ...`) and never types a
samples-per-pixel count (`.spp = 64`): it reads its settings from the table
through <name>_quality_of(quality) (cmake/gtlab_quality.cmake). Passing a
quality along (`study_context ctx = {dir, QUALITY_PRODUCTION, ...}`) is not a
comparison and is allowed.

Files written before the table are listed in KNOWN while they are converted;
a listed file that no longer offends (remove it from KNOWN), or one not
listed that does, fails the audit.

  tests/audit/quality_literals.py SOURCE_DIR
"""
import os
import re
import sys

KNOWN = [
    "techniques/environment/env_approx_study.c",
    "techniques/specular_occlusion/study/specular_occlusion_study.c",
    "techniques/sphere_light/sphere_light_scenes.c",
    "techniques/sphere_light/sphere_light_study.c",
]

RULES = [
    ("compares a quality", re.compile(
        r"[!=]=\s*QUALITY_(PREVIEW|PRODUCTION)|QUALITY_(PREVIEW|PRODUCTION)\s*[!=]="
        r"|\bquality\s*(\?|[!=]=|[<>])|!\s*[\w>.-]*quality\b")),
    ("types a sample count", re.compile(r"\bspp\s*=\s*[0-9]")),
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
    offending = set()
    for path in technique_sources(root):
        found = offences(os.path.join(root, path))
        if not found:
            continue
        offending.add(path)
        if path not in KNOWN:
            failed = True
            for number, what in found:
                print(f"{path}:{number}: {what}: read it from techniques/quality_table.txt instead")
    for path in KNOWN:
        if path not in offending:
            failed = True
            print(f"{path}: no longer compares a quality or types a sample count: remove it from KNOWN")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
