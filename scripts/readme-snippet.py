#!/usr/bin/env python3
"""Print the README's usage snippet: the ```c block that follows the line
'<!-- snippet: compiled and run by tests/readme/test_readme.c -->', without its #include lines
(the test includes the header itself and wraps the statements in a function)."""
import sys

MARK = "<!-- snippet: compiled and run by tests/readme/test_readme.c -->"
lines = open(sys.argv[1], encoding="utf-8").read().splitlines()
try:
    start = lines.index(MARK)
except ValueError:
    sys.exit("README.md: snippet marker not found")
i = start + 1
while not lines[i].startswith("```c"):
    i += 1
out = []
for line in lines[i + 1:]:
    if line.startswith("```"):
        break
    if not line.startswith("#include"):
        out.append(line)
if not any(l.strip() for l in out):
    sys.exit("README.md: the snippet is empty")
print("\n".join(out))
