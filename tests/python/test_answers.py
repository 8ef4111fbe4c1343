# SPDX-License-Identifier: GPL-3.0-or-later
"""Every answer is the one asked for (issue 25, item 2): the first row of a
branch is the point the engine continues from, IPS follows AUTO's default,
run('NAME', c='OTHER') reads only c.OTHER, keywords are constants keys.

The knot runs use the flat (7,2) knot of runs/knot72 (c.knot72, its first
branch point BP1 at T = 11.0761 after 10 steps)."""
import os
import re

import pytest

import cable

from conftest import copy_in


@pytest.fixture
def knot(work):
    copy_in(work, 'runs/knot72/c.knot72', 'runs/knot72/c.knot72sym')
    rn = cable.Runner()
    flat = rn.run(e='braid_knot', c='knot72', NMX=12, NTHREADS=1, sv='flat')
    return rn, flat


def _rows(name):
    """(T, L2-NORM) of every data row of b.NAME."""
    rows = []
    with open('b.%s' % name) as f:
        for line in f:
            w = line.split()
            if len(w) > 5 and w[0] != '0':
                rows.append((float(w[4]), float(w[5])))
    return rows


def test_carried_par_does_not_move_a_switch(knot):
    """c.knot72 has PAR={..., 'T': 0.0}; a switch from the flat branch's BP1
    with the flat run's constants (no c=) starts at BP1 (AUTO does not carry
    PAR from run to run).  Before: row 1 had T = 0 and row 2 T = 11.08."""
    rn, flat = knot
    bp = flat('BP1')
    rn.run(bp, ISW=-1, NMX=3, sv='sw')
    rows = _rows('sw')
    assert rows[0][0] == pytest.approx(bp['T'], rel=1e-9)
    assert abs(rows[1][0] - bp['T']) < 1.0   # the first step (DS 5) stays next to the BP


def test_par_on_a_switch_is_refused(knot):
    """The issue's case: PAR={'T': 5.0} on a switch at T = 11.0761 wrote T = 5
    in row 1 and 11.0761 in row 2; a switch happens at the stored branch point."""
    rn, flat = knot
    with pytest.raises(cable.CableError) as e:
        rn.run(flat('BP1'), e='braid_knot_sym', c='knot72sym', NMX=3, PAR={'T': 5.0}, sv='sw5')
    assert str(e.value).startswith('PAR: PAR sets PAR(1) = 5') and 'branch point' in str(e.value)
    assert not os.path.exists('b.sw5')


def test_par_on_a_restart_gives_a_solution_in_row_1(knot):
    """A restart (ISW=1) with Delta changed: row 1 is the stored solution
    corrected at the new Delta, so it solves the problem.  Checked
    independently: row 1 is labelled (NPR=1), and a restart from that label
    evaluates the residual of the stored data (the d-file note of an
    uncorrected restart).  Before, row 1 was the old Delta's solution with the
    new Delta written next to it: max |F| = 1.35 in that check (measured on
    the code before the fix)."""
    rn, flat = knot
    r = rn.run(flat('BP1'), ISW=1, NMX=2, NPR=1, PAR={'Delta': 0.0052}, sv='moved')
    first = r()[0]
    assert first['PT'] == 1 and first['Delta'] == 0.0052
    rn.run(first, ISW=1, NMX=1, sv='check')
    with open('d.check') as f:
        note = re.search(r'restart: stored solution taken without Newton, max \|F\| = (\S+)', f.read())
    assert note and float(note.group(1)) < 1e-8


def test_ips_missing_means_auto_default(work):
    """A constants file without IPS means IPS=1 in AUTO (algebraic
    equilibria), which cable does not solve: refused naming the file and key
    (before, cable assumed 4 and solved a boundary-value problem)."""
    with open('c.noips', 'w') as f:
        f.write("NDIM = 2, NBC = 2, ICP = ['lambda'], NMX = 3\n")
    rn = cable.Runner()
    with pytest.raises(cable.CableError) as e:
        rn.run(e='bratu', c='noips')
    assert 'c.noips' in str(e.value) and 'IPS' in str(e.value) and "AUTO's default" in str(e.value)
    r = rn.run(e='bratu', c='noips', IPS=4)   # the override says what the file does not
    assert len(r()) >= 1


