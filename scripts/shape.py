#!/usr/bin/env python3
"""The header's shape against DESIGN.md's budgets (`make shape`, a step of `make check`).

usage: shape.py [--lines N] [--manual N] [--function N] HEADER [OTHER ...]
       shape.py --self-test

HEADER: its lines in all (at most --lines, DESIGN.md's 1,200), its manual (the comment that
opens the file, at most --manual lines, DESIGN.md's 150) and each function (at most --function
lines, DESIGN.md's 80). OTHER (a header beside it, such as the batch's): its lines are
reported, and its functions held to the same --function limit.

A function's lines run from the line that names it to its closing brace, so a signature
wrapped over two lines counts both. Functions are found by their braces in the text with
comments, string literals and preprocessor directives taken out: a brace at depth 0 right
after a ')' opens a function body, unless the ')' closes a macro naming a struct, union or
enum (`struct CYL__N(ray) {`), which is what a C99 header of this style has at file scope.
Prints one line per measure and the longest functions; exits 1 when a limit is exceeded.
--self-test checks the function finder on a made-up header (make shape runs it first)."""
import argparse
import re
import sys


def strip(text):
    """text with comments, string and character literals and preprocessor directives blanked,
    newlines kept (so offsets map to the same lines)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            j += 1
        elif c == "#" and text[text.rfind("\n", 0, i) + 1:i].strip() == "":
            j = i  # a directive, with its continuation lines
            while True:
                e = text.find("\n", j)
                if e < 0:
                    j = n
                    break
                j = e
                if text[e - 1] != "\\":
                    break
                j = e + 1
        else:
            out.append(c)
            i += 1
            continue
        out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
        i = j
    return "".join(out)


# Each bracket's step in depth; parentheses and braces nest properly in C, so one count serves both.
DEPTH = {"(": 1, "{": 1, ")": -1, "}": -1}
STRUCT = re.compile(r"\b(struct|union|enum)\s+\w+\s*\(\s*\w+\s*\)$")
NAME = re.compile(r"(\w+\s*\(\s*\w+\s*\)|\w+)\s*$")


def match(s, k, step):
    """The index of the bracket that closes (step 1) or opens (step -1) the one at s[k]."""
    d = 0
    while 0 <= k < len(s):
        d += DEPTH.get(s[k], 0) * step
        if d == 0:
            return k
        k += step
    return k


def functions(text):
    """(name, first line, last line) of each function body at file scope, 1-based lines."""
    s = strip(text)
    line_of = lambda k: s.count("\n", 0, k) + 1
    found, depth, i = [], 0, 0
    while i < len(s):
        if s[i] == "{" and depth == 0:
            head = s[:i].rstrip()
            if head.endswith(")") and not STRUCT.search(head):
                k = match(head, len(head) - 1, -1)  # the '(' that opens the parameter list
                m = NAME.search(head[:k])
                j = match(s, i, 1)
                found.append((re.sub(r"\s+", "", m.group(1)) if m else "?",
                              line_of(m.start(1) if m else k), line_of(j)))
                i = j + 1
                continue
        depth += DEPTH.get(s[i], 0)
        i += 1
    return found


def self_test():
    """functions() on a header with each thing it must tell apart; exits 1 on a wrong answer."""
    body = "\n".join("    x += %d;" % k for k in range(78))
    text = ("/* manual { */\n"                                    # 1: a brace in a comment
            "#define M(x) do { x; } while (0)\n"                  # 2: braces in a directive
            "typedef struct CYL__P(frame) { int a; } CYL__P(frame);\n"  # 3: a struct, not a function
            "static int CYL__P(long_one)(int x,\n"                # 4: a wrapped signature
            "                            int y)\n"
            "{\n" + body + "\n    return x + y;\n}\n"          # 6 .. 86
            "static const char *s(void) { return \"}{\"; }\n"   # 87: braces in a string
            "int t(int x) { if (x) { return 1; } return 0; }\n")  # 88: nested braces
    want = [("CYL__P(long_one)", 4, 86), ("s", 87, 87), ("t", 88, 88)]
    got = functions(text)
    if got != want:
        sys.exit(f"shape: self-test: found {got}, want {want}")
    longest = want[0][2] - want[0][1] + 1
    print(f"shape: self-test: {len(want)} functions found as written (one of {longest} lines)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lines", type=int, default=1200)
    ap.add_argument("--manual", type=int, default=150)
    ap.add_argument("--function", type=int, default=80)
    ap.add_argument("--self-test", action="store_true")
    ap.add_argument("header", nargs="?")
    ap.add_argument("others", nargs="*")
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    if not a.header:
        ap.error("HEADER is required")
    bad = []

    def measure(what, value, limit):
        over = limit is not None and value > limit
        print(f"shape: {what}: {value}" + (f" (limit {limit})" if limit is not None else "")
              + (" OVER" if over else ""))
        if over:
            bad.append(what)

    for path in [a.header] + a.others:
        text = open(path, encoding="utf-8").read()
        main_header = path == a.header
        measure(f"{path} lines", text.count("\n"), a.lines if main_header else None)
        if main_header:
            end = text.find("*/") if text.startswith("/*") else -1
            if end < 0:
                sys.exit(f"shape: {path} does not open with its manual (a /* comment)")
            measure(f"{path} manual lines", text.count("\n", 0, end) + 1, a.manual)
        fns = functions(text)
        if not fns:
            sys.exit(f"shape: no function found in {path}")
        fns.sort(key=lambda f: f[1] - f[2])
        name, first, last = fns[0]
        measure(f"{path} longest function ({name}, lines {first}-{last}; {len(fns)} functions)",
                last - first + 1, a.function)
        for name, first, last in fns[1:4]:
            print(f"shape:   next: {name}, {last - first + 1} lines")
    if bad:
        sys.exit("shape: over its budget: " + "; ".join(bad))


if __name__ == "__main__":
    main()
