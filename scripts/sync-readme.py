#!/usr/bin/env python3
"""Copy generated blocks into README.md so that its figures are the ones the commands wrote.

usage: sync-readme.py [--check] README.md NAME=SOURCE [NAME=SOURCE ...]
--check: change nothing, exit 1 if README.md differs from what the sources say.
For each NAME, the lines between '<!-- NAME:begin' and '<!-- NAME:end' in SOURCE replace the
lines between the same markers in README.md. A marker missing on either side is an error."""
import re
import sys


def block(lines, name, path):
    b = [i for i, l in enumerate(lines) if l.startswith(f"<!-- {name}:begin")]
    e = [i for i, l in enumerate(lines) if l.startswith(f"<!-- {name}:end")]
    if len(b) != 1 or len(e) != 1 or e[0] < b[0]:
        sys.exit(f"sync-readme: markers '{name}' not found once in {path}")
    return b[0], e[0]


args = sys.argv[1:]
check = bool(args) and args[0] == "--check"
if check:
    args = args[1:]
readme = args[0]
text = open(readme, encoding="utf-8").read()
lines = text.split("\n")
for arg in args[1:]:
    name, src = arg.split("=", 1)
    slines = open(src, encoding="utf-8").read().split("\n")
    sb, se = block(slines, name, src)
    rb, re_ = block(lines, name, readme)
    lines = lines[: rb + 1] + slines[sb + 1 : se] + lines[re_:]
new = "\n".join(lines)
if check:
    if new != text:
        sys.exit(f"{readme} is out of date against its sources: run 'make readme'")
else:
    open(readme, "w", encoding="utf-8").write(new)
