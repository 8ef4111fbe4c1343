# SPDX-License-Identifier: GPL-3.0-or-later
"""A new study without hidden knowledge (issue 26 item 6): `cable info` and
info(), AUTO's PAR={...} updates, the braid problems' recommended constants
as the defaults of a keywords-only run, the advice at a double branch point
of the plain braid_knot, strand 2, the contact curve and the contact pressure
as numpy arrays.

The (7,2) knot of runs/knot72 (c.knot72).  Exact facts the geometry checks
use: strand 2 is r1 + Delta d1 with |d1| = 1 (so |r2 - r1| = Delta to
round-off), the contact curve their midpoint; on a knot strand 1 ends where
strand 2 begins and strand 2 ends where strand 1 begins (the (p,2) closure,
doc/braid-boundary-conditions.md), to the Newton tolerance; sigma, strand 2's
arclength, runs from 0 to L2; and p1 = sigma' p2 (the force per unit length
of strand 1 and of strand 2, doc/braid-equations.md), checked with a
second-order difference of sigma on the 211 stored points (error about
h^2 sigma''', measured 6e-5), so 1e-3."""
import os
import subprocess

import numpy as np
import pytest

import cable

from conftest import BUILD, ROOT, copy_in

KNOT = dict(e='braid_knot', TORUS=7, HAND=1, PAR={'Delta': 0.0051364907419, 'Ltot': 1.98889, 'T': 0.0})


@pytest.fixture
def knot(work):
    copy_in(work, 'runs/knot72/c.knot72')
    return cable.Runner()


def test_info_lists_names_keys_and_recommended_constants(work, monkeypatch):
    monkeypatch.setenv('CABLE_CACHE_DIR', str(work / 'cache'))
    text = cable.Runner().info('braid_knot')
    for word in ('problem braid_knot', 'NDIM=21, NBC=24, NINT=0', '1 T', '5 Delta', '15 eps13', '16 F',
                 '18 x1', '21 sigma', 'TORUS', 'HAND', "'left' = -1", 'NTST=30, NCOL=7', 'DSMAX=20.0', 'NSV=2',
                 # the material a start takes unless PAR gives it: B = 1, C = B/(1 + nu), nu = 0.3
                 'B1 = 1, B2 = 1, C1 = 0.7692307692, C2 = 0.7692307692', "PAR={'Delta': ..., 'Ltot': ...}"):
        assert word in text, word
    # the command line says the same
    p = subprocess.run([os.path.join(BUILD, 'cable'), 'info', 'e=braid_knot'], capture_output=True, text=True,
                       cwd=str(work))
    assert p.returncode == 0 and p.stdout == text
    # a test problem: its names, no keys, no recommended constants
    assert '1 lambda' in cable.Runner().info('bratu') and 'none beyond' in cable.Runner().info('bratu')
    # an AUTO equation file in the run directory
    copy_in(work, 'tests/data/autoeq/stpnt3_f/gelf.f')
    assert 'an AUTO equation file (gelf.f)' in cable.Runner().info('gelf')
    with pytest.raises(cable.CableError, match="unknown problem 'nosuch'"):
        cable.Runner().info('nosuch')
    p = subprocess.run([os.path.join(BUILD, 'cable'), 'info', 'e=nosuch'], capture_output=True, text=True,
                       cwd=str(work))
    assert p.returncode != 0 and "unknown problem 'nosuch'" in p.stderr


def test_par_keyword_updates_only_its_entries(work):
    """c.par's PAR = {'lambda': 0.0, 5: 7.0}; the keyword PAR={'lambda': 0.1}
    changes lambda's start and keeps PAR(5) (before: PAR(5) was lost, 0)."""
    copy_in(work, 'runs/bratu/c.bratu')
    with open('c.bratu') as f:
        text = f.read()
    with open('c.par', 'w') as f:
        f.write(text + "\nPAR = {'lambda': 0.0, 5: 7.0}\n")
    r = cable.Runner().run(e='bratu', c='par', PAR={'lambda': 0.1}, NMX=2)
    start = r()[0]
    assert start['PAR(5)'] == 7.0
    assert start['lambda'] == pytest.approx(0.1, abs=1e-12)


def test_keywords_only_braid_run_takes_the_recommended_constants(knot):
    """A first run from keywords alone gets the scenes' settings (before:
    AUTO's defaults NTST=20, NCOL=4, DS=0.01, DSMAX=0.1: measured, the flat
    branch to RL1 = 34 took 2000 steps, 18.0 s of CPU, reached T = 10.6 and
    found no branch point; with them 29 points, the scene's four BPs)."""
    r = knot.run(NMX=2, **KNOT)
    c = r()[-1].c
    assert (c['NTST'], c['NCOL'], c['JAC'], c['NSV'], c['DSMAX'], c['DS']) == (30, 7, 1, 2, 20.0, 5.0)
    # keywords win over them
    c = cable.Runner().run(NMX=2, NTST=24, **KNOT)()[-1].c
    assert (c['NTST'], c['NCOL']) == (24, 7)
    # a constants file is the user's: no recommended constants under it
    c = cable.Runner().run(e='braid_knot', c='knot72', NMX=2, DSMAX=7.0)()[-1].c
    assert (c['NTST'], c['NCOL'], c['DSMAX']) == (30, 7, 7.0)
    # the same first steps as the scene's constants file
    a = cable.Runner().run(NMX=4, **KNOT)
    b = cable.Runner().run(e='braid_knot', c='knot72', NMX=4)
    assert np.allclose(a['T'], b['T'], rtol=0, atol=1e-12) and np.allclose(a['F'], b['F'], rtol=1e-12)


