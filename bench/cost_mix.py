#!/usr/bin/env python3
"""cost_mix.py: where the instructions of `make cost` go, by kind (`make cost-mix`).

    cost_mix.py --loops "24 endpoint,24 intersect:plain,..." KEY=BINARY:CGDIR ...

Each CGDIR holds a callgrind run of bench/cost.c's BINARY made with --dump-instr=yes (the
k-th dump counts the k-th loop of plan.txt, as for `make cost`). For each loop named, this
prints the instructions per call by kind, the empty loop's subtracted kind by kind, so that a
cost can be read as data movement (register copies, shuffles, loads and stores; lea, push and
pop counted with them), conversions, arithmetic, and decisions (comparisons and branches), not
as one number only. Kinds are assigned by mnemonic (x86-64, SSE and AVX forms alike);
instructions outside the binary (libm, libc) count as "call".
"""
import argparse
import os
import re
import subprocess
import sys

from cost_report import PRECS  # ("24", "float"), ("53", "double"): plan.txt's precisions

KINDS = ("move", "convert", "arith", "decide", "other", "call")


def kind(mn):
    """The kind of an x86-64 mnemonic (objdump's AT&T spelling, VEX 'v' prefix ignored)."""
    m = mn[1:] if mn.startswith("v") and not mn.startswith("vzero") else mn
    if m.startswith("cvt"):
        return "convert"
    if re.match(r"(j|set|cmov|cmp|test|comis|ucomis)", m):
        return "decide"
    if re.match(r"(mov|unpck|shuf|pshuf|broadcast|perm|insert|extract|blend|punpck|lea|push|pop)", m):
        return "move"
    if re.match(r"(add|sub|mul|div|sqrt|min|max|fmadd|fmsub|fnmadd|fnmsub|and|or|xor|hadd)"
                r"[a-z0-9]*(ss|sd|ps|pd)$", m) or m in ("pxor", "pand", "por", "pandn"):
        return "arith"
    return "other"


def mnemonics(binary):
    """address -> mnemonic of every instruction in the binary."""
    dis = subprocess.run(["objdump", "-d", "--no-show-raw-insn", binary], capture_output=True,
                         text=True, check=True).stdout
    out = {}
    for line in dis.splitlines():
        m = re.match(r"^\s+([0-9a-f]+):\s+(\S+)", line)
        if m:
            out[int(m.group(1), 16)] = m.group(2)
    return out


def mix(dump, binary, mn, obs):
    """Instructions of one callgrind dump by kind (self cost only, calls' inclusive lines skipped);
    obs: the object names of the run's earlier dumps (callgrind names each once per run)."""
    ob, addr, skip = "", 0, False
    total = dict.fromkeys(KINDS, 0)
    for line in open(dump):
        if line.startswith(("ob=", "cob=")):  # named once, on either
            m = re.match(r"c?ob=\((\d+)\)(?: (.*))?", line.rstrip("\n"))
            if m.group(2):
                obs[m.group(1)] = m.group(2)
            if line.startswith("ob="):
                ob = obs.get(m.group(1), "")
            continue
        if line.startswith("calls="):
            skip = True
            continue
        m = re.match(r"^(0x[0-9a-f]+|[+-]\d+|\*)\s+\S+\s+(\d+)", line)
        if not m:
            continue
        a = m.group(1)
        addr = int(a, 16) if a.startswith("0x") else addr + int(a) if a != "*" else addr
        if skip:
            skip = False
            continue
        own = os.path.basename(ob) == os.path.basename(binary)
        total[kind(mn.get(addr, "?")) if own else "call"] += int(m.group(2))
    return total


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--loops", required=True, help="comma-separated 'PREC NAME' of plan.txt")
    ap.add_argument("runs", nargs="+", help="KEY=BINARY:CGDIR")
    args = ap.parse_args()
    loops = [tuple(x.split()) for x in args.loops.split(",")]
    known = dict(PRECS)
    bad = [" ".join(lp) for lp in loops if len(lp) != 2 or lp[0] not in known]
    if bad:
        ap.error("--loops: each entry is 'PREC NAME' with PREC one of %s, not: %s"
                 % (", ".join(known), "; ".join(repr(b) for b in bad)))
    print("Instructions per call by kind (callgrind, bench/cost.c's loops, the empty loop's "
          "subtracted): move = register copies, shuffles, loads, stores (lea, push, pop too); "
          "decide = comparisons and branches; call = outside the binary.\n")
    print("| binary | loop | total | " + " | ".join(KINDS) + " |")
    print("|---|---|---:|" + "---:|" * len(KINDS))
    for run in args.runs:
        key, rest = run.split("=", 1)
        binary, cgdir = rest.split(":", 1)
        mn = mnemonics(binary)
        plan = [ln.split() for ln in open(cgdir + "/plan.txt") if ln.startswith("cost ")]
        per, obs = {}, {}
        for k, p in enumerate(plan):  # every dump in order, for the names
            got = mix("%s/out.%d" % (cgdir, k + 1), binary, mn, obs)
            if p[2] == "empty" or (p[1], p[2]) in loops:
                per[(p[1], p[2])] = {kd: c / int(p[3]) for kd, c in got.items()}
        for lp in loops:
            if lp not in per:
                print("| %s | %s %s | n/a |%s" % (key, lp[0], lp[1], " |" * len(KINDS)))
                continue
            e = per[(lp[0], "empty")]
            row = {kd: per[lp][kd] - e[kd] for kd in KINDS}
            name = dict(PRECS)[lp[0]] + " " + lp[1]
            print("| %s | %s | %.1f | %s |" % (key, name, sum(row.values()),
                                             " | ".join("%.1f" % row[kd] for kd in KINDS)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
