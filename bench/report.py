#!/usr/bin/env python3
"""report.py: bench/REPORT.md, bench/error_vs_time.png and docs/accuracy.md's table.

    python bench/report.py --results RESULTS.json [--times T2.json ...] --insn INSN.tsv \
        --md REPORT.md --png PLOT.png [--doc DOC.md] [--table TABLE.md] \
        [--header HDR --goal CMD]                                         (run by `make report`)
    python bench/report.py --insn-table INSN.tsv [--header HDR]           (run by `make insn`)

RESULTS.json: build/bench/bench's accuracy and first timing; T*.json: more timing runs of the
same binary (--time-only); every ns shown is the median over the runs, every time ratio the
median of the runs' ratios. INSN.tsv: instructions per call under callgrind (mk/bench.mk).
DOC.md (docs/accuracy.md) gets the accuracy-and-cost table between its <!-- headline:begin -->
and <!-- headline:end --> markers; TABLE.md gets the same table as a file of its own (`make
report V=2`, which leaves every committed file alone). HDR: the header measured, named in the
report when it is not ./cylinder_isect.h (its git revision comes in $BENCH_LIB_REV); CMD: the
command that regenerates the report, named in it. Variants the measured header does not
provide (RESULTS.json's "unavailable": CYL_PRECISE where it defines CYL_NO_PRECISE) are shown
as n/a. Needs matplotlib for the plot (build/report-venv). Every number comes from those
files; nothing here is measured.
"""
import argparse
import json
import math
import os
import platform
import sys
import datetime

GROUPS = {
    "benign": ["well", "axis", "huge", "tiny", "surface", "trange"],
    "stiff": ["far", "parallel", "grazing", "thin", "flat"],
}
HEADLINE = ["lib", "lib+NO_ERRBOUND+NO_NORMAL", "lib+PRECISE", "endpoint", "literal"]
LABEL = {"lib": "lib (default)", "lib+NO_ERRBOUND+NO_NORMAL": "lib NO_ERRBOUND+NO_NORMAL",
         "lib+PRECISE": "lib PRECISE", "endpoint": "end-point (pa, pb, ra)",
         "literal": "literal (c, unit a, r, h)"}
# the cost targets of issue 17: instructions per capped call on the well-conditioned family as
# a ratio to the end-point routine (judged, PASS/FAIL), and the time ratio's aim (reported)
COST_TARGETS = [("lib+NO_ERRBOUND+NO_NORMAL", 1.3, 1.15), ("lib", 2.0, 1.5),
                ("lib+PRECISE", 3.0, 2.5)]
COST_FAMILY = "well"
ERR_FLOOR = 0.01          # ulps plotted in place of an error of exactly 0
PNAME = {24: "float", 53: "double"}
DEFAULT_HEADER = "cylinder_isect.h"   # v1, the committed report's subject
NA_NOTE = ("- **n/a**: the variant is not available in the measured header (its call returns "
           "an error: `CYL_PRECISE` where the header defines `CYL_NO_PRECISE`).")


def band(prec):
    return 2.0 ** -(prec - 8)


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def fmt(x, nd=3):
    if x is None:
        return "-"
    if isinstance(x, float) and (math.isinf(x) or math.isnan(x)):
        return str(x)
    if x == 0:
        return "0"
    return f"{x:.{nd}g}"


def all_occ(r):
    if r["kind"] != 0:
        return "-"
    return f"{r.get('all_miscls_out', 0)} / {r.get('occ_miscls_out', 0)}"


