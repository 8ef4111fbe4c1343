#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""make bench: cable against AUTO-07p on the flat (7,2) braid knot, in one run.

Usage: /usr/bin/python3 scripts/bench_compare.py BUILD_DIR [REPEATS]

Both programs run the same AUTO-format equation data: AUTO-07p runs
tests/auto07p/knot72auto.c (written by scripts/gen_braid.py: the same generated
right-hand side as cable's), cable runs its built-in braid_knot (the same
equations and conditions; cable's loader for AUTO equation files is not on this
branch yet).  Both start from the same solution file: cable's first point of the
flat branch (label 1 of a run with NMX=1), given to AUTO as fort.3 and to cable
as s=...  Settings (issue 17): NDIM 21, NTST 150, NCOL 4, IAD 3, EPSL = EPSU =
1e-7, EPSS = 1e-5, DS = -5, DSMAX = 5, NMX 60.  Per-step cost = (time of the
NMX=60 run - time of the NMX=2 run) / 58, which removes start-up and the first
point.  Runs alternate between the programs and cases; each time is the median
of REPEATS runs (default 3).  Output: markdown on stdout.
"""

import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
AUTO_DIR = "/usr/lib/auto-07p"

SETTINGS = dict(NTST=150, NCOL=4, IAD=3, EPSL=1e-7, EPSU=1e-7, EPSS=1e-5, DS=-5.0, DSMAX=5.0, DSMIN=1e-6)
# BENCH_NMX, BENCH_NTSTS ("25 50 ..."), BENCH_SWEEP_NMX, BENCH_GEOM_NMX: smaller settings to check this
# script's logic quickly (the tables' texts name the settings used)
NLONG, NSHORT = int(os.environ.get("BENCH_NMX", "60")), 2
# the NTST sweep: per step = (NMX=NSWEEP run - NMX=2 run) / (NSWEEP - 2), medians of at least SWEEP_REPEATS
# runs.  With 10 steps and 3 runs the differences of a few tenths of a second were at the mercy of the
# machine's other jobs (2026-11-25: 0.029 to 0.19 ms per step and NTST in one run); with 20 steps and 5
# runs still 0.063 to 0.149 (make bench at 9a6c2cc; the NMX=22 run's CPU time at NTST 200 alone
# spread 0.73-0.97 s over three runs): 60 steps, as in the main table
NSWEEP = int(os.environ.get("BENCH_SWEEP_NMX", "62"))
SWEEP_REPEATS = int(os.environ.get("BENCH_SWEEP_REPEATS", "5"))
NTSTS = [int(x) for x in os.environ.get("BENCH_NTSTS", "25 50 100 200 400 800").split()]
# the geometry share: link102's flat branch (runs/link102/c.link102, NTST 100) with and without the
# geometric columns, per step = (NMX=GEOM_NMX run - NMX=GEOM_SHORT run) / (GEOM_NMX - GEOM_SHORT)
GEOM_NMX, GEOM_SHORT = int(os.environ.get("BENCH_GEOM_NMX", "61")), 11



def load_range(loads):
    """'min / median / max' of the 1-minute load averages ('1.23 4.56 7.89' strings)."""
    one = [float(x.split()[0]) for x in loads]
    return "%.2f / %.2f / %.2f" % (min(one), statistics.median(one), max(one))

def load():
    with open("/proc/loadavg") as fh:
        return " ".join(fh.read().split()[:3])


def timed(cmd, cwd, env=None):
    """Run cmd; return (wall s, cpu s of the child, peak RSS in MB, returncode)."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.stderr.close()
    rc = os.waitstatus_to_exitcode(status)
    return wall, ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024.0, rc


