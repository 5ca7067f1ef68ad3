#!/usr/bin/env python3
"""Lists the longest functions of the package's headers (lines from the line
that opens the body to the closing brace, the signature not counted).

    benchmark/longest_functions.py [N] [--rev REV]

N (default 10): how many. --rev: read the headers of a git revision instead of
the working tree (e.g. --rev HEAD~1), to compare before and after a change.
A heuristic brace matcher, not a C++ parser: a body opens on a line ending in
'{' whose text before it has a ')' (or is a lambda's), and is not a control
statement; comments and strings are not skipped, which the package's style
(no braces in comments) makes harmless. Lambdas count as part of the function
around them.
"""
import re
import subprocess
import sys
from pathlib import Path

here = Path(__file__).resolve().parent.parent
args = sys.argv[1:]
rev = None
if "--rev" in args:
    i = args.index("--rev")
    rev = args[i + 1]
    del args[i:i + 2]
n = int(args[0]) if args else 10


def headers():
    if rev is None:
        for p in sorted((here / "include").rglob("*.h")):
            yield str(p.relative_to(here)), p.read_text()
    else:
        names = subprocess.run(["git", "-C", str(here), "ls-tree", "-r", "--name-only", rev, "include"],
                               capture_output=True, text=True, check=True).stdout.split()
        for name in names:
            if name.endswith(".h"):
                yield name, subprocess.run(["git", "-C", str(here), "show", f"{rev}:{name}"],
                                           capture_output=True, text=True, check=True).stdout


control = re.compile(r"^\s*(\}?\s*else\b|if\b|for\b|while\b|switch\b|do\b|try\b|catch\b|namespace\b|struct\b|class\b|"
                     r"enum\b|union\b|extern\b|case\b|default\b)")
name_re = re.compile(r"([A-Za-z_~][A-Za-z_0-9:<>~]*)\s*\([^()]*(\([^()]*\)[^()]*)*\)\s*(const)?\s*(noexcept)?\s*"
                     r"(->\s*[^{]*)?(:.*)?\{\s*$")

found = []
for name, text in headers():
    lines = text.split("\n")
    for i, line in enumerate(lines):
        stripped = line.strip()
        if not stripped.endswith("{") or stripped.startswith("//") or control.match(stripped):
            continue
        # the signature: this line and up to 6 before, back to a line ending in ';', '{' or '}'
        start = i
        while start > 0 and i - start < 6 and not re.search(r"[;{}]\s*$|^\s*$|^\s*//", lines[start - 1]):
            start -= 1
        signature = " ".join(l.strip() for l in lines[start:i + 1])
        if re.search(r"\]\s*(\(|\{|mutable)", signature) or re.search(r"\breturn\b", signature):
            continue  # a lambda
        m = name_re.search(signature)
        if not m or "(" not in signature:
            continue
        depth = 0
        for j in range(i, len(lines)):
            depth += lines[j].count("{") - lines[j].count("}")
            if depth <= 0:
                break
        func = m.group(1).split("::")[-1]
        found.append((j - i + 1, f"{name}:{i + 1}", func))

found.sort(key=lambda x: -x[0])
for length, where, func in found[:n]:
    print(f"{length:5d}  {func:40s} {where}")
