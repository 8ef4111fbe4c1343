# SPDX-License-Identifier: GPL-3.0-or-later
"""PVLS's Lk along a branch (issue 30, doc/geometry.md "Lk along a branch"): the
b-file's Lk column, filled at every step by the update from the previous point
(Fuller's integral plus the counted axis passages, equations/ribbon_track.c)
instead of a full writhe, against the full computation (analyze(), the Gauss
writhe) at every labelled point, and dmin (the tree search) against the
analysis's.  The branch: link62's mode branch from the simple BP at T = 29.81
on a coarse mesh (NTST 40, DSMAX 15, the path of test_link_branches.py),
labelled every third step for 200 steps; its axis passes through itself three
times each way (Lk -3 -> 3 -> -3 -> 3), so the update's integer part is
exercised at every passage.  The update agrees with the full Lk to about
RIBBON_TRACK_DRIFT = 1e-5 by construction (it restarts from a full computation
when it drifts farther from the integer), and the full Lk itself is within
1e-5 of its integer on this mesh (measured); a miscounted passage is off by 2.
CABLE_TEST_QUICK skips it (about 30 s of CPU)."""
import os
import shutil

import pytest

from conftest import ROOT, run_script

pytestmark = pytest.mark.skipif(bool(os.environ.get('CABLE_TEST_QUICK')),
                                reason='CABLE_TEST_QUICK: the link62 mode branch is skipped')

# |Lk(b-file) - Lk(full)|: the drift bound 1e-5 plus the full computations'
# own distances from the integer (1e-5 on this mesh), with margin
LK_TOL = 5e-5

SCRIPT = """
flat = run(e='braid_link', c='link62', NTST=40, DSMAX=5.0, ICP=['T', 'F', 'h', 'Ham', 'Phi'], UZSTOP={'T': 30.5},
           sv='flat')
bp = branch_point(flat, T=(29.0, 30.5), kind='simple')
m = run(bp, e='braid_link', c='link62mode', NTST=40, DSMAX=15.0, ICP=['T', 'F', 'h', 'Ham', 'Phi', 'Lk', 'dmin'],
        NPR=3, NMX=200, sv='mode')
for s in m():
    a = analyze(s)
    print('lab %d %.17g %.17g %.17g %.17g' % (s['LAB'], s['Lk'], a['Lk'], s['dmin'], a['dmin']))
"""


def test_lk_and_dmin_columns_against_the_full_computation(work):
    d = os.path.join(ROOT, 'runs', 'link62')
    for n in os.listdir(d):
        if n.startswith('c.'):
            shutil.copy(os.path.join(d, n), str(work))
    rc, out, err = run_script(work, SCRIPT)
    assert rc == 0, err
    rows = [[float(x) for x in line.split()[1:]] for line in out.splitlines() if line.startswith('lab ')]
    assert len(rows) >= 60, 'labelled points of the mode branch: %d' % len(rows)
    bad = ['LAB %d: Lk column %.10f, full %.10f' % (r[0], r[1], r[2]) for r in rows if not abs(r[1] - r[2]) <= LK_TOL]
    bad += ['LAB %d: dmin column %.12g, analysis %.12g' % (r[0], r[3], r[4]) for r in rows if r[3] != r[4]]
    assert not bad, bad
    # the branch passes through Lk = -3 and 3 (the passages are exercised)
    ints = sorted({round(r[2]) for r in rows})
    assert ints == [-3, 3], ints
    # the column is the update's, not a recomputation: it differs from the full value somewhere
    assert any(r[1] != r[2] for r in rows)