def agg(rows):
    """Aggregate rows (sets of one variant) into one summary."""
    out = {
        "n": sum(r["n"] for r in rows),
        "miscls": sum(r["miscls"] for r in rows),
        "miscls_out": sum(r["miscls_out"] for r in rows),
        "all_out": sum(r.get("all_miscls_out", 0) for r in rows),
        "occ_out": sum(r.get("occ_miscls_out", 0) for r in rows),
        "worst_margin": max([r["worst_margin"] for r in rows if r["miscls"] > 0] or [0.0]),
        "compared": sum(r["compared"] for r in rows),
        "cond_n": sum(r["cond_n"] for r in rows),
        "cond_ulp_max": max([r["cond_ulp_max"] for r in rows] or [0.0]),
        "stab_max": max([r.get("stab_max", 0.0) for r in rows] or [0.0]),
        "ulp_p99": max([r["ulp_p99"] for r in rows] or [0.0]),
        "rel_max": max([r["rel_max"] for r in rows] or [0.0]),
        "nrm_max": max([r["nrm_max"] for r in rows] or [0.0]),
        "terr_checked": sum(r["terr_checked"] for r in rows),
        "terr_fail": sum(r["terr_fail"] for r in rows),
        "ns": sum(r["ns"] for r in rows) / len(rows) if rows else float("nan"),
    }
    return out


TARGET2_FAMILIES = ["well", "huge", "tiny", "axis"]  # target 2's benign families


def median(xs):
    xs = sorted(x for x in xs if not math.isnan(x))
    if not xs:
        return float("nan")
    m = len(xs) // 2
    return xs[m] if len(xs) % 2 else (xs[m - 1] + xs[m]) / 2


def key(r):
    return (r["prec"], r["family"], r["caps"], r["variant"])


def read_insn(path):
    """(prec, family, caps, variant) -> instructions per call, from mk/bench.mk's insn.tsv"""
    out = {}
    with open(path) as f:
        for line in f:
            p = line.rstrip("\n").split("\t")
            if len(p) == 6:
                out[(int(p[0]), p[1], int(p[2]), p[3])] = float(p[5])
    return out


