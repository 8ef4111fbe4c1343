#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""F at the paper's points (a)-(d) of Fig. 12.2 on the branches `cable explore` computed,
against the knot72 scene's (its acceptance path's mode branches) and the paper's.

    bench_explore.py EXPLORE_DIR SCENE_DIR

The scene's F: of the UZ labels at the paper's T on its mode-k branch, the one whose F is
nearest the paper's (the rule of compare(), scenes.py).  The explored F: every stretch of
the right arm's k-th branch point's branches (every direction) between two consecutive
labelled solutions that brackets the paper's T is continued from its first label with the
branch's own constants (c.branch, its formulation) and UZR at the paper's T until that UZ
(STOP UZ1): of those, the F nearest the scene's.  Prints a markdown table."""
import functools
import json
import os
import sys

_print = print

import cable

PAPER_T = [-2.10752, -9.89105, -10.97932, -15.51471]
PAPER_F = [171.50131, 368.075, 634.5698, 942.989]
ICP = {'braid_knot': ['T', 'L', 'L2', 'eps21', 'F', 'h', 'Ham'],
       'braid_knot_sym': ['T', 'L', 'L2', 'eps21', 'eps13', 'F', 'h', 'Ham']}


def scene_F(scene, k):
    os.chdir(scene)
    r = cable.Runner()
    m = r.loadbd('mode%d' % k)
    uz = [s for s in m() if s.TY == 'UZ' and abs(s['T'] - PAPER_T[k - 1]) < 1e-6 * abs(PAPER_T[k - 1])]
    return min(uz, key=lambda s: abs(s['F'] - PAPER_F[k - 1]))['F'] if uz else float('nan')


def explore_F(edir, k, target):
    os.chdir(edir)
    with open('table.json') as f:
        branches = [b for b in json.load(f)['branches'] if b['arm'] == 'right' and b['bp'] == k]
    r = cable.Runner()
    found = []
    for b in branches:
        sols = r.loadbd(b['name'])()
        t = PAPER_T[k - 1]
        for i in range(len(sols) - 1):
            if (sols[i]['T'] - t) * (sols[i + 1]['T'] - t) > 0:
                continue
            u = r.run(sols[i], c='branch', e=b['formulation'], ICP=ICP[b['formulation']], ISW=1,
                      UZR={'T': t}, STOP=['UZ1'], NMX=40, ISP=0, ILP=0)
            uz = [s for s in u() if s.TY == 'UZ']
            if uz:
                found.append((uz[0]['F'], b['name'], b['formulation']))
    if not found:
        return float('nan'), '-', '-', 0
    best = min(found, key=lambda x: abs(x[0] - target))
    return best[0], best[1], best[2], len(found)


def main():
    edir, scene = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    # the runs' logs (the engine prints on file descriptor 1) go to EXPLORE_DIR/../F.log
    sys.stdout.flush()
    table = os.fdopen(os.dup(1), 'w')
    log = os.open(os.path.join(os.path.dirname(edir), 'F.log'), os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
    os.dup2(log, 1)
    os.close(log)
    print = functools.partial(_print, file=table, flush=True)
    print('| point | T | F paper | F scene | F explore | rel. diff explore-scene | branch (formulation, '
          'crossings) |')
    print('|---|---:|---:|---:|---:|---:|---|')
    for k in range(1, 5):
        fs = scene_F(scene, k)
        fe, name, form, n = explore_F(edir, k, fs if fs == fs else PAPER_F[k - 1])
        print('| (%s) | %.5f | %.7g | %.10f | %.10f | %.1e | %s (%s, %d) |'
              % ('abcd'[k - 1], PAPER_T[k - 1], PAPER_F[k - 1], fs, fe, abs(fe - fs) / abs(fs), name, form, n))


if __name__ == '__main__':
    main()
