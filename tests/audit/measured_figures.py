#!/usr/bin/env python3
"""Audit (issue 43 item 6): docs/decisions.md and docs/design.md keep choices,
not measured figures.

A timing or a throughput is the machine's, the load's and the code's of the
day: copied into a document it goes stale with the next change and nobody
notices. Such a figure lives in the output that prints it (`gtlab bench ...`,
tests/fuzz/run_fuzz.sh, results/summary.json's stage_seconds), and the
documents cite that command instead. This check fails on a line of either
document that states one:

  - a number followed by a time unit (s, ms, µs/us, ns, min, minutes,
    seconds, hours, h): "about 30 ms", "2.4-2.6 s", "~4.6 min";
  - a number followed by a rate (/s, per second, a second, Mrays):
    "1,500 per second", "3e8 rays/s", "10 a second";
  - a speed-up: "4–8× faster", "a speed-up of 1.9", "efficiency of 80".

Settings that legitimately carry a time unit (a time limit, an interval) are
allowed by WHITELIST, a short list of exact phrases, each with the reason;
a number that is a setting or a definition (a sample count, a size, a
tolerance) has no time unit and is not looked at. One line per offence,
`file:line: the text`, exit 1 when there is one.

  tests/audit/measured_figures.py SOURCE_DIR
"""
import re
import sys

DOCUMENTS = ["docs/decisions.md", "docs/design.md"]

# Exact phrases removed from a line before it is checked.
WHITELIST = [
    # the shader compiler's child process CPU limit (RLIMIT_CPU, GPU_COMPILE_CPU_SECONDS): a setting
    "60 s of CPU",
    # the same limit as its error message words it
    "60 s CPU limit",
    # the error message of a fence not signalled within gpu/compute_dispatch.c's time limit: a setting
    "device timeout after 1 s",
    # the checkpoint interval of a resumable render (CHECKPOINT_SECONDS): a setting
    "Every 60 s",
    # s.e. is a standard error, not seconds: the 95 % interval's half-width
    "1.96 s.e.",
    # s is a standard error here too ("compare |d| with t s, not 1.96 s")
    "not 1.96 s:",
]

NUMBER = r"(?<![\w.^])\d[\d,]*(?:\.\d+)?(?:e[+-]?\d+)?"
RULES = [
    ("a time", re.compile(NUMBER + r"\s*(?:ms|µs|μs|us|ns|min|mins|minutes?|seconds?|secs?|hours?|hrs?)\b")),
    # one-letter units need a space: "2h" and "2s" are a formula's products
    ("a time", re.compile(NUMBER + r"\s+[sh]\b")),
    ("a rate", re.compile(NUMBER + r"(?:\s*[\w-]+){0,2}?\s*(?:/\s*s\b|per\s+second\b|an?\s+second\b)")),
    ("a rate", re.compile(NUMBER + r"\s*[kMG](?:rays|samples|paths|pixels)\b")),
    ("a speed-up", re.compile(NUMBER + r"\s*(?:×|x|times)\s+(?:faster|slower|quicker|speed-?ups?)\b", re.I)),
    ("a speed-up", re.compile(r"\b(?:speed-?ups?|efficiency)\s+(?:of\s+)?(?:about\s+|~\s*)?\d", re.I)),
]


def blanked(line):
    """The line with its whitelisted phrases blanked out (offsets kept)."""
    for phrase in WHITELIST:
        line = line.replace(phrase, " " * len(phrase))
    return line.rstrip("\n")


def offences(path):
    """(line number, rule, line) for each line stating a measured figure.

    A figure whose unit is wrapped onto the next line ("1,500 per" / "second")
    counts too: each line is read with the next one after it, and a match
    that starts on the line is the line's."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    found = []
    for index, line in enumerate(lines):
        text = blanked(line)
        following = blanked(lines[index + 1]).strip() if index + 1 < len(lines) else ""
        joined = text + " " + following
        for what, rule in RULES:
            if any(m.start() < len(text) for m in rule.finditer(joined)):
                found.append((index + 1, what, line))
                break
    return found


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[-1].strip())
    root = sys.argv[1]
    count = 0
    for path in DOCUMENTS:
        for number, what, line in offences(f"{root}/{path}"):
            count += 1
            print(f"{path}:{number}: {line.strip()}")
    sys.exit(1 if count else 0)


if __name__ == "__main__":
    main()
