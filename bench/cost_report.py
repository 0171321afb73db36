#!/usr/bin/env python3
"""cost_report.py: the tables of `make cost` and `make cost-time` (see mk/cost.mk, bench/cost.c).

  cost_report.py pair --key KEY --cflags FLAGS PLAN CGDIR > KEY.tsv
      pairs the lines "cost PREC NAME CASES" that build/cost/cost-KEY printed under callgrind
      with its dumps CGDIR/out.1, out.2, ... (the k-th dump counts the k-th such line) and
      writes instructions per call, the empty loop of the same precision subtracted; lines
      "na PREC NAME CODE" (a loop not run) are kept as n/a.
  cost_report.py insn --out MD [--v2-dir DIR] [--n N] [--seed S] [--held TXT] KEY.tsv...
      one markdown table per -march setting, then v2's cost limits (LIMITS) met or not,
      printed and written to MD; exits 1 if a limit TXT lists as held is no longer met.
  cost_report.py time --out MD [--v2-dir DIR] [--n N] [--seed S] RUN.txt...
      the same from the --time runs (RUN.txt: "# key KEY" then cost --time's output):
      ns per call and ratio to the end-point routine, each the median over the runs.

KEY is VERSION-MARCH: v1 or v2, base (-O2) or v3 (-O2 -march=x86-64-v3).
"""
import argparse
import glob
import os
import re
import statistics
import sys

MARCHES = [("base", "-O2"), ("v3", "-O2 -march=x86-64-v3")]
VERSIONS = ["v1", "v2"]
PRECS = [("24", "float"), ("53", "double")]
# (row label, loop name in cost.c); the end-point routine first
ROWS = [
    ("end-point routine (pa, pb, ra)", "endpoint"),
    ("plain: CAPS\\|NO_ERRBOUND\\|NO_NORMAL", "intersect:plain"),
    ("plain and t_err: CAPS\\|NO_NORMAL", "intersect:bound"),
    ("plain and normal: CAPS\\|NO_ERRBOUND", "intersect:normal"),
    ("default: CAPS", "intersect:default"),
    ("precise: CAPS\\|PRECISE", "intersect:precise"),
]
# The cost limits of issues 28 and 29 on v2 at -O2 (ratio to the end-point routine, both APIs):
# (option set, loop name, limit, issue)
LIMITS = [
    ("plain", "intersect:plain", 1.4, 28),
    ("default", "intersect:default", 2.0, 28),
    ("precise", "intersect:precise", 3.0, 29),
]
SITES = ["plain", "bound", "normal", "default", "precise", "open", "outward"]
SITE_OPTS = {
    "plain": "CAPS\\|NO_ERRBOUND\\|NO_NORMAL",
    "bound": "CAPS\\|NO_NORMAL",
    "normal": "CAPS\\|NO_ERRBOUND",
    "default": "CAPS",
    "precise": "CAPS\\|PRECISE",
    "open": "0 (open tube)",
    "outward": "OUTWARD",
}


def read_header(lines):
    meta = {}
    for line in lines:
        if line.startswith("# "):
            k, _, v = line[2:].partition(" ")
            meta[k] = v.strip()
    return meta


def dump_total(path):
    with open(path) as f:
        for line in f:
            m = re.match(r"^(summary|totals):\s+(\d+)", line)
            if m:
                return int(m.group(2))
    sys.exit(f"cost_report: no total in {path}")


def cmd_pair(a):
    with open(a.plan) as f:
        plan = [line.split() for line in f if line.strip()]
    out = [f"# key {a.key}", f"# cflags {a.cflags}"]
    rows, k = [], 0
    for w in plan:
        if w[0] == "compiler":
            out.append("# compiler " + " ".join(w[1:]))
        elif w[0] == "na":
            rows.append((w[1], w[2], "-", "na:" + w[3]))
        elif w[0] == "cost":
            k += 1
            files = glob.glob(os.path.join(a.cgdir, f"out.{k}")) or \
                glob.glob(os.path.join(a.cgdir, f"out.*.{k}"))
            if not files:
                sys.exit(f"cost_report: no callgrind dump {k} for: {' '.join(w)}")
            rows.append((w[1], w[2], w[3], dump_total(files[0])))
        else:
            sys.exit(f"cost_report: unexpected plan line: {' '.join(w)}")
    empty = {r[0]: r[3] for r in rows if r[1] == "empty"}
    for prec, name, n, c in rows:
        if isinstance(c, str):
            out.append(f"{prec}\t{name}\t{n}\t{c}")
        elif name != "empty":
            if prec not in empty or int(n) < 1:
                sys.exit(f"cost_report: no empty loop for precision {prec}")
            out.append(f"{prec}\t{name}\t{n}\t{(c - empty[prec]) / int(n):.1f}")
    print("\n".join(out))


def load_tsv(path):
    """{(prec, name): value or 'n/a'}, meta"""
    with open(path) as f:
        lines = f.read().splitlines()
    meta = read_header(lines)
    vals = {}
    for line in lines:
        if line.startswith("#") or not line.strip():
            continue
        prec, name, n, v = line.split("\t")
        vals[(prec, name)] = "n/a" if v.startswith("na:") else float(v)
        meta["cases"] = n if n != "-" else meta.get("cases", "?")
    return vals, meta