class Bench:
    def __init__(self, build, repeats):
        self.build = os.path.abspath(build)
        self.repeats = repeats
        self.work = os.path.join(self.build, "bench")
        self.cable = os.path.join(self.build, "cable")
        self.exe = os.path.join(self.work, "knot72auto.exe")
        self.loads = []
        os.makedirs(self.work, exist_ok=True)
        shutil.copy(os.path.join(ROOT, "runs", "knot72", "c.knot72"), self.work)

    # ---- setup -------------------------------------------------------------
    def build_auto(self):
        src = os.path.join(ROOT, "tests", "auto07p", "knot72auto.c")
        obj = os.path.join(self.work, "knot72auto.o")
        subprocess.run(["gcc", "-O2", "-fPIC", "-c", src, "-o", obj],  # auto_f2c.h: /usr/include
                       check=True)
        objs = sorted(os.path.join(AUTO_DIR, "lib", f) for f in os.listdir(os.path.join(AUTO_DIR, "lib"))
                      if f.endswith(".o"))
        subprocess.run(["gfortran", "-fopenmp", "-O2", obj] + objs + ["-L" + os.path.join(AUTO_DIR, "lib"),
                        "-lauto_c", "-o", self.exe], check=True)

    def start_file(self, ntst):
        name = "start%d" % ntst
        if not os.path.exists(os.path.join(self.work, "s." + name)):
            subprocess.run([self.cable, "run", "c=knot72", "e=braid_knot", "NTST=%d" % ntst, "NCOL=4", "NMX=1",
                            "ISP=0", "NSV=0", "sv=" + name], cwd=self.work, check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return name

    # ---- one run of each program --------------------------------------------
    def run_cable(self, tag, ntst, nmx, isp, jac, nthreads):
        start = self.start_file(ntst)
        s = dict(SETTINGS, NTST=ntst)
        args = [self.cable, "run", "c=knot72", "e=braid_knot", "s=" + start, "IRS=1", "NMX=%d" % nmx,
                "ISP=%d" % isp, "NSV=%d" % (2 if isp else 0), "JAC=%d" % jac, "NTHREADS=%d" % nthreads,
                "sv=" + tag] + ["%s=%s" % (k, v) for k, v in s.items()]
        return timed(args, self.work)

    def run_auto(self, tag, ntst, nmx, isp, jac, nthreads=1):
        start = self.start_file(ntst)
        d = os.path.join(self.work, "auto_" + tag)
        os.makedirs(d, exist_ok=True)
        shutil.copy(os.path.join(self.work, "s." + start), os.path.join(d, "fort.3"))
        s = dict(SETTINGS, NTST=ntst)
        with open(os.path.join(d, "fort.2"), "w") as fh:
            fh.write("NDIM=21, IPS=4, IRS=1, ILP=0\n")
            fh.write("ICP=[1, 2, 3, 14, 16, 18, 20]\n")
            fh.write("NTST=%d, NCOL=%d, IAD=%d, ISP=%d, ISW=1, IPLT=0, NBC=24, NINT=0\n"
                     % (s["NTST"], s["NCOL"], s["IAD"], isp))
            fh.write("NMX=%d, NPR=0, MXBF=0, IID=2, ITMX=9, ITNW=5, NWTN=3, JAC=%d\n" % (nmx, jac))
            fh.write("EPSL=%g, EPSU=%g, EPSS=%g\n" % (s["EPSL"], s["EPSU"], s["EPSS"]))
            fh.write("DS=%g, DSMIN=%g, DSMAX=%g, IADS=1\n" % (s["DS"], s["DSMIN"], s["DSMAX"]))
            fh.write("NPAR=36, THL={}, THU={}, UZR={}\n")
            fh.write("RL0=-34.0, RL1=34.0, A0=0.0, A1=1e30\n")
        # AUTO-07p's OpenMP with as many threads as cable's NTHREADS in the same comparison
        env = dict(os.environ, OMP_NUM_THREADS=str(nthreads))
        r = timed([self.exe], d, env)
        return r

    # ---- results -----------------------------------------------------------
    def cable_points(self, tag):
        """(T, F) of every point of cable's b-file, and the Newton iterations of its steps."""
        pts = []
        with open(os.path.join(self.work, "b." + tag)) as fh:
            for line in fh:
                f = line.split()
                if len(f) > 8 and f[0] != "0" and re.match(r"^-?\d+$", f[1]):
                    pts.append((float(f[4]), float(f[9])))
        its = 0
        with open(os.path.join(self.work, "d." + tag)) as fh:
            lines = fh.readlines()
        for i, line in enumerate(lines):
            if line.split()[:3] == ["BR", "PT", "IT"] and i + 1 < len(lines):
                g = lines[i + 1].split()
                if len(g) > 2 and g[1] != "1":
                    its += int(g[2])
        return pts, its

    def auto_points(self, tag):
        pts = []
        with open(os.path.join(self.work, "auto_" + tag, "fort.7")) as fh:
            for line in fh:
                f = line.split()
                if len(f) > 8 and f[0] != "0" and re.match(r"^-?\d+$", f[1]):
                    pts.append((float(f[4]), float(f[9])))
        its = 0
        with open(os.path.join(self.work, "auto_" + tag, "fort.9")) as fh:
            for line in fh:
                m = re.match(r"^\s*\d+\s+\d+\s+Iterations\s*:\s*(\d+)", line)
                if m:
                    its += int(m.group(1))
        return pts, its

    def alternate(self, cases, nlong=NLONG, repeats=None):
        """cases: list of (key, fn(nmx) -> timed tuple).  Alternates them, REPEATS (or repeats) times each
        at NMX nlong and 2.  Returns {key: dict(long=median wall, short=..., cpu_long, cpu_short, rss)}."""
        res = {k: {"long": [], "short": [], "cl": [], "cs": [], "rss": []} for k, _ in cases}
        for _ in range(repeats or self.repeats):
            for nmx, lk, ck in ((nlong, "long", "cl"), (NSHORT, "short", "cs")):
                for k, fn in cases:
                    self.loads.append(load())
                    w, c, rss, rc = fn(nmx)
                    if rc != 0:
                        raise SystemExit("bench: %s (NMX=%d) failed with status %d" % (k, nmx, rc))
                    res[k][lk].append(w)
                    res[k][ck].append(c)
                    res[k]["rss"].append(rss)
        out = {}
        for k, v in res.items():
            out[k] = dict(long=statistics.median(v["long"]), short=statistics.median(v["short"]),
                          cl=statistics.median(v["cl"]), cs=statistics.median(v["cs"]), rss=max(v["rss"]))
            out[k]["step"] = (out[k]["long"] - out[k]["short"]) / (nlong - NSHORT)
            out[k]["cstep"] = (out[k]["cl"] - out[k]["cs"]) / (nlong - NSHORT)
        return out


def agree(a, b):
    """Largest relative difference in F and largest difference in T over the common points."""
    n = min(len(a), len(b))
    dT = max(abs(a[i][0] - b[i][0]) for i in range(n))
    dF = max(abs(a[i][1] - b[i][1]) / abs(b[i][1]) for i in range(n))
    return n, dT, dF


def work_model(r):
    """Amdahl's law fitted to the 1- and 2-thread wall times per step: T(p) = T1 (s + (1 - s) / p)."""
    print("Work model (Amdahl's law fitted to this table's 1- and 2-thread wall times per step, s = the")
    print("serial fraction, s = 2 T2 / T1 - 1; doc/engine.md, Threads, has the model from a profile):")
    print()
    print("| program, case | s | predicted s/step, 8 threads | predicted s/step, 16 threads | speed-up at 16 |")
    print("|---|---:|---:|---:|---:|")
    for name, a, b in (("AUTO-07p, ISP=0", "auto_isp0_jac1", "auto_isp0_jac1_t2"),
                       ("cable, ISP=0", "cable_isp0_jac1_t1", "cable_isp0_jac1_t2"),
                       ("AUTO-07p, ISP=2", "auto_isp2_jac1", "auto_isp2_jac1_t2"),
                       ("cable, ISP=2 NSV=2", "cable_isp2_jac1_t1", "cable_isp2_jac1_t2")):
        t1, t2 = r[a]["step"], r[b]["step"]
        sf = min(max(2 * t2 / t1 - 1, 0.0), 1.0)
        t8, t16 = t1 * (sf + (1 - sf) / 8), t1 * (sf + (1 - sf) / 16)
        print("| %s | %.2f | %.4f | %.4f | %.1f |" % (name, sf, t8, t16, t1 / t16))
    print()


def geometry_share(B):
    """The per-step share of PVLS's geometric columns (Lk, pmin, dmin) on runs/link102's flat branch."""
    d = os.path.join(B.work, "geom")
    os.makedirs(d, exist_ok=True)
    shutil.copy(os.path.join(ROOT, "runs", "link102", "c.link102"), d)
    icps = {"with": "['T', 'F', 'h', 'Ham', 'Phi', 'Lk', 'pmin', 'dmin']", "without": "['T', 'F', 'h', 'Ham', 'Phi']"}

    def run(icp, nmx):
        return timed([B.cable, "run", "c=link102", "e=braid_link", "NMX=%d" % nmx, "NPR=1000", "NTHREADS=1",
                      "ICP=" + icps[icp], "sv=geom_%s_%d" % (icp, nmx)], d)
    res = {k: {"l": [], "s": []} for k in icps}
    for _ in range(B.repeats):
        for nmx, lk in ((GEOM_NMX, "l"), (GEOM_SHORT, "s")):
            for k in icps:
                w, c, rss, rc = run(k, nmx)
                if rc != 0:
                    raise SystemExit("bench: link102 geometry run (%s, NMX=%d) failed with status %d" % (k, nmx, rc))
                res[k][lk].append(c)
    per = {k: (statistics.median(v["l"]) - statistics.median(v["s"])) / (GEOM_NMX - GEOM_SHORT)
           for k, v in res.items()}
    print("## The geometric columns' share of a step (runs/link102/c.link102, NTST 100, 1 thread)")
    print()
    print("The flat (10,2) link's branch with ISP=2 NSV=2 as the scene runs it, with ICP listing Lk, pmin")
    print("and dmin (PVLS computes them at every step: Lk by its update along the branch, dmin by the tree")
    print("search, doc/geometry.md) and without them; CPU per step = (NMX=%d run - NMX=%d run) / %d,"
          % (GEOM_NMX, GEOM_SHORT, GEOM_NMX - GEOM_SHORT))
    print("medians of %d alternated runs." % B.repeats)
    print()
    print("| ICP | CPU s/step |")
    print("|---|---:|")
    print("| with Lk, pmin, dmin | %.4f |" % per["with"])
    print("| without | %.4f |" % per["without"])
    print()
    print("Share of the geometry: %.1f %% of a step (issue 30's target: at most 10 %%)."
          % (100 * (per["with"] - per["without"]) / per["with"]))
    print()


def main():
    build = sys.argv[1]
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    B = Bench(build, repeats)
    B.build_auto()
    t_start = time.time()
    print("Load (1, 5, 15 min averages) at the start: %s; %d cores." % (load(), os.cpu_count()))
    print()

    # ---- the table: NTST 150 ----------------------------------------
    cases = [
        ("auto_isp0_jac0", lambda nmx: B.run_auto("isp0_jac0_%d" % nmx, 150, nmx, 0, 0)),
        ("cable_isp0_jac0_t1", lambda nmx: B.run_cable("c_isp0_jac0_t1_%d" % nmx, 150, nmx, 0, 0, 1)),
        ("auto_isp0_jac1", lambda nmx: B.run_auto("isp0_jac1_%d" % nmx, 150, nmx, 0, 1)),
        ("cable_isp0_jac1_t1", lambda nmx: B.run_cable("c_isp0_jac1_t1_%d" % nmx, 150, nmx, 0, 1, 1)),
        ("auto_isp0_jac1_t2", lambda nmx: B.run_auto("isp0_jac1_t2_%d" % nmx, 150, nmx, 0, 1, 2)),
        ("cable_isp0_jac1_t2", lambda nmx: B.run_cable("c_isp0_jac1_t2_%d" % nmx, 150, nmx, 0, 1, 2)),
        ("auto_isp2_jac1", lambda nmx: B.run_auto("isp2_jac1_%d" % nmx, 150, nmx, 2, 1)),
        ("cable_isp2_jac1_t1", lambda nmx: B.run_cable("c_isp2_jac1_t1_%d" % nmx, 150, nmx, 2, 1, 1)),
        ("auto_isp2_jac1_t2", lambda nmx: B.run_auto("isp2_jac1_t2_%d" % nmx, 150, nmx, 2, 1, 2)),
        ("cable_isp2_jac1_t2", lambda nmx: B.run_cable("c_isp2_jac1_t2_%d" % nmx, 150, nmx, 2, 1, 2)),
    ]
    r = B.alternate(cases)
    load_main = load()

    # agreement of the 60 points, and iterations
    L = NLONG
    ap, ait = B.auto_points("isp0_jac1_%d" % L)
    cp, cit = B.cable_points("c_isp0_jac1_t1_%d" % L)
    n, dT, dF = agree(ap, cp)
    cp2, cit2 = B.cable_points("c_isp0_jac1_t2_%d" % L)
    same12 = open(os.path.join(B.work, "b.c_isp0_jac1_t1_%d" % L)).read().split("\n")[10:] == \
        open(os.path.join(B.work, "b.c_isp0_jac1_t2_%d" % L)).read().split("\n")[10:]
    same12s = open(os.path.join(B.work, "s.c_isp0_jac1_t1_%d" % L)).read() == \
        open(os.path.join(B.work, "s.c_isp0_jac1_t2_%d" % L)).read()
    cpb1, _ = B.cable_points("c_isp2_jac1_t1_%d" % L)
    cpb2, _ = B.cable_points("c_isp2_jac1_t2_%d" % L)

    print("## Cost per step, flat (7,2) branch, NTST 150, NCOL 4 (the issue's settings)")
    print()
    print("Settings: NDIM 21, NTST 150, NCOL 4, IAD 3, EPSL = EPSU = 1e-7, EPSS = 1e-5, DS = -5,")
    print("DSMAX = 5, NMX %d, both from the same start (cable's first point of the flat branch, label 1)." % NLONG)
    print("AUTO-07p 0.9.2 runs `tests/auto07p/knot72auto.c` (generated by scripts/gen_braid.py from the same")
    print("sympy right-hand side as cable's) with OMP_NUM_THREADS equal to cable's NTHREADS in the same row;")
    print("cable runs its built-in `braid_knot` (the same equations; the file itself through cable: below the")
    print("table, when cable has the loader).")
    print("Per step = (median wall time of the NMX=%d run - that of the NMX=2 run) / %d, medians of %d"
          % (NLONG, NLONG - NSHORT, repeats))
    print("alternated runs; CPU = the same from the process's user+system time (on a loaded machine wall")
    print("time of a one-thread run is its CPU time plus waiting).  Per iteration = per step / (Newton")
    print("iterations of the steps / steps).  AUTO's branch-point test: ISP=2 (its determinant test);")
    print("cable's: ISP=2, NSV=2 (determinant sign, two smallest singular values, the pencil test when")
    print("the singular values say a crossing may lie in the step, double-BP location by minimisation).")
    print("Every ratio compares the same number of threads.")
    print()
    print("| case | threads (AUTO = cable) | AUTO-07p s/step | cable s/step | AUTO / cable (wall) | CPU s/step AUTO | CPU s/step cable | AUTO / cable (CPU) | cable peak memory (MB) | AUTO peak memory (MB) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")

    def row(name, nt, a, c):
        A, C = r[a], r[c]
        print("| %s | %d | %.4f | %.4f | %.1f | %.4f | %.4f | %.1f | %.0f | %.0f |" % (
            name, nt, A["step"], C["step"], A["step"] / C["step"], A["cstep"], C["cstep"],
            A["cstep"] / C["cstep"], C["rss"], A["rss"]))

    row("no branch-point tests (ISP=0), finite-difference Jacobians (JAC=0)", 1, "auto_isp0_jac0",
        "cable_isp0_jac0_t1")
    row("no branch-point tests (ISP=0), analytic Jacobians (JAC=1)", 1, "auto_isp0_jac1", "cable_isp0_jac1_t1")
    row("no branch-point tests (ISP=0), analytic Jacobians (JAC=1)", 2, "auto_isp0_jac1_t2", "cable_isp0_jac1_t2")
    row("branch-point tests (AUTO ISP=2; cable ISP=2 NSV=2), JAC=1", 1, "auto_isp2_jac1", "cable_isp2_jac1_t1")
    row("branch-point tests (AUTO ISP=2; cable ISP=2 NSV=2), JAC=1", 2, "auto_isp2_jac1_t2", "cable_isp2_jac1_t2")
    print()
    print("Gain from the second thread (wall per step, 1 thread / 2 threads): AUTO %.2f and %.2f, cable %.2f"
          " and %.2f (ISP=0 and ISP=2)."
          % (r["auto_isp0_jac1"]["step"] / r["auto_isp0_jac1_t2"]["step"],
             r["auto_isp2_jac1"]["step"] / r["auto_isp2_jac1_t2"]["step"],
             r["cable_isp0_jac1_t1"]["step"] / r["cable_isp0_jac1_t2"]["step"],
             r["cable_isp2_jac1_t1"]["step"] / r["cable_isp2_jac1_t2"]["step"]))
    print()
    work_model(r)
    share1 = 1 - r["cable_isp0_jac1_t1"]["cstep"] / r["cable_isp2_jac1_t1"]["cstep"]
    print("The branch-point tests' share of cable's step (1 thread, CPU time): %.0f %% (ISP=2 NSV=2 against"
          " ISP=0; it includes the location of the double branch points the run passes); they cost %.0f %%"
          " of a plain step (issue 30's target: at most 25 %%)."
          % (100 * share1, 100 * (r["cable_isp2_jac1_t1"]["cstep"] / r["cable_isp0_jac1_t1"]["cstep"] - 1)))
    print()
    print("Targets of issue 17 (this table): <= 0.013 s/step without the tests, <= 0.034 s/step with them.")
    print("Measured (wall, best of the 1- and 2-thread columns): %.4f and %.4f s/step; CPU time of the"
          " one-thread runs: %.4f and %.4f s/step."
          % (min(r["cable_isp0_jac1_t1"]["step"], r["cable_isp0_jac1_t2"]["step"]),
             min(r["cable_isp2_jac1_t1"]["step"], r["cable_isp2_jac1_t2"]["step"]),
             r["cable_isp0_jac1_t1"]["cstep"], r["cable_isp2_jac1_t1"]["cstep"]))
    print("AUTO / cable by CPU time (one thread each): %.1f without the tests (JAC=1), %.1f with them."
          % (r["auto_isp0_jac1"]["cstep"] / r["cable_isp0_jac1_t1"]["cstep"],
             r["auto_isp2_jac1"]["cstep"] / r["cable_isp2_jac1_t1"]["cstep"]))
    print()
    ait_ps = ait / (NLONG - 1.0)
    cit_ps = cit / (NLONG - 1.0)
    print("Newton iterations per step (ISP=0, JAC=1, the %d steps): AUTO %.2f, cable %.2f; per iteration:"
          " AUTO %.4f s, cable %.4f s (1 thread each)."
          % (NLONG - 1, ait_ps, cit_ps, r["auto_isp0_jac1"]["step"] / max(ait_ps, 1e-9),
             r["cable_isp0_jac1_t1"]["step"] / max(cit_ps, 1e-9)))
    print()
    print("The same points: %d points in both b-files, T from %.4f to %.4f (AUTO) and %.4f to %.4f (cable);"
          % (n, ap[0][0], ap[n - 1][0], cp[0][0], cp[n - 1][0]))
    print("largest |T_AUTO - T_cable| = %.1e, largest relative difference in F = %.1e." % (dT, dF))
    print("1 and 2 threads: the b-files of the ISP=0 runs are %s, their s-files %s; of the ISP=2 runs the"
          " points %s." % ("identical" if same12 else "DIFFERENT", "identical" if same12s else "DIFFERENT",
                           "agree exactly" if cpb1 == cpb2 else "DIFFER"))
    print()
    print("Load during these runs (1-minute average, min / median / max over the runs): %s; at the end: %s."
          % (load_range(B.loads), load_main))
    print()

    # ---- the same equation file through cable ---------------------------------
    if os.path.exists(os.path.join(ROOT, "auto_iface", "autoeq", "auto_compat")):
        tag = "c_autofile_%d" % NLONG
        shutil.copy(os.path.join(ROOT, "tests", "auto07p", "knot72auto.c"), B.work)
        with open(os.path.join(B.work, "c.knot72auto"), "w") as fh:
            fh.write("NDIM=21, IPS=4, ILP=0, ICP=[1, 2, 3, 14, 16, 18, 20]\n")
            fh.write("NBC=24, NINT=0, NPAR=36, IADS=1, ITMX=9, ITNW=5, NWTN=3, RL0=-34.0, RL1=34.0\n")
        args = [B.cable, "run", "c=knot72auto", "e=knot72auto", "s=" + B.start_file(150), "IRS=1", "NMX=%d" % NLONG,
                "ISP=0", "NSV=0", "JAC=1", "NTHREADS=1", "sv=" + tag] + ["%s=%s" % (k, v) for k, v in SETTINGS.items()]
        w, c, rss, rc = timed(args, B.work)
        if rc != 0:
            print("cable could not run tests/auto07p/knot72auto.c (status %d)." % rc)
        else:
            fp, _ = B.cable_points(tag)
            n2, dT2, dF2 = agree(fp, cp)
            n3, dT3, dF3 = agree(fp, ap)
            print("The same equation file through cable (its AUTO-equation-file loader, `e=knot72auto`, ISP=0,"
                  " JAC=1, one thread, one run): %.1f s wall, %.2f s CPU for the %d points; against cable's"
                  " built-in braid_knot: largest |dT| = %.1e, largest relative |dF| = %.1e (%d points);"
                  " against AUTO-07p: %.1e and %.1e." % (w, c, NLONG, dT2, dF2, n2, dT3, dF3))
        print()

    # ---- cost against NTST ---------------------------------------------------
    print("## Cost against NTST (ISP=0, JAC=1, 1 thread; AUTO ISP=0, JAC=1)")
    print()
    print("The same settings with NTST changed (each program from the start file at that NTST); per step")
    print("= (NMX=%d run - NMX=2 run) / %d, medians of %d alternated runs; peak memory = the largest"
          % (NSWEEP, NSWEEP - 2, max(repeats, SWEEP_REPEATS)))
    print("resident set of the runs.")
    print()
    print("| NTST | AUTO s/step | cable s/step, 1 thread | cable s/step, 2 threads | AUTO / cable (1 thread) | CPU s/step AUTO | CPU s/step cable (1 thread) | AUTO / cable (CPU) | cable CPU per step and NTST (ms) | cable peak memory (MB) | AUTO peak memory (MB) |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    B.loads = []
    for ntst in NTSTS:
        cs = [("a", lambda nmx, nt=ntst: B.run_auto("ntst%d_%d" % (nt, nmx), nt, nmx, 0, 1)),
              ("c1", lambda nmx, nt=ntst: B.run_cable("c_ntst%d_t1_%d" % (nt, nmx), nt, nmx, 0, 1, 1)),
              ("c2", lambda nmx, nt=ntst: B.run_cable("c_ntst%d_t2_%d" % (nt, nmx), nt, nmx, 0, 1, 2))]
        rr = B.alternate(cs, NSWEEP, max(repeats, SWEEP_REPEATS))
        print("| %d | %.4f | %.4f | %.4f | %.1f | %.4f | %.4f | %.1f | %.3f | %.0f | %.0f |" % (
            ntst, rr["a"]["step"], rr["c1"]["step"], rr["c2"]["step"], rr["a"]["step"] / rr["c1"]["step"],
            rr["a"]["cstep"], rr["c1"]["cstep"], rr["a"]["cstep"] / rr["c1"]["cstep"],
            1000 * rr["c1"]["cstep"] / ntst, rr["c1"]["rss"], rr["a"]["rss"]))
        sys.stdout.flush()
    print()
    print("Load during these runs (1-minute average, min / median / max): %s." % load_range(B.loads))
    print()
    geometry_share(B)
    print("This section took %.0f s." % (time.time() - t_start))


if __name__ == "__main__":
    main()
