# SPDX-License-Identifier: GPL-3.0-or-later
"""cable.explore (doc/explore.md): the (7,2) knot of Fig. 12.2 on a small
exploration (the first branch point of each arm), its files, its table
against analyze() of the same labelled solutions, its stretches against the
tube distance and the axis passages, the branch ends; the known branch
points of a session; `cable explore` on the command line."""
import json
import math
import os
import subprocess

import pytest

import cable
from cable import _cable, explorer as explore

from conftest import BUILD, PYTHON

DELTA, LTOT = 0.0051364907419, 1.98889
PAPER_T_A = -2.10752
# Lk of a closed knot ribbon is a half-odd integer: a wrong topology is off by 1
LK_TOL = 0.01


@pytest.fixture(scope='module')
def small(tmp_path_factory):
    """explore(7, 1, ..., modes=1): the flat branch to the first BP of each arm
    and every branch from those two BPs, at the scene's mesh (NTST 30, NCOL 7:
    the BPs are double there; at NTST 12, NCOL 4 they split into pairs)."""
    out = str(tmp_path_factory.mktemp('explore') / 'e72')
    return explore.explore(7, 1, DELTA, Ltot=LTOT, modes=1, out=out)


def test_files(small):
    d = small['dir']
    assert os.path.isdir(d) and not [n for n in os.listdir(os.path.dirname(d)) if '.partial-' in n]
    for f in ('c.flat', 'c.branch', 'b.flat', 's.flat', 'b.flat_left', 's.flat_left', 'diagram.png',
              'table.txt', 'table.json'):
        assert os.path.exists(os.path.join(d, f)), f
    for b in small['branches']:
        for t in 'bsd':
            assert os.path.exists(os.path.join(d, '%s.%s' % (t, b['name'])))
    for r in small['rows']:
        if r.get('picture'):
            assert os.path.getsize(os.path.join(d, r['picture'])) > 1000


def test_branch_points_and_branches(small):
    # modes=1: one branch point per arm, on its own side of T = 0
    assert [len(small['bps'][a]) for a in ('right', 'left')] == [1, 1]
    assert small['bps']['right'][0]['T'] > 0 > small['bps']['left'][0]['T']
    # the flat (7,2) knot's BPs are double (D7): the detector says so
    assert all(b.kind == 'double' for v in small['bps'].values() for b in v)
    # every direction of each BP is followed: as many branches as directions
    by_bp = {}
    for b in small['branches']:
        by_bp.setdefault((b['arm'], b['bp']), []).append(b)
    assert sorted(by_bp) == [('left', 1), ('right', 1)]
    for bs in by_bp.values():
        n = bs[0]['ndir']
        assert n >= 1 and [b['direction'] for b in bs] == list(range(1, n + 1))
    for b in small['branches']:
        assert b['end'] in ('fold', 'branch point', 'closed loop', 'limits') or \
            b['end'].startswith('known branch'), b['end']


def test_mode1_reaches_paper_point_a(small):
    """The right arm's first branch crosses to T < 0, past the paper's (a) at
    T = -2.10752, to its fold (doc/knot72.md: lowest labelled T -10.24 at
    NPR 5), where it stops; its axis passes through itself once on the way
    (Lk 3.5 -> 5.5)."""
    r1 = [b for b in small['branches'] if b['name'] == 'r1'][0]
    # at this fold the detector locates a branch point too (the S0 formulation's): the branch
    # stops at whichever comes first, at the fold's T (doc/explore.md)
    assert r1['end'] in ('fold', 'branch point')
    last = r1['result']()[-1]
    assert last.TY in ('LP', 'BP') and -11.0 < last['T'] < PAPER_T_A
    assert len(r1['passages']) == 1 and r1['passages'][0][2] in (1, -1)
    t_pass = r1['passages'][0][0]
    assert 0 < t_pass < r1['bp_sol']['T']
    rows = [r for r in small['rows'] if r['branch'] == 'r1']
    lks = [r['Lk'] for r in rows]
    assert abs(lks[0] - 3.5) < LK_TOL and abs(lks[-1] - 5.5) < LK_TOL
    # the paper's (a) lies in an overlap-free stretch after the passage
    assert any(min(r['T_from'], r['T_to']) <= PAPER_T_A <= max(r['T_from'], r['T_to']) and
               r['stretch_end'] != 'axis passage' and abs(r['Lk'] - 5.5) < LK_TOL for r in rows)