def test_switch_at_a_double_branch_point_says_what_to_do(knot, capfd):
    flat = knot.run(e='braid_knot', c='knot72', UZSTOP={'T': 15.0})
    bp = flat('BP1')
    assert bp.kind == 'double'
    capfd.readouterr()
    knot.run(bp, ISW=-1, NMX=2)
    out = capfd.readouterr().out
    assert 'note: label %d (T = ' % bp.LAB in out and 'is a double branch point: braid_knot cannot follow' in out
    assert "e='braid_knot_sym'" in out and 'eps13' in out and 'knot72.md' in out
    # in the symmetric formulation, where the branch point is simple, no such note
    knot.run(bp, e='braid_knot_sym', ICP=['T', 'L', 'L2', 'eps21', 'eps13', 'F'], ISW=-1, ISP=0, DS=0.05, NMX=2)
    assert 'is a double branch point' not in capfd.readouterr().out


def test_strand2_contact_curve_and_pressure_as_arrays(knot):
    r = knot.run(e='braid_knot', c='knot72', NMX=3)
    s = r()[-1]
    n = len(s['t'])
    r1, r2, c = s.strand1, s.strand2, s.contact
    assert r1.shape == r2.shape == c.shape == (n, 3)
    assert np.array_equal(r1[:, 0], s['x1']) and np.array_equal(r1[:, 2], s['z1'])
    assert np.max(np.abs(np.linalg.norm(r2 - r1, axis=1) - s['Delta'])) < 1e-14
    assert np.max(np.abs(c - (r1 + r2) / 2)) < 1e-15
    assert np.array_equal(s['x2'], r2[:, 0]) and np.array_equal(s['zc'], c[:, 2])
    # the knot's closure: strand 1 ends where strand 2 begins, and back
    assert np.max(np.abs(r2[0] - r1[-1])) < 1e-8 and np.max(np.abs(r1[0] - r2[-1])) < 1e-8
    sig = s.sigma
    assert abs(sig[0]) < 1e-12 and sig[-1] == pytest.approx(s['L2'], rel=1e-10)
    p1, p2 = s.pressure, s.pressure2
    assert p1.shape == p2.shape == (n,) and np.array_equal(s['p1'], p1)
    dsig = np.gradient(sig, s['t'] * s['L'])
    assert np.max(np.abs(p1 / p2 - dsig)) < 1e-3
    # the analysis's pressure range is taken over the same points
    a = knot.analyze(s)
    assert np.min(p1) == pytest.approx(a['pmin1'], rel=1e-9) and np.max(p1) == pytest.approx(a['pmax1'], rel=1e-9)
    # a solution that is not a braid has no strands
    copy_in(str(os.getcwd()), 'runs/bratu/c.bratu')
    b = cable.Runner().run(e='bratu', c='bratu', NMX=2)()[0]
    with pytest.raises(cable.CableError, match='not a braid solution'):
        b.strand2


CIRCLE_F90 = """! u' = 0 with u(0)**2 + PAR(1)**2 = 1: the solutions lie on the unit circle
SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
  INTEGER NDIM, ICP(*), IJAC
  DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,*), DFDP(NDIM,*)
  F(1) = 0.0D0
END SUBROUTINE FUNC
SUBROUTINE STPNT(NDIM,U,PAR,T)
  INTEGER NDIM
  DOUBLE PRECISION U(NDIM), PAR(*), T
  PAR(1) = 0.0D0
  U(1) = 1.0D0
END SUBROUTINE STPNT
SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
  INTEGER NDIM, ICP(*), NBC, IJAC
  DOUBLE PRECISION PAR(*), U0(NDIM), U1(NDIM), FB(NBC), DBC(NBC,*)
  FB(1) = U0(1)**2 + PAR(1)**2 - 1.0D0
END SUBROUTINE BCND
SUBROUTINE ICND
END SUBROUTINE ICND
SUBROUTINE FOPT
END SUBROUTINE FOPT
SUBROUTINE PVLS
END SUBROUTINE PVLS
"""


def test_closed_loop_ends_with_a_note(work, monkeypatch, capfd):
    """The unit circle from (lambda, u) = (0, 1): one turn, then the end
    reason and the start named (before: NMX = 300 points, about 5 turns)."""
    monkeypatch.setenv('CABLE_CACHE_DIR', str(work / 'cache'))
    with open('circle.f90', 'w') as f:
        f.write(CIRCLE_F90)
    with open('c.circle', 'w') as f:
        f.write("NDIM=1, IPS=4, NBC=1, NINT=0, ICP=[1], NTST=4, NCOL=2, ISP=0, ILP=0\n"
                "DS=0.1, DSMIN=1e-4, DSMAX=0.2, NMX=300\n")
    r = cable.Runner().run(e='circle', c='circle')
    lam = r['PAR(1)']
    assert 30 < len(lam) < 100
    note = r[0].branches[0].end_note
    # the end reason for programs is a field (the note is for people)
    assert r[0].branches[0].end_status == 'CABLE_END_LOOP'
    assert note and 'closed on itself' in note and 'returned to its start (its first point, PAR(1) = 0)' in note
    assert "end: the branch closed on itself (a closed loop): closed loop: the branch returned" in capfd.readouterr().out