def cell(vals, prec, name):
    """"v (r x)": r is the stored ratio (the median of the runs' ratios, --time) or else
    v over the end-point routine's count in the same binary"""
    if vals is None:
        return "n/a"
    v = vals.get((prec, name))
    ep = vals.get((prec, "endpoint"))
    if not isinstance(v, float):
        return "n/a"
    if name == "endpoint":
        return f"{v:.1f}"
    r = vals.get(("ratio", prec, name))
    if r is None and isinstance(ep, float) and ep > 0:
        r = v / ep
    return f"{v:.1f} ({r:.2f}x)" if r is not None else f"{v:.1f}"


def header_line(unit, a, metas, v2_present):
    comp = next((m["compiler"] for m in metas if "compiler" in m), "?")
    cases = next((m["cases"] for m in metas if m.get("cases", "?") != "?"), "?")
    v2 = f"v2: {a.v2_dir}/cylinder_isect.h" if v2_present else \
        f"v2: n/a (no {a.v2_dir}/cylinder_isect.h)"
    return (f"{unit}; in parentheses the ratio to the end-point routine measured in the same "
            f"binary. {cases} capped well-conditioned cases per precision (bench/cases.c, seed "
            f"{a.seed}), the empty loop subtracted; bench/cost.c, gcc {comp}, `-std=c99` plus "
            f"the flags above. v1: ./cylinder_isect.h; {v2}.")


def table(title, data, rows, prec_names=PRECS):
    """data: {(version, march): vals}; rows: [(label, name)]"""
    out = [title, ""]
    head = "| option set |"
    rule = "|---|"
    for _, pn in prec_names:
        for v in VERSIONS:
            head += f" {pn} API {v} |"
            rule += "---:|"
    out += [head, rule]
    for label, name in rows:
        line = f"| {label} |"
        for prec, _ in prec_names:
            for v in VERSIONS:
                line += f" {cell(data.get(v), prec, name)} |"
        out.append(line)
    return out


def write(a, lines):
    text = "\n".join(lines) + "\n"
    sys.stdout.write(text)
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    with open(a.out, "w") as f:
        f.write(text)


def report(a, loaded, unit, heading):
    """loaded: {(version, march): (vals, meta)}"""
    v2_present = any(v == "v2" for v, _ in loaded)
    metas = [m for _, m in loaded.values()]
    return [heading, "", header_line(unit, a, metas, v2_present), ""] + tables(loaded, ROWS)


def tables(loaded, rows):
    """One table of the given rows per -march setting."""
    lines = []
    for march, flags in MARCHES:
        data = {v: loaded[(v, march)][0] for v in VERSIONS if (v, march) in loaded}
        lines += table(f"### gcc -std=c99 {flags}", data, rows)
        lines.append("")
    return lines


def every_site(a, loaded):
    lines = ["## Every call site", "",
             "Each entry point with each constant option set (its own loop function); the table "
             "above shows the intersect rows.", ""]
    rows = [("end-point routine", "endpoint")]
    for api in ["intersect", "intersect_all", "occluded"]:
        for s in SITES:
            rows.append((f"{api}, {SITE_OPTS[s]}", f"{api}:{s}"))
    return lines + tables(loaded, rows)


def key_of(meta, path):
    key = meta.get("key")
    if not key or "-" not in key:
        sys.exit(f"cost_report: {path} has no '# key VERSION-MARCH' line")
    v, m = key.split("-", 1)
    return v, m


def limits(loaded, held_txt):
    """The table of LIMITS on v2 at -O2, and the held ones (held_txt: lines "SET float|double") lost."""
    vals = loaded.get(("v2", "base"), (None,))[0]
    held = set()
    if held_txt:
        with open(held_txt) as f:
            held = {tuple(ln.split()) for ln in f if ln.strip() and not ln.startswith("#")}
        unknown = held - {(s, pn) for s, *_ in LIMITS for _, pn in PRECS}
        if unknown:
            sys.exit(f"cost_report: {held_txt} names limits LIMITS does not have: {sorted(unknown)}")
    lines = ["### v2's cost limits, gcc -std=c99 -O2", "",
             "| option set | precision | measured | limit | met |", "|---|---|---:|---:|---|"]
    lost = []
    for label, name, limit, issue in LIMITS:
        for prec, pn in PRECS:
            v, ep = (vals or {}).get((prec, name)), (vals or {}).get((prec, "endpoint"))
            r = v / ep if isinstance(v, float) and isinstance(ep, float) and ep > 0 else None
            met = "yes" if r is not None and r <= limit else "no"
            shown = f"{v:.1f} ({r:.3f}x)" if r is not None else "n/a"
            lines.append(f"| {label} (issue {issue}) | {pn} | {shown} | {limit:.1f}x | {met} |")
            if met == "no" and (label, pn) in held:
                lost.append(f"{label} {pn}: {shown} > {limit:.1f}x")
    return lines + [""], lost