def test_table_against_analyze(small):
    """Every row's Lk, companion, pressure and dmin are analyze()'s and
    tube_dmin's at the labelled solution it names; the stretch's labels are
    overlap-free and its ends lie between labels."""
    byname = {b['name']: b for b in small['branches']}
    assert small['rows']
    for row in small['rows']:
        b = byname[row['branch']]
        sols = b['result']()
        br = b['result'].branches[0]
        i = [k for k, s in enumerate(sols) if s.LAB == row['LAB']]
        assert len(i) == 1
        i = i[0]
        a = _cable.analyze(br, i)
        assert row['Lk'] == a['Lk'] and row['pmin'] == a['pmin'] and row['crossings'] == a['crossings']
        assert row['companion'].endswith(a['knot'])
        assert row['pressure'] == ('+' if a['pmin'] > 0 else '-' if a['pmax1'] < 0 else '+-')
        assert row['dmin'] == _cable.tube_dmin(br, i) > 1.0
        assert row['T'] == sols[i]['T'] and row['F'] == sols[i]['F']
        assert min(row['T_lo'], row['T_hi']) <= row['T'] <= max(row['T_lo'], row['T_hi'])
    for b in small['branches']:
        for st in b['stretches']:
            assert all(b['dmin'][i] > 1.0 for i in st['idx'])
            assert st['idx'] == list(range(st['idx'][0], st['idx'][-1] + 1))
            after = st['idx'][-1] + 1
            if st['end'] == 'overlap':
                assert b['dmin'][after] <= 1.0
            if st['end'] == 'branch end':
                assert after == len(b['dmin'])
    # table.txt and table.json carry the same rows
    d = small['dir']
    with open(os.path.join(d, 'table.txt')) as f:
        lines = [l for l in f.read().splitlines() if not l.startswith('#')]
    assert lines[0].split('\t') == explore.TABLE_FIELDS and len(lines) == 1 + len(small['rows'])
    with open(os.path.join(d, 'table.json')) as f:
        js = json.load(f)
    assert len(js['rows']) == len(small['rows']) and len(js['branches']) == len(small['branches'])
    for jr, r in zip(js['rows'], small['rows']):
        assert jr['Lk'] == r['Lk'] and jr['branch'] == r['branch']


def test_known_branch_point_ends_a_branch(work):
    """A branch that reaches a BP computed before ends there, and explore's
    branch_end names the point (the session's known points)."""
    with open('c.f', 'w') as f:
        f.write("NDIM = 21, IPS = 4\nICP = ['T', 'L', 'L2', 'eps21', 'F', 'h', 'Ham']\nTORUS = 7, HAND = 1\n"
                "PAR = {'Delta': %r, 'Ltot': %r, 'T': 0.0}\nNTST = 30, NCOL = 7, IAD = 3, JAC = 1\n"
                "ISP = 2, ILP = 0, NSV = 2\nDS = 5.0, DSMIN = 1e-6, DSMAX = 20.0, NMX = 40\n"
                "RL0 = -34.0, RL1 = 14.0\n" % (DELTA, LTOT))
    r = cable.Runner()
    first = r.run(e='braid_knot', c='f')
    bp = first('BP')
    assert len(bp) == 1 and explore.branch_end(first) == 'limits'
    assert r.known(first) == 1
    again = r.run(e='braid_knot', c='f')
    assert explore.branch_end(again) == 'known branch: BP label %d of branch %d' % (bp[0].LAB, bp[0].BR)
    assert abs(again()[-1]['T'] - bp[0]['T']) < 1e-7 * abs(bp[0]['T'])
    r.clear_known()
    assert explore.branch_end(r.run(e='braid_knot', c='f')) == 'limits'


def test_command_line(work):
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
    exe = os.path.join(BUILD, 'cable')
    p = subprocess.run([exe, 'explore'], capture_output=True, text=True, env=env)
    assert p.returncode == 2 and 'usage: cable explore' in p.stdout
    p = subprocess.run([exe, 'explore', 'TORUS=7', 'HAND=1'], capture_output=True, text=True, env=env)
    assert p.returncode == 2 and 'Delta= is needed' in p.stderr
    p = subprocess.run([exe, 'explore', 'TORUS=7', 'HAND=2', 'Delta=0.005', 'Ltot=2'], capture_output=True,
                       text=True, env=env)
    assert p.returncode == 1 and 'HAND=1 or -1' in p.stderr
    p = subprocess.run([exe, 'explore', 'TORUS=7', 'HAND=1', 'Delta=0.005'], capture_output=True, text=True,
                       env=env)
    assert p.returncode == 1 and 'Ltot=' in p.stderr
    assert not os.listdir(str(work))
