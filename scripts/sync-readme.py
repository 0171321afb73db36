#!/usr/bin/env python3
"""README.md's two checked parts: its generated blocks, and its usage snippet (mk/readme.mk).

usage: sync-readme.py README.md NAME=SOURCE [NAME=SOURCE ...]
       sync-readme.py --check README.md NAME=SOURCE [NAME=SOURCE ...]
       sync-readme.py --snippet README.md

Blocks: for each NAME, the lines between '<!-- NAME:begin' and '<!-- NAME:end' in SOURCE (a
document a project command writes) replace the lines between the same markers in README.md, so
the README's figures are the ones the command wrote. A marker missing on either side is an
error. --check changes nothing and fails if README.md differs from its sources, or if one of
its relative links or images names a file that does not exist.

--snippet prints C for tests/readme/test_readme.c: the ```c block after the snippet marker,
without its #include lines, as the body of readme_snippet(), and the text of the line
'prints `...`' after the block as readme_prints, so the test checks what the README says."""
import os
import re
import sys

SNIPPET_MARK = "<!-- snippet: compiled and run by tests/readme/test_readme.c -->"


def die(msg):
    sys.exit(f"sync-readme: {msg}")


def block(lines, name, path):
    b = [i for i, l in enumerate(lines) if l.startswith(f"<!-- {name}:begin")]
    e = [i for i, l in enumerate(lines) if l.startswith(f"<!-- {name}:end")]
    if len(b) != 1 or len(e) != 1 or e[0] < b[0]:
        die(f"markers '{name}' not found once in {path}")
    return b[0], e[0]


def c_string(s, path):
    if not s.isascii() or any(ord(ch) < 32 for ch in s):
        die(f"{path}: the snippet's printed line must be plain ASCII")
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '\\n"'


def snippet(path):
    lines = open(path, encoding="utf-8").read().split("\n")
    if lines.count(SNIPPET_MARK) != 1:
        die(f"{path}: the snippet marker is not there once")
    i = lines.index(SNIPPET_MARK) + 1
    if i >= len(lines) or not lines[i].startswith("```c"):
        die(f"{path}: no ```c block right after the snippet marker")
    body = []
    i += 1
    while i < len(lines) and not lines[i].startswith("```"):
        if not lines[i].startswith("#include"):
            body.append(lines[i])
        i += 1
    if i == len(lines):
        die(f"{path}: the snippet's block is not closed")
    if not any(l.strip() for l in body):
        die(f"{path}: the snippet is empty")
    m = re.match(r"prints `([^`]+)`", lines[i + 1] if i + 1 < len(lines) else "")
    if not m:
        die(f"{path}: the line after the snippet must begin with prints `<what it prints>`")
    print(f"/* generated from {path} by scripts/sync-readme.py --snippet */")
    print(f"static const char readme_prints[] = {c_string(m.group(1), path)};")
    print("static void readme_snippet(void)\n{")
    print("\n".join(body))
    print("}")


def missing_links(path, text):
    """Relative link and image targets of a Markdown text that name no file or directory."""
    base = os.path.dirname(os.path.abspath(path))
    text = re.sub(r"```.*?```", "", text, flags=re.S)  # code blocks hold no links
    out = []
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"[a-z][a-z0-9+.-]*:", target) or target.startswith("#"):
            continue
        if not os.path.exists(os.path.join(base, target.split("#", 1)[0])):
            out.append(target)
    return out


def sync(args, check):
    if len(args) < 2:
        die("usage: sync-readme.py [--check] README.md NAME=SOURCE ...")
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
    if not check:
        if new != text:
            open(readme, "w", encoding="utf-8").write(new)
        return
    if new != text:
        die(f"{readme} is out of date against its sources: run 'make readme'")
    bad = missing_links(readme, text)
    if bad:
        die(f"{readme} links to missing files: {', '.join(bad)}")


args = sys.argv[1:]
if args[:1] == ["--snippet"] and len(args) == 2:
    snippet(args[1])
elif args[:1] == ["--check"]:
    sync(args[1:], True)
else:
    sync(args, False)