def layers(loaded):
    """What each part adds to v2's plain intersect, per API and -march setting, and what the
    default limit leaves over plain (its multiple of the end-point routine, less plain)."""
    lim = next(limit for label, _, limit, _ in LIMITS if label == "default")
    keys = [(m, flags, prec, pn) for m, flags in MARCHES if ("v2", m) in loaded for prec, pn in PRECS]
    if not keys:
        return []
    lines = ["### What each part adds to v2's plain intersect", "",
             "Instructions per call, from the rows above: each option set's count less plain's "
             "(CAPS\\|NO_ERRBOUND\\|NO_NORMAL), CYL_PRECISE's less the default's. The last row is "
             f"what the default limit ({lim:.1f}x the end-point routine) leaves for the t_err bound "
             "and the normal.", "",
             "| part | " + " | ".join(f"{pn}, {flags}" for _, flags, _, pn in keys) + " |",
             "|---|" + "---:|" * len(keys)]
    plain = "intersect:plain"

    def row(label, diff):
        cells = [diff(loaded[("v2", m)][0], prec) for m, _, prec, _ in keys]
        return f"| {label} |" + "".join(f" {c:+.1f} |" if c is not None else " n/a |" for c in cells)

    def less(name, base):
        return lambda vals, prec: sub(vals.get((prec, name)), vals.get((prec, base)))

    def sub(v, b):
        return v - b if isinstance(v, float) and isinstance(b, float) else None

    def left(vals, prec):
        ep = vals.get((prec, "endpoint"))
        return sub(lim * ep, vals.get((prec, plain))) if isinstance(ep, float) else None

    lines += [row("t_err bound (CAPS\\|NO_NORMAL)", less("intersect:bound", plain)),
              row("normal (CAPS\\|NO_ERRBOUND)", less("intersect:normal", plain)),
              row("both: the default (CAPS)", less("intersect:default", plain)),
              row("CYL_PRECISE over the default", less("intersect:precise", "intersect:default")),
              row(f"left by the default limit ({lim:.1f}x)", left)]
    return lines + [""]


def cmd_insn(a):
    loaded = {}
    for p in a.files:
        vals, meta = load_tsv(p)
        loaded[key_of(meta, p)] = (vals, meta)
    lines = report(a, loaded, "Instructions per call under callgrind",
                   "## Instructions per call: v1 and v2 against the end-point routine")
    lim, lost = limits(loaded, a.held) if ("v2", "base") in loaded else ([], [])
    write(a, lines + lim + layers(loaded))
    with open(a.out, "a") as f:
        f.write("\n".join(every_site(a, loaded)))
    if lost:
        sys.exit("cost: a limit " + a.held + " lists as met is no longer met: " + "; ".join(lost))


def cmd_time(a):
    runs = {}   # key -> list of {(prec, name): ns or 'n/a'}
    metas = {}
    for p in a.files:
        with open(p) as f:
            lines = f.read().splitlines()
        meta = read_header(lines)
        k = key_of(meta, p)
        vals = {}
        for line in lines:
            w = line.split()
            if not w or w[0] == "#":
                continue
            if w[0] == "compiler":
                meta["compiler"] = " ".join(w[1:])
            elif w[0] == "time":
                vals[(w[1], w[2])] = float(w[4])
                meta["cases"] = w[3]
            elif w[0] == "na":
                vals[(w[1], w[2])] = "n/a"
        runs.setdefault(k, []).append(vals)
        metas[k] = meta
    loaded = {}
    for k, rs in runs.items():
        med = {}
        for key in rs[0]:
            xs = [r.get(key) for r in rs]
            if any(not isinstance(x, float) for x in xs):
                med[key] = "n/a"
                continue
            med[key] = statistics.median(xs)
            if key[1] != "endpoint":
                eps = [r.get((key[0], "endpoint")) for r in rs]
                if all(isinstance(e, float) and e > 0 for e in eps):
                    med[("ratio",) + key] = statistics.median(
                        x / e for x, e in zip(xs, eps))
        loaded[k] = (med, metas[k])
        nruns = len(rs)

    lines = report(a, loaded, f"Nanoseconds per call (wall clock, clock_gettime), each figure "
                   f"and each ratio the median of {nruns} runs on this machine",
                   "## Time per call: v1 and v2 against the end-point routine")
    write(a, lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("pair")
    p.add_argument("--key", required=True)
    p.add_argument("--cflags", required=True)
    p.add_argument("plan")
    p.add_argument("cgdir")
    for name in ["insn", "time"]:
        p = sub.add_parser(name)
        p.add_argument("--out", required=True)
        p.add_argument("--v2-dir", default="v2")
        p.add_argument("--seed", default="?")
        p.add_argument("--held", default=None)
        p.add_argument("files", nargs="+")
    a = ap.parse_args()
    {"pair": cmd_pair, "insn": cmd_insn, "time": cmd_time}[a.cmd](a)


if __name__ == "__main__":
    main()
