#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""CPU cost per step of two cable builds (and AUTO-07p) side by side: a partial
measurement for one change, not `make bench`.

Usage: /usr/bin/python3 scripts/bench_before_after.py BEFORE_CABLE AFTER_CABLE BUILD_DIR [REPEATS] [--no-auto]
                                                      [--threads=N]

BEFORE_CABLE, AFTER_CABLE: the `cable` programs of two builds (e.g. of the
commits before and after a change); BUILD_DIR: the build whose bench work
directory holds the start file and AUTO's program (scripts/bench_compare.py's
setup, reused).  The flat (7,2) branch at the issue's settings (NTST 150, NCOL 4,
IAD 3, EPSL = EPSU = 1e-7, EPSS = 1e-5, DS = -5, DSMAX = 5; JAC=1; cable with
NTHREADS=N, default 1),
without branch-point tests (ISP=0 NSV=0; AUTO ISP=0) and with them (ISP=2 NSV=2;
AUTO ISP=2).  Per step = (CPU time of the NMX=60 run - that of the NMX=2 run) /
58, CPU = user + system time of the process (and the same from wall times,
the measure of what the threads gain), medians of REPEATS (default 3) runs; the programs and cases alternate inside every repeat.  Also checks that
the two cable builds give the same points (largest differences in T and F).
Output: a markdown table on stdout."""

import os
import statistics
import sys

sys.dont_write_bytecode = True  # no __pycache__ in scripts/
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_compare as bc  # noqa: E402


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    with_auto = "--no-auto" not in sys.argv
    threads = 1
    for a in sys.argv[1:]:
        if a.startswith("--threads="):
            threads = int(a.split("=", 1)[1])
            if threads < 1:
                raise SystemExit("bench_before_after.py: --threads must be at least 1, got %d" % threads)
        elif a.startswith("--") and a != "--no-auto":
            raise SystemExit("bench_before_after.py: unknown option %s" % a)
    before, after, build = (os.path.abspath(a) for a in args[:3])
    repeats = int(args[3]) if len(args) > 3 else 3
    B = bc.Bench(build, repeats)
    if with_auto:
        B.build_auto()
    progs = {"before": before, "after": after}

    def cable_case(prog, isp):
        def fn(nmx):
            B.cable = progs[prog]
            return B.run_cable("ba_%s_isp%d_%d" % (prog, isp, nmx), 150, nmx, isp, 1, threads)
        return fn

    def auto_case(isp):
        return lambda nmx: B.run_auto("ba_isp%d_%d" % (isp, nmx), 150, nmx, isp, 1)

    B.cable = after
    B.start_file(150)
    cases = []
    for isp in (0, 2):
        if with_auto:
            cases.append(("auto_isp%d" % isp, auto_case(isp)))
        cases.append(("before_isp%d" % isp, cable_case("before", isp)))
        cases.append(("after_isp%d" % isp, cable_case("after", isp)))
    load0 = bc.load()
    r = B.alternate(cases)
    load1 = bc.load()
    loads = [float(x.split()[0]) for x in B.loads]

    print("Load (1-minute average) during the runs, min / median / max: %.2f / %.2f / %.2f (start %s, end %s)."
          % (min(loads), statistics.median(loads), max(loads), load0, load1))
    print()
    print("cable with NTHREADS=%d; AUTO-07p with one thread." % threads)
    print()
    print("| case | before CPU s/step | after CPU s/step | before / after | before wall s/step | after wall s/step |"
          " before / after (wall) | AUTO-07p CPU s/step | AUTO / after (CPU) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for isp, name in ((0, "no branch-point tests (ISP=0 NSV=0; AUTO ISP=0)"),
                      (2, "branch-point tests (ISP=2 NSV=2; AUTO ISP=2)")):
        b, a = r["before_isp%d" % isp]["cstep"], r["after_isp%d" % isp]["cstep"]
        bw, aw = r["before_isp%d" % isp]["step"], r["after_isp%d" % isp]["step"]
        au = r["auto_isp%d" % isp]["cstep"] if with_auto else None
        print("| %s | %.4f | %.4f | %.2f | %.4f | %.4f | %.2f | %s | %s |" % (
            name, b, a, b / a, bw, aw, bw / aw, "%.4f" % au if au else "not run", "%.2f" % (au / a) if au else "-"))
    print()
    for isp in (0, 2):
        pb, _ = B.cable_points("ba_before_isp%d_60" % isp)
        pa, _ = B.cable_points("ba_after_isp%d_60" % isp)
        n, dT, dF = bc.agree(pb, pa)
        print("ISP=%d: %d / %d points (before / after); over the common points largest |dT| = %.1e, largest"
              " relative dF = %.1e." % (isp, len(pb), len(pa), dT, dF))


if __name__ == "__main__":
    main()