def insn_table(path, header=DEFAULT_HEADER):
    """`make insn`: the counts of the headline variants, capped sets, and the cost ratios."""
    I = read_insn(path)
    fams = list(dict.fromkeys(k[1] for k in I))
    # a variant with no count at all was left out by the benchmark: not in this header
    counted = {(k[0], k[3]) for k in I}

    def cell(prec, fam, v):
        return fmt(I.get((prec, fam, 1, v)), 4) if (prec, v) in counted else "n/a"

    if header != DEFAULT_HEADER:
        print(f"Header: {header} at commit {os.environ.get('BENCH_LIB_REV') or '?'}\n")
    print("Instructions per capped call (callgrind; the empty loop subtracted)\n")
    print("| precision | family | " + " | ".join(LABEL[v] for v in HEADLINE) + " |")
    print("|---|---|" + "---:|" * len(HEADLINE))
    for prec in (24, 53):
        for fam in fams:
            print(f"| {PNAME[prec]} | {fam} | " +
                  " | ".join(cell(prec, fam, v) for v in HEADLINE) + " |")
    print()
    for prec in (24, 53):
        ep = I.get((prec, COST_FAMILY, 1, "endpoint"))
        for v, lim, _ in COST_TARGETS:
            x = I.get((prec, COST_FAMILY, 1, v))
            if (prec, v) not in counted and I:
                print(f"{PNAME[prec]} {v} / endpoint, {COST_FAMILY} capped: n/a "
                      f"(not available in this header)")
                continue
            if x is None or not ep:
                continue
            print(f"{PNAME[prec]} {v} / endpoint, {COST_FAMILY} capped: {x / ep:.2f} "
                  f"(target <= {lim}): {'PASS' if x / ep <= lim else 'FAIL'}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--insn-table")
    ap.add_argument("--results")
    ap.add_argument("--times", nargs="*", default=[])
    ap.add_argument("--insn")
    ap.add_argument("--md")
    ap.add_argument("--png")
    ap.add_argument("--doc")
    ap.add_argument("--table")
    ap.add_argument("--header", default=DEFAULT_HEADER)
    ap.add_argument("--goal", default="make report")
    ap.add_argument("--cost", help="make cost's tables (cost.md), copied in as a section")
    args = ap.parse_args()
    if args.insn_table:
        insn_table(args.insn_table, args.header)
        return
    if not (args.results and args.insn and args.md and args.png):
        ap.error("--results, --insn, --md and --png are needed")
    png_path = args.png
    for p in (args.md, args.png, args.table):
        if p and os.path.dirname(p):
            os.makedirs(os.path.dirname(p), exist_ok=True)
    # the report's subject: v1 (./cylinder_isect.h) or the header named by --header
    hdr = args.header
    title = "cylinder_isect" if hdr == DEFAULT_HEADER else hdr
    rev = os.environ.get('BENCH_LIB_REV') or '?'
    goal = args.goal
    bdir = os.path.dirname(args.results) or "."
    with open(args.results) as f:
        R = json.load(f)
    unavailable = set(R.get("unavailable") or [])

    def na(prec, v):
        """the benchmark left the variant out: the header does not provide it"""
        return f"{PNAME[prec]} {v}" in unavailable
    runs = [{key(r): r["ns"] for r in R["rows"]}]
    for t in args.times:
        with open(t) as f:
            T = json.load(f)
        if T["seed"] != R["seed"] or T["n"] != R["n"]:
            sys.exit(f"report: {t} is not a timing of the same cases as {args.results}")
        runs.append({key(r): r["ns"] for r in T["rows"]})
    INSN = read_insn(args.insn)
    rows = R["rows"]
    for r in rows:   # every ns shown: the median over the runs
        r["ns_runs"] = [run[key(r)] for run in runs if key(r) in run]
        r["ns"] = median(r["ns_runs"])
        r["insn"] = INSN.get(key(r))
    nruns = len(runs)
    variants = []
    for r in rows:
        if (r["prec"], r["variant"]) not in variants:
            variants.append((r["prec"], r["variant"]))

    def sel(prec=None, variant=None, fams=None, caps=None):
        return [r for r in rows
                if (prec is None or r["prec"] == prec)
                and (variant is None or r["variant"] == variant)
                and (fams is None or r["family"] in fams)
                and (caps is None or r["caps"] == caps)]

    def one(prec, fam, caps, v):
        rs = sel(prec, v, [fam], caps)
        return rs[0] if rs else None

    def time_ratio(prec, fam, caps, v, alt):
        """median over the runs of the run's time ratio v / alt"""
        k, ka = (prec, fam, caps, v), (prec, fam, caps, alt)
        return median([run[k] / run[ka] for run in runs if k in run and ka in run and run[ka]])

    def insn_ratio(prec, fam, caps, v, alt):
        x, y = INSN.get((prec, fam, caps, v)), INSN.get((prec, fam, caps, alt))
        return x / y if x is not None and y else float("nan")

    L = []
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    L.append(f"# {title}: error and cost against the alternatives\n")
    L.append(f"Generated by `{goal}` on {now}. Regenerate with `{goal}` "
             f"(options: `BENCH_SEED=... BENCH_N=... BENCH_RUNS=...`); the raw numbers are in "
             f"`{args.results}`, `{bdir}/times-*.json` and "
             f"`{args.insn}`, a single case is shown in full by "
             f"`{bdir}/probe PREC FAMILY CAPS INDEX`.\n")
    L.append("| | |\n|---|---|")
    L.append(f"| machine | {cpu_model()}, {os.cpu_count()} logical cores, {platform.machine()}, "
             f"{platform.system()} {platform.release()} |")
    L.append(f"| compiler | gcc {R.get('compiler', '?')}, `{R.get('cflags', '?')}` (+ `-std=c99`) |")
    L.append(f"| library | {hdr} at commit {rev} |")
    L.append(f"| seed | {R['seed']} |")
    L.append(f"| cases | {R['n']} per family x caps on/off x precision; every variant runs the "
             f"same cases |")
    L.append(f"| time | ns per call: throughput over the set's cases, {R['rounds']} interleaved "
             f"rounds of ~{R['block_ms']} ms per variant, fastest round; the median of "
             f"{nruns} runs of the benchmark (time ratios: the median of the {nruns} runs' "
             f"ratios); each variant's loop inlines its routine with its options folded, as at "
             f"a user's single call site; shared machine |")
    L.append("| instructions | per call, counted by callgrind in the same binary's timing loops "
             "(one pass over the same cases), the empty loop subtracted; exact, the same on "
             "every run |")
    L.append("| timed cases | capped sets: the cases of finite height (the end-point formulation "
             "cannot express an infinite one), for every variant; open sets: every case |")
    if R.get("unavailable"):
        L.append(f"| not available in this build | {', '.join(R['unavailable'])} |")
    L.append("")
    L.append("Inputs: the library takes its ray (o, d, tmin, tmax) and cylinder (c, a, r, h) as "
             "generated. The alternatives take theirs in their own form, prepared before any "
             "call is timed: **literal**: the same ray, the cylinder with a unit axis a/|a|; "
             "**end-point** (pa, pb, ra; Quilez's capped-cylinder formulation): pa = c − â h/2, "
             "pb = c + â h/2, ra = r and a unit direction d/|d| (t range scaled by |d|, its t "
             "divided by |d| for the comparison). Each returns t and the outward normal only. "
             "Their errors include the rounding of that preparation (about an ulp of the data), "
             "which their users holding data in that form would not have.\n")
    L.append("Reference: `ref/cyl_ref.c`, exact polynomial quantities in MPFR (precision grows "
             "with the exponent span, every operation checked exact), roots at >= 320 bits. "
             "**Misclassified**: hit vs miss, wrong part or wrong crossing. **Margin**: relative "
             "distance of the case to the nearest decision boundary (tangency, parallel "
             "tolerance, rim, tmin/tmax); *beyond band* counts misclassifications whose margin "
             "exceeds 2^-(p-8), i.e. that a correct-to-a-few-ulps decision would not make. "
             "**ulps**: |t - t_exact| in ulps of t_exact; *cond* restricts to well-conditioned "
             "hits (a relative data change of u moves t by at most one ulp, ev_kappa: the radius on a "
             "wall, nothing on a cap); *ulps/κ*: the largest ulps per unit of the full condition "
             "κ (every component of o − c, d, a and r, h moved by a relative u moves t by at most "
             "κ·u·|t|; bench/eval.c, ev_kappa_full) over every hit above the band: about 1 for "
             "a backward-stable method, however ill-conditioned the hit. **rel**: |t - "
             "t_exact| / max(|t|, r/|d|). **n err**: |n - n_exact|. **t_err fail**: exact t "
             "outside [t - t_err, t + t_err] (must be 0).\n")

    # ---------------------------------------------------------------- headline
    HEAD = "## Headline: accuracy over all families (caps on and off), cost per capped call\n"
    L.append(HEAD)
    hl = []
    for prec in (24, 53):
        for v in HEADLINE:
            rs = sel(prec, v)
            if not rs:
                if na(prec, v):
                    hl.append((f"{PNAME[prec]} {LABEL[v]}",) + ("n/a",) * 5)
                continue
            a = agg(rs)
            w = one(prec, COST_FAMILY, 1, v)
            tf = f"{a['terr_fail']} of {a['terr_checked']}" if a["terr_checked"] else "-"
            hl.append((f"{PNAME[prec]} {LABEL[v]}", fmt(w["ns"], 3) if w else "-",
                       fmt(w["insn"], 4) if w else "-", str(a["miscls_out"]),
                       fmt(a["cond_ulp_max"]), tf))
    hl_head = ("| variant | ns per call | instructions per call | misclassified beyond the band "
               "| worst ulps, well-conditioned hits | t_err failures |\n"
               "|---|---:|---:|---:|---:|---:|")
    hl_lines = [hl_head] + ["| " + " | ".join(x) + " |" for x in hl]
    hl_notes = [
        f"- **variant**: float or double API; the library with its default options, with "
        f"`CYL_NO_ERRBOUND|CYL_NO_NORMAL` and with `CYL_PRECISE`; the end-point (pa, pb, ra) "
        f"and the literal formulations, each fed its own input form (bench/alt_formulations.h).",
        f"- **ns per call**: time per capped call on the well-conditioned family, median of "
        f"{nruns} benchmark runs on this machine ({cpu_model()}, `{R.get('cflags', '?')}`).",
        "- **instructions per call**: the same calls counted by callgrind in the same binary, "
        "exact and repeatable where time is not.",
        f"- **misclassified beyond the band**: hit/miss, part or crossing different from the "
        f"exact answer although the case is farther than 2^-(p-8) from any decision boundary, "
        f"over all {len(R['families'])} families with and without caps ({R['n']} cases each; the "
        f"end-point routine only on the capped cases of finite height it can express).",
        "- **worst ulps, well-conditioned hits**: largest |t − t_exact| in ulps of t_exact where "
        "a relative change u of the data moves t by at most one ulp.",
        "- **t_err failures**: hits whose exact t lies outside [t − t_err, t + t_err], of those "
        "checked; `-`: no error bound.",
    ]
    if any(na(prec, v) for prec in (24, 53) for v in HEADLINE):
        hl_notes.append(NA_NOTE)
    L.extend(hl_lines)
    L.append("")
    L.extend(hl_notes)
    L.append("")

    # ---------------------------------------------------------------- targets
    L.append("## Targets (issues 3 and 17)\n")
    L.append("| target | precision | result | numbers |")
    L.append("|---|---|---|---|")
    for prec in (24, 53):
        libv = [v for (p, v) in variants if p == prec and v.startswith("lib")]
        fails = sum(r["terr_fail"] for r in sel(prec) if r["variant"] in libv)
        checked = sum(r["terr_checked"] for r in sel(prec) if r["variant"] in libv)
        L.append(f"| 1. t_err contains the exact t, every library variant | {PNAME[prec]} | "
                 f"{'PASS' if fails == 0 else 'FAIL'} | {fails} of {checked} hits outside |")
    for prec in (24, 53):
        a = agg(sel(prec, "lib", TARGET2_FAMILIES))
        ok = a["miscls_out"] + a["all_out"] + a["occ_out"] == 0 and a["cond_ulp_max"] <= 4
        L.append(f"| 2. default path, well/huge/tiny/axis: no misclassification beyond "
                 f"2^-{prec - 8}, t within 4 ulps | {PNAME[prec]} | {'PASS' if ok else 'FAIL'} | "
                 f"{a['miscls_out']} beyond band (intersect_all {a['all_out']}, occluded "
                 f"{a['occ_out']}); max {fmt(a['cond_ulp_max'])} ulps over "
                 f"{a['cond_n']} well-conditioned hits; at most {fmt(a['stab_max'])} ulps per "
                 f"unit of the full condition κ |")
    for prec in (24, 53):
        rs = sel(prec, "lib+PRECISE")
        if not rs:
            L.append(f"| 3. CYL_PRECISE | {PNAME[prec]} | n/a | not available in this build |")
            continue
        a = agg(rs)
        ok = a["miscls_out"] + a["all_out"] + a["occ_out"] == 0 and a["cond_ulp_max"] <= 2
        ratios = [time_ratio(prec, fam, caps, "lib+PRECISE", "lib")
                  for fam in R["families"] for caps in (0, 1)
                  if one(prec, fam, caps, "lib+PRECISE") and one(prec, fam, caps, "lib")]
        ratios = [x for x in ratios if not math.isnan(x)]
        rmax = max(ratios) if ratios else float("nan")
        rmean = sum(ratios) / len(ratios) if ratios else float("nan")
        L.append(f"| 3. CYL_PRECISE, all families: no misclassification beyond band, t within "
                 f"2 ulps (well-conditioned) | {PNAME[prec]} | {'PASS' if ok else 'FAIL'} | "
                 f"{a['miscls_out']} beyond band (worst margin {fmt(a['worst_margin'])}; "
                 f"intersect_all {a['all_out']}, occluded {a['occ_out']}); max "
                 f"{fmt(a['cond_ulp_max'])} ulps over {a['cond_n']} hits |")
        L.append(f"| 3. CYL_PRECISE at most 2x the default path's time | {PNAME[prec]} | "
                 f"{'PASS' if rmax <= 2 else 'FAIL'} | time ratio mean {fmt(rmean)}, worst "
                 f"{fmt(rmax)} over family x caps (each the median of {nruns} runs) |")
    for prec in (24, 53):
        for v, lim, aim in COST_TARGETS:
            if na(prec, v):
                L.append(f"| 4. {v}: instructions per capped call on the {COST_FAMILY} family at "
                         f"most {lim}x the end-point routine's | {PNAME[prec]} | n/a | not "
                         f"available in this build |")
                continue
            ir = insn_ratio(prec, COST_FAMILY, 1, v, "endpoint")
            tr = time_ratio(prec, COST_FAMILY, 1, v, "endpoint")
            x, y = INSN.get((prec, COST_FAMILY, 1, v)), INSN.get((prec, COST_FAMILY, 1, "endpoint"))
            res = "n/a" if math.isnan(ir) else ("PASS" if ir <= lim else "FAIL")
            L.append(f"| 4. {v}: instructions per capped call on the {COST_FAMILY} family at most "
                     f"{lim}x the end-point routine's | {PNAME[prec]} | {res} | {fmt(ir, 3)}x "
                     f"({fmt(x, 4)} / {fmt(y, 4)}); time {fmt(tr, 3)}x (median of {nruns} runs; "
                     f"aim {aim}x: {'met' if tr <= aim else 'not met'}) |")
    L.append("")

    # ---------------------------------------------------------------- cost per family
    L.append("## Cost per capped call, every family\n")
    L.append("Instructions per call / ns per call of each variant, and the ratios of "
             "target 4 (instructions; time in parentheses) to the end-point routine. Target 4 "
             f"is judged on {COST_FAMILY} only.\n")
    L.append("| precision | family | " + " | ".join(LABEL[v] for v in HEADLINE) + " | " +
             " | ".join(f"{LABEL[v]} / end-point" for v, _, _ in COST_TARGETS) + " |")
    L.append("|---|---|" + "---:|" * (len(HEADLINE) + len(COST_TARGETS)))
    for prec in (24, 53):
        for fam in R["families"]:
            cells = []
            for v in HEADLINE:
                r = one(prec, fam, 1, v)
                cells.append(f"{fmt(r['insn'], 4)} / {fmt(r['ns'], 3)}" if r else
                             "n/a" if na(prec, v) else "-")
            for v, _, _ in COST_TARGETS:
                cells.append("n/a" if na(prec, v) else
                             f"{fmt(insn_ratio(prec, fam, 1, v, 'endpoint'), 3)} "
                             f"({fmt(time_ratio(prec, fam, 1, v, 'endpoint'), 3)})")
            L.append(f"| {PNAME[prec]} | {fam} | " + " | ".join(cells) + " |")
    L.append("")
    png_rel = os.path.relpath(png_path, os.path.dirname(args.md) or ".")
    L.append(f"![error against time]({png_rel})\n")
    L.append("x: ns per call (mean over the group's families and caps variants); y: worst "
             "t error in ulps of the exact t over the well-conditioned hits where the variant "
             "agrees with the reference on hit, part and crossing (so that the inherent error of "
             "grazing contacts does not hide the method's own error); hollow markers: the "
             "variant also misclassifies beyond the band in that group. The dashed line is the "
             "Pareto front of each group (no other point is both faster and more accurate). "
             f"Groups: benign = {', '.join(GROUPS['benign'])}; stiff = "
             f"{', '.join(GROUPS['stiff'])}.\n")

    # ---------------------------------------------------------------- make cost's tables
    if args.cost:  # as `make cost` wrote them, in the program a renderer would be
        with open(args.cost) as f:
            cost = f.read().strip()
        if not cost.startswith("## "):
            sys.exit(f"report: {args.cost} does not start with a ## heading")
        head, _, body = cost.partition("\n")
        L.append(f"{head} (`make cost`, copied by `{goal}`)\n")
        L.append(body.strip() + "\n")

    # ---------------------------------------------------------------- full tables
    L.append("## Full results\n")
    for prec in (24, 53):
        L.append(f"### {PNAME[prec]}\n")
        L.append("| family | caps | variant | cases | ref hits | misclassified (beyond band) | "
                 "worst margin | all / occluded beyond band | ulps median | p99 | max "
                 "| cond max (n) | ulps/κ | max rel | max n err | t_err fail | ns/call | insn/call |")
        L.append("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for fam in R["families"]:
            for caps in (0, 1):
                for r in sel(prec, None, [fam], caps):
                    tf = f"{r['terr_fail']}/{r['terr_checked']}" if r["terr_checked"] else "-"
                    L.append(f"| {fam} | {caps} | {r['variant']} | {r['n']} | {r['ref_hits']} | "
                             f"{r['miscls']} ({r['miscls_out']}) | "
                             f"{fmt(r['worst_margin']) if r['miscls'] else '-'} | "
                             f"{all_occ(r)} | "
                             f"{fmt(r['ulp_median'])} | {fmt(r['ulp_p99'])} | "
                             f"{fmt(r['ulp_max'])} | {fmt(r['cond_ulp_max'])} ({r['cond_n']}) | "
                             f"{fmt(r.get('stab_max', float('nan')))} | "
                             f"{fmt(r['rel_max'])} | "
                             f"{fmt(r['nrm_max']) if 'NO_NORMAL' not in r['variant'] else '-'} | "
                             f"{tf} | {fmt(r['ns'])} | {fmt(r['insn'], 4)} |")
        L.append("")
    with open(args.md, "w") as f:
        f.write("\n".join(L) + "\n")

    # the headline table and its column notes also go into docs/accuracy.md, between its
    # markers (scripts/sync-readme.py copies them into the README), or into a file of its own
    lib = "" if hdr == DEFAULT_HEADER else f"{hdr} at commit {rev}; "
    block = "\n".join(
        [f"{lib}Seed {R['seed']}, {R['n']} cases per family x caps x precision, {now}; every "
         f"figure from `{goal}` (all of them in {args.md}).", ""]
        + hl_lines + [""] + hl_notes)
    if args.table:
        with open(args.table, "w") as f:
            f.write(block + "\n")
    if args.doc:
        with open(args.doc) as f:
            text = f.read()
        b, e = "<!-- headline:begin -->", "<!-- headline:end -->"
        if b not in text or e not in text:
            sys.exit(f"report: markers {b} {e} not found in {args.doc}")
        text = text[:text.index(b) + len(b)] + "\n" + block + "\n" + text[text.index(e):]
        with open(args.doc, "w") as f:
            f.write(text)

    # ---------------------------------------------------------------- plot
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(13, 5.5), sharey=False)
    names = [v for v in dict.fromkeys(v for (_, v) in variants)]
    cmap = plt.get_cmap("tab10")
    color = {v: cmap(i % 10) for i, v in enumerate(names)}
    marker = {"benign": "o", "stiff": "^"}
    for ax, prec in zip(axes, (24, 53)):
        for g, fams in GROUPS.items():
            pts = []
            for v in names:
                rs = sel(prec, v, fams)
                if not rs:
                    continue
                a = agg(rs)
                y = max(a["cond_ulp_max"], ERR_FLOOR)
                x = a["ns"]
                bad = a["miscls_out"] > 0
                ax.scatter([x], [y], s=55, marker=marker[g],
                           facecolors="none" if bad else color[v], edgecolors=color[v],
                           linewidths=1.5, label=f"{v}" if g == "benign" else None, zorder=3)
                pts.append((x, y))
            pts.sort()
            front, best = [], float("inf")
            for x, y in pts:
                if y < best:
                    front.append((x, y))
                    best = y
            if front:
                fx = [p[0] for p in front]
                fy = [p[1] for p in front]
                ax.step(fx, fy, where="post", linestyle="--", color="gray" if g == "benign"
                        else "black", linewidth=1, zorder=2,
                        label=f"Pareto front ({g}: {'o' if g == 'benign' else '^'})")
        ax.set_yscale("log")
        ax.set_xlabel("ns per call")
        ax.set_ylabel("worst t error, ulps (well-conditioned hits)")
        ax.set_title(f"{PNAME[prec]}: o benign families, ^ stiff families")
        ax.grid(True, which="both", alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=8, frameon=False)
    fig.suptitle(f"{title}: error against run time (seed {R['seed']}, "
                 f"{R['n']} cases per family; hollow = misclassifies beyond 2^-(p-8))",
                 fontsize=10)
    fig.tight_layout(rect=(0, 0.12, 1, 0.95))
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    main()