def test_run_name_with_c_reads_only_c_other(work):
    """run('NAME', c='OTHER') is AUTO's e=NAME, c=OTHER: c.NAME is neither read
    nor checked (before: a broken c.NAME failed the run)."""
    copy_in(work, 'runs/bratu/c.bratu')
    with open('c.broken', 'w') as f:
        f.write('NTST = -5\n')
    rn = cable.Runner()
    r = rn.run('broken', e='bratu', c='bratu', NMX=3)
    assert len(r()) >= 1


@pytest.mark.parametrize('key', ['NMX=50, NPR', 'NMX ', '1NMX', 'N\u00e9X'])
def test_keywords_are_keys(work, key):
    """run(**{'NMX=50, NPR': 1}) was pasted into the override as two statements."""
    copy_in(work, 'runs/bratu/c.bratu')
    rn = cable.Runner()
    with pytest.raises(cable.CableError) as e:
        rn.run(e='bratu', c='bratu', **{key: 1})
    assert 'not a constants key' in str(e.value)


def test_non_utf8_names_are_refused(work):
    """Bytes that are not UTF-8 in parnames went into the b-file header,
    which AUTO's parser then cannot read."""
    copy_in(work, 'runs/bratu/c.bratu')
    with open('c.bratu', 'rb') as f:
        text = f.read()
    with open('c.latin', 'wb') as f:
        f.write(text + b"parnames = {1: 'lambda', 2: 'p\xe9'}\n")
    rn = cable.Runner()
    with pytest.raises(cable.CableError) as e:
        rn.run(e='bratu', c='latin')
    msg = str(e.value)
    assert 'c.latin' in msg and 'parnames' in msg and 'UTF-8' in msg


def test_fatal_user_routine_fails_the_run(work):
    """A FUNC returning -3 (fatal, doc/plugins.md) in an AUTO equation file:
    the branch ends, its points are saved, and `cable run` exits non-zero
    (before: exit status 0)."""
    import subprocess
    from conftest import BUILD
    copy_in(work, 'tests/data/autoeq/bratu_c/bratu.c', 'tests/data/autoeq/bratu_c/c.bratu')
    with open('bratu.c') as f:
        src = f.read()
    anchor = '  f[1] = -par[0] * exp(u[0]);\n'
    assert src.count(anchor) == 1
    with open('bratu.c', 'w') as f:
        f.write(src.replace(anchor, anchor + '  if (par[0] > 1.0) return -3;\n'))
    p = subprocess.run([os.path.join(BUILD, 'cable'), 'run', 'e=bratu', 'c=bratu', 'sv=x'], capture_output=True,
                       text=True, timeout=600)
    assert p.returncode != 0, p.stdout + p.stderr
    # the message names the routine, the equation file, the status and the files
    assert 'FUNC' in p.stderr and 'bratu.c' in p.stderr and 'returned -3' in p.stderr, p.stderr
    assert 'b.x, s.x, d.x' in p.stderr, p.stderr
    lams = [float(line.split()[4]) for line in open('b.x') if line.split()[0] != '0']
    assert len(lams) > 3 and max(lams) <= 1.0


def test_negative_measure_is_inside_the_default_bounds(work):
    """A0's default is unbounded below, as AUTO's: with IPLT=-2 (MIN U(2), u'
    of Bratu's problem, negative) the run goes on to NMX (before, A0 = 0
    ended it after the first step with 'RL0, RL1, A0, A1 reached')."""
    copy_in(work, 'runs/bratu/c.bratu')
    rn = cable.Runner()
    r = rn.run(e='bratu', c='bratu', IPLT=-2, NMX=10, NPR=0)
    sols = r()
    assert sols[-1]['PT'] == 10 and sols[-1]['TY'] == 'EP'
