#!/usr/bin/env python3
"""The table of contents of a Markdown document is its headings (issue 43).

A document that keeps one (docs/decisions.md) has, after its introduction, a
"## Contents" section with one line per "## " heading below it, in order,
linking the heading's anchor as GitHub renders it. This check fails when the
list and the headings disagree, so the contents cannot go stale;
`--write` rewrites the list from the headings.

  tests/audit/docs_contents.py [--write] FILE.md
"""
import re
import sys

CONTENTS = "## Contents"


def anchor(title):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"`", "", title.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def headings(lines):
    """The '## ' headings after the contents section (outside code blocks)."""
    found, fenced, after = [], False, False
    for line in lines:
        if line.startswith("```"):
            fenced = not fenced
        if fenced or not line.startswith("## "):
            continue
        if line.rstrip() == CONTENTS:
            after = True
            continue
        if after:
            found.append(line[3:].rstrip())
    return found


def contents_block(titles):
    return ["- [%s](#%s)" % (re.sub(r" \(.*$", "", t), anchor(t)) for t in titles]


def split(lines):
    """(before, current contents lines, after) around the contents section."""
    start = lines.index(CONTENTS)
    end = start + 1
    while end < len(lines) and not lines[end].startswith("## "):
        end += 1
    body = [l for l in lines[start + 1:end] if l.strip()]
    return lines[:start + 1], body, lines[end:]


def main():
    write = sys.argv[1] == "--write"
    path = sys.argv[-1]
    lines = open(path).read().split("\n")
    if CONTENTS not in lines:
        print("%s: no '%s' section" % (path, CONTENTS))
        return 1
    before, current, after = split(lines)
    expected = contents_block(headings(lines))
    if write:
        open(path, "w").write("\n".join(before + [""] + expected + [""] + after))
        return 0
    if current != expected:
        for i, (have, want) in enumerate(zip(current + [""] * len(expected), expected + [""] * len(current))):
            if have != want:
                print("%s: contents line %d is '%s', the headings say '%s' (tests/audit/docs_contents.py --write %s)"
                      % (path, i + 1, have, want, path))
                break
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
