#!/usr/bin/env python3
"""Side by side: two outputs of `ilsa_benchmark --runs N` made with the
benchmark built against two CGALs (BENCHMARKS.md, "CGAL 6.1.1 beside 5.5.1").

    python3 benchmark/compare_cgal_runs.py OLD.md NEW.md [OLD_NAME NEW_NAME]

Prints one Markdown row per mesh and method (input rows left out): mean and
minimum q, flipped faces, Hausdorff distance, median time and ILSA's time over
the method's, each as "old / new", a figure printed once where both agree.
"""
import sys


def load(path):
    rows = {}
    for line in open(path, encoding="utf-8"):
        if not line.startswith("| ") or line.startswith("| mesh") or "---" in line:
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells[1] != "input":
            rows[(cells[0], cells[1])] = cells
    return rows


def main():
    if len(sys.argv) not in (3, 5):
        sys.exit(__doc__)
    old, new = load(sys.argv[1]), load(sys.argv[2])
    names = sys.argv[3:5] if len(sys.argv) == 5 else ["old", "new"]
    columns = [("q min", 2), ("q mean", 3), ("flipped", 6), ("Hausdorff", 8), ("time s (median)", 11),
               ("ILSA time / this", 12)]
    print("| mesh | method | " + " | ".join(f"{c} ({names[0]} / {names[1]})" for c, _ in columns) + " |")
    print("|---|---|" + "---|" * len(columns))
    for key, a in old.items():
        b = new.get(key)
        if b is None:
            print(f"| {key[0]} | {key[1]} | only in {names[0]} |")
            continue
        cells = [a[i] if a[i] == b[i] else f"{a[i]} / {b[i]}" for _, i in columns]
        print(f"| {key[0]} | {key[1]} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
