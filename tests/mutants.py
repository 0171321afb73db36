#!/usr/bin/env python3
"""Mutation check of the contract suite: does every test that should fail, fail?

Applies one deliberate bug at a time to a copy of cylinder_isect.h (in BUILD/mutants, never to
the real file), builds tests/test_float.c, test_double.c (the contract tests of tests/contract/)
and test_api.c against it and counts the failing tests. A mutant is "killed" when at least one runner reports a failure. Patterns
are text of the header: when the header is rewritten a pattern may no longer match; that
mutant is reported as "stale" (update it), not as a failure.

    make tests-mutants            (or: python3 tests/mutants.py BUILD [index...])

Exit status 1 when a mutant survives.
"""
import os
import subprocess
import sys

# (name, text in cylinder_isect.h, replacement): each one a bug the suite must notice.
MUTANTS = [
 ("tangent never", "*tangent = D <= band;", "*tangent = 0;"),
 ("band one-sided", "if (D < -band) return 0;", "if (D < 0) return 0;"),
 ("open: no INSIDE", "c[n].flags = tf | (k ? CYL_F_INSIDE : 0u);", "c[n].flags = tf;"),
 ("outward ignored", "if (opts & CYL_OUTWARD) face = 1;", "if (opts & CYL_OUTWARD) face = face;"),
 ("side facing broken", "face = CYL__P(dot)(no, f->d) > 0 ? -1 : 1;", "face = 1;"),
 ("tmin exclusive", "if (tu >= ray->tmin && tu <= ray->tmax", "if (tu > ray->tmin && tu <= ray->tmax"),
 ("tmax exclusive", "if (tu >= ray->tmin && tu <= ray->tmax", "if (tu >= ray->tmin && tu < ray->tmax"),
 ("t_err zero", "return d * safe;", "return d * 0;"),
 ("t_err huge", "return d * safe;", "return d * 4096;"),
 ("t_err 1/4", "return d * safe;", "return d * CYL__C(0.25);"),
 ("NO_ERRBOUND ignored", "hit->t_err = CYL__MAXR * 2;\n    } else {", "hit->t_err = 0;\n    } else {"),
 ("NO_NORMAL ignored side", "v = CYL__FMAR(c->t, f->ad, f->aw) / f->na;\n        if (!(opts & CYL_NO_NORMAL)) {", "v = CYL__FMAR(c->t, f->ad, f->aw) / f->na;\n        if (1) {"),
 ("parallel band x8", "if (f->A <= CYL__PARA * CYL__PARA * f->aa", "if (f->A <= 64 * CYL__PARA * CYL__PARA * f->aa"),
 ("parallel band /8", "if (f->A <= CYL__PARA * CYL__PARA * f->aa", "if (64 * f->A <= CYL__PARA * CYL__PARA * f->aa"),
 ("cap hits as side", "c[n].part = pos[k] ? sp[k] : CYL_SIDE;", "c[n].part = CYL_SIDE;"),
 ("cap v swapped", "(c->part == CYL_CAP_HIGH ? f->Hu : -f->Hu);", "(c->part == CYL_CAP_HIGH ? -f->Hu : f->Hu);"),
 ("h=0 accepted", "if (!(cyl->h > 0)) return CYL_E_HEIGHT;", "if (!(cyl->h >= 0)) return CYL_E_HEIGHT;"),
 ("r=inf accepted", "if (!(cyl->r > 0) || !(cyl->r <= CYL__MAXR))", "if (!(cyl->r > 0))"),
 ("root off by 1ulp", "    t[0] = q / f->A;\n    t[1] = C / q;", "    t[0] = q / f->A * (1 + 2 * CYL__U);\n    t[1] = C / q;"),
 ("occluded needs 2", ") > 0;\n}\n\n/* The cylinder from p0", ") > 1;\n}\n\n/* The cylinder from p0"),
 ("all writes both", "for (k = 0; k < n; k++) CYL__P(finish)(&f, &c[k], opts, ray, &hits[k]);", "for (k = 0; k < n; k++) CYL__P(finish)(&f, &c[k], opts, ray, &hits[k]);\n    if (n == 1) hits[1] = hits[0];"),
 ("segment axis reversed", "cy.a[i] = p0 && p1 ? p1[i] - p0[i] : 0;", "cy.a[i] = p0 && p1 ? p0[i] - p1[i] : 0;"),
 ("no wall sort", "    if (t[0] > t[1]) { CYL__R x = t[0]; t[0] = t[1]; t[1] = x; }\n    return 1;\n}", "    return 1;\n}"),
 ("precise caps ignored", "pos[k] = CYL__P(side)(f, tw[k], tl[k]);", "pos[k] = 0;"),
 ("trange nan accepted", "if (!(ray->tmin <= ray->tmax)) return CYL_E_TRANGE;", "if (ray->tmin > ray->tmax) return CYL_E_TRANGE;"),
 ("wall v unclamped+1ulp", "hit->v = c->part == CYL_SIDE ? (v > f->Hu ? f->Hu : (v < -f->Hu ? -f->Hu : v))", "hit->v = c->part == CYL_SIDE ? v * (1 + 2 * CYL__U)"),
 ("cap normal flipped outward", "for (i = 0; i < 3; i++) no[i] = sgn * f->a[i] / f->na;", "for (i = 0; i < 3; i++) no[i] = -sgn * f->a[i] / f->na;"),
]


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    only = set(sys.argv[2:])
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    src = open(os.path.join(root, "cylinder_isect.h")).read()
    work = os.path.join(root, build, "mutants")
    hdir = os.path.join(work, "include")
    os.makedirs(hdir, exist_ok=True)
    unity = os.path.join(root, build, "unity")
    unity_o = os.path.join(root, build, "gcc-O2", "unity.o")
    flags = ["-std=c99", "-O1", "-I" + unity, "-DUNITY_INCLUDE_DOUBLE", "-DUNITY_SUPPORT_64",
             "-I" + hdir, "-I" + os.path.join(root, "tests")]
    killed = survived = stale = 0
    for i, (name, old, new) in enumerate(MUTANTS):
        if only and str(i) not in only:
            continue
        if old not in src:
            print(f"stale    [{i}] {name}: pattern not found in cylinder_isect.h")
            stale += 1
            continue
        with open(os.path.join(hdir, "cylinder_isect.h"), "w") as f:
            f.write(src.replace(old, new, 1))
        notes, fails = [], 0
        for t in ("test_float", "test_double", "test_api"):
            exe = os.path.join(work, t)
            r = subprocess.run(["gcc", *flags, os.path.join(root, "tests", t + ".c"), "-x", "none",
                                unity_o, "-lm", "-o", exe], capture_output=True, text=True)
            if r.returncode:
                notes.append(f"{t}: does not build")
                fails += 1
                continue
            r = subprocess.run([exe], capture_output=True, text=True, timeout=300)
            bad = [l for l in r.stdout.splitlines() if ":FAIL" in l]
            if bad:
                notes.append(f"{t}: {len(bad)} failing, first {bad[0].split(':', 2)[2][:70]}")
                fails += len(bad)
            elif r.returncode not in (0, 1):
                notes.append(f"{t}: crashed ({r.returncode})")
                fails += 1
        if fails:
            killed += 1
            print(f"killed   [{i}] {name}: " + "; ".join(notes))
        else:
            survived += 1
            print(f"SURVIVED [{i}] {name}")
    print(f"mutants: {killed} killed, {survived} survived, {stale} stale")
    return 1 if survived else 0


if __name__ == "__main__":
    sys.exit(main())
