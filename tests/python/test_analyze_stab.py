# SPDX-License-Identifier: GPL-3.0-or-later
"""analyze(sol, STAB=1) and `cable analyze s.NAME LAB STAB=1`: the Morse index
of a braid solution (doc/stability.md S7).  On the flat (7,2) knot below its
first branch point (T = 11.08) the index is 0, and at every labelled point it
agrees with the run's own STAB=1 verdict (the b-file's PT < 0 exactly at the
stable points); without STAB the dict has no index."""
import os
import subprocess

from conftest import BUILD, copy_in, run_script


def test_analyze_stab(work):
    copy_in(work, 'runs/knot72/c.knot72')
    text = ("r = run(e='braid_knot', c='knot72', NTST=20, NMX=4, DS=3, DSMAX=3, NPR=1, STAB=1, sv='k')\n"
            "for s in r():\n"
            "    a = analyze(s, STAB=1)\n"
            "    print('pt %d %d %d %.9g' % (s['LAB'], a['index'], a['nzero'], a['sigma'][0]))\n"
            "print('plain', 'index' in analyze(r()[0]))\n"
            "try:\n"
            "    analyze(r()[0], STAB=2)\n"
            "except Exception as e:\n"
            "    print('refused', e)\n")
    st, out, err = run_script(work, text)
    assert st == 0, err
    pts = [l.split()[1:] for l in out.splitlines() if l.startswith('pt ')]
    assert len(pts) >= 3, out
    assert all(p[1] == '0' and p[2] == '0' and float(p[3]) > 0 for p in pts), \
        'the flat (7,2) knot below T = 11 is stable: index 0, sigma_1 > 0'
    assert 'plain False' in out, 'without STAB no index'
    assert 'refused' in out and 'STAB' in out
    # the b-file's PT is negative at these (stable) points: the run's verdict agrees
    rows = [l.split() for l in open('b.k') if l.split() and l.split()[0] == '1' and len(l.split()) > 3]
    assert rows and all(int(r[1]) < 0 for r in rows), 'STAB=1 run: every point stable (PT < 0)'
    # the command line
    p = subprocess.run([os.path.join(BUILD, 'cable'), 'analyze', 's.k', '2', 'STAB=1'], capture_output=True,
                       text=True, cwd=str(work))
    assert p.returncode == 0, p.stderr
    assert 'stability: Morse index 0 (stable), zero eigenvalues 0' in p.stdout, p.stdout
    p = subprocess.run([os.path.join(BUILD, 'cable'), 'analyze', 's.k', '2', 'STAB=7'], capture_output=True,
                       text=True, cwd=str(work))
    assert p.returncode != 0 and 'STAB' in p.stderr
