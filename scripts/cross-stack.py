#!/usr/bin/env python3
"""Worst-case stack of one function's call tree, from GCC's -fcallgraph-info=su output (.ci).

usage: cross-stack.py file.ci root_function
Prints the bytes on the deepest path from root (each frame as -fstack-usage measures it), with
"+dyn" when a frame on it is dynamic and "+ext" when the path calls a function outside the
object (libgcc's soft-float helpers, libm's sqrtf): their frames are not counted."""
import re, sys
from functools import lru_cache


def main():
    path, root = sys.argv[1], sys.argv[2]
    frame, dyn, edges = {}, {}, {}
    name_of = {}
    for line in open(path):
        m = re.match(r'node: \{ title: "([^"]*)" label: "([^"]*)"', line)
        if m:
            title, label = m.groups()
            parts = label.split("\\n")
            name_of[title] = parts[0]
            s = next((p for p in parts if re.match(r"\d+ bytes", p)), None)
            if s is not None:
                frame[title] = int(s.split()[0])
                dyn[title] = "dynamic" in s
            continue
        m = re.match(r'edge: \{ sourcename: "([^"]*)" targetname: "([^"]*)"', line)
        if m:
            edges.setdefault(m.group(1), set()).add(m.group(2))

    @lru_cache(maxsize=None)
    def deepest(node):
        best, bdyn, bext = 0, False, False
        for nxt in edges.get(node, ()):
            if nxt not in frame:
                # "file:function" is a static function of this object that GCC emitted without
                # a node of its own (seen for small leaves): no frame recorded, not external.
                # A bare name is defined elsewhere.
                bext = bext or ":" not in nxt
                continue
            s, d, e = deepest(nxt)
            if s > best:
                best, bdyn = s, d
            bext = bext or e
        return frame[node] + best, dyn[node] or bdyn, bext

    roots = [t for t, n in name_of.items() if n == root and t in frame]
    if not roots:
        sys.exit(f"cross-stack.py: {root} not found in {path}")
    s, d, e = deepest(roots[0])
    print(f"{s}{'+dyn' if d else ''}{'+ext' if e else ''}")


if __name__ == "__main__":
    main()
