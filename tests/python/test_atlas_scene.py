# SPDX-License-Identifier: GPL-3.0-or-later
"""Acceptance test of the atlas scene (runs/atlas/atlas.toml): its task for
the right-handed (7,2) knot at the paper's Delta, mode 1, with the scene's
own mesh and branch constants, cut to the first 75 points of the branch
(NMX; the scene runs 300), as a one-task sweep on one local worker.  The
rows must show what the paper's Fig. 12.3 shows, derived from the branch:
the flat knot's Lk = 7/2 before the axis passes through itself, then one
self-passage (the figure-eight), an unknotted axis with Lk = Tw + Wr = 5.5
and the paper's 'linking number' 5.5, and tubes free of overlap over a
stretch of T that holds the paper's point (a), T = -2.10752.

CABLE_TEST_QUICK skips it (a minute of continuation)."""
import os
import re

import pytest

from cable import atlas

from conftest import ROOT

# distributed 2022.12 on tornado 6.2 (Debian): its in-process LocalCluster warns of a deprecated tornado call
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")

PAPER_T_A = -2.10752
# Lk of a closed knot ribbon is a half-odd integer; a wrong topology is off by 1
LK_TOL = 0.01


def one_task_sweep(text):
    """The scene's file with one family, one p, the paper's Delta, mode 1 and
    NMX = 75 (each replaced line must be there)."""
    subs = [(r'(?m)^deltas = .*$', 'deltas = [0.0051364907419]'),
            (r'(?m)^modes = .*$', 'modes = [1]'),
            (r'(?m)^p = \[3, 5, 7.*$', 'p = [7]'),
            (r'(?ms)^\[\[family\]\]\nkind = "link"\np = \[[^\]]*\]\n', ''),
            (r'(?ms)(\[branch\].*?)^NMX = \d+$', r'\1NMX = 75'),
            (r'(?m)^output = .*$', 'output = "one"')]
    for pat, new in subs:
        text, n = re.subn(pat, new, text, count=1)
        assert n == 1, pat
    return text


@pytest.mark.skipif(bool(os.environ.get('CABLE_TEST_QUICK')), reason='CABLE_TEST_QUICK')
def test_atlas_scene_knot72_mode1(work):
    with open(os.path.join(ROOT, 'runs/atlas/atlas.toml')) as f:
        text = one_task_sweep(f.read())
    path = os.path.join(str(work), 'one.toml')
    with open(path, 'w') as f:
        f.write(text)
    sweep = atlas.load(path)
    assert len(sweep.tasks) == 1
    t = sweep.tasks[0]
    assert (t.inputs['kind'], t.inputs['p'], t.inputs['mode'], t.inputs['arm']) == ('knot', 7, 1, 1)
    counts = atlas.run(sweep, workers=1)
    assert {k: counts[k] for k in ('total', 'skipped', 'computed', 'failed')} == \
        {'total': 1, 'skipped': 0, 'computed': 1, 'failed': 0}
    rows = atlas.read_csv(os.path.join(sweep.output, 'atlas.csv'))
    assert [int(r['segment']) for r in rows] == list(range(len(rows)))
    s0, s1 = rows[0], rows[1]
    assert s0['status'] == 'ok' and int(s0['bp_multiplicity']) == 2 and s0['formulation'] == 'braid_knot_sym'
    assert float(s0['bp_T']) > 0
    assert s0['companion'] == 'unknot' and abs(float(s0['Lk']) - 3.5) < LK_TOL
    # (a): one self-passage, the unknotted axis, Lk = Lk_tube = 5.5, free of overlap
    assert abs(float(s1['passages']) - 1) < LK_TOL
    assert s1['companion'] == 'unknot' and int(s1['crossings']) == 0
    assert abs(float(s1['Lk']) - 5.5) < LK_TOL and abs(float(s1['Lk_tube']) - 5.5) < LK_TOL
    assert int(s1['overlap_free']) == 1 and float(s1['dmin']) > 1
    assert float(s1['T_free_end']) <= PAPER_T_A <= float(s1['T_free'])
    assert float(s1['pmin']) >= 0   # the paper: non-negative contact pressure
