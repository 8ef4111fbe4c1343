# SPDX-License-Identifier: GPL-3.0-or-later
"""Acceptance tests of the link scenes runs/link62, runs/link43, runs/link102
(ported from tests/test_link_scenes.c): the path to each scene's branch point,
replayed with the scene's constants files on a coarser mesh (NTST 50-60
instead of 100) and without the costly Lk/dmin columns, with each scene's own
selection (branch_point(flat, T=(lo, hi), kind=...), the line of
runs/NAME/NAME.auto, which is read from the scene file itself), checking what
the scene relies on:
  - the flat branch's branch points, each of the kind the scene's comments
    and doc/links.md give (sol['kind'], cable_solution.bp_kind), at T within
    1e-3 of the NTST-100 values (the coarser mesh moves them by up to 5e-5;
    the location is exact to EPSS * DS = 5e-7 of arclength, or to the bracket
    it reports when the corrector does not converge inside it: up to 1.4e-3
    of arclength at NTST 50, which moves T by less than 1e-3 on these
    branches);
  - exactly one BP in the scene's window of the scene's kind;
  - the switch there, and at link62's double BP at T = 23.57, treats the
    kernel as the detector found it (double: two-dimensional).
These are also the regression tests of the BP location fixes (cont_special.c):
  - link62 at DSMAX = 5: the simple BP at T = 29.81, 0.12 before a double
    one, was not located; the simple BP at 17.55 was missed by the location
    and found by the dip test;
  - link102: the simple BPs at T = 30.77 and 35.75 were not located;
  - the double BP at T = 23.57 was switched as simple;
  - link62 at DSMAX = 5: the double BP at T = 29.93, found in the step after
    the located simple BP at 29.81, was labelled a 'pair'.
The mode branches themselves (hundreds of steps each) are left to
make scenes; CABLE_TEST_QUICK skips the replays."""
import os
import re
import shutil

import pytest

from conftest import ROOT, run_script

pytestmark = pytest.mark.skipif(bool(os.environ.get('CABLE_TEST_QUICK')),
                                reason='CABLE_TEST_QUICK: the link scene paths are skipped')

ICP = "ICP=['T', 'F', 'h', 'Ham', 'Phi']"


def scene_selection(scene):
    """The scene's own branch_point(...) line, from runs/NAME/NAME.auto."""
    with open(os.path.join(ROOT, 'runs', scene, scene + '.auto')) as f:
        m = re.search(r"^bp = (branch_point\(flat, T=\([^)]*\), kind='\w+'\))$", f.read(), re.M)
    assert m, '%s: the scene selects its BP with branch_point(flat, T=(lo, hi), kind=...)' % scene
    return m.group(1)


def check_flat(work, scene, files, flat_run, after, want, pick_t):
    for n in files:
        shutil.copy(os.path.join(ROOT, 'runs', scene, n), str(work))
    text = (flat_run + "\n"
            "for b in flat('BP'):\n"
            "    print('bp %s %.10f' % (b['kind'], b['T']))\n"
            "bp = " + scene_selection(scene) + "\n"
            "print('pick %.10f' % bp['T'])\n" + after)
    rc, out, err = run_script(work, text)
    bad = []
    if rc:
        bad.append("%s: the path to the scene's branch point replays: %s" % (scene, err))
    got = [l.split()[1:] for l in out.splitlines() if l.startswith('bp ')]
    if len(got) != len(want):
        bad.append('%s: %d branch points on the flat branch, got %s' % (scene, len(want), got))
    for i, ((t, kind), g) in enumerate(zip(want, got), 1):
        if not abs(float(g[1]) - t) <= 1e-3:
            bad.append('%s: BP%d at T = %.2f, got %s' % (scene, i, t, g[1]))
        if g[0] != kind:
            bad.append("%s: BP%d is %s (got '%s')" % (scene, i, kind, g[0]))
    pick = [float(l.split()[1]) for l in out.splitlines() if l.startswith('pick ')]
    if len(pick) != 1:
        bad.append("%s: the scene's selection finds exactly one branch point (%s)" % (scene, err.strip()))
    elif not abs(pick[0] - pick_t) <= 1e-3:
        bad.append('%s: and it is the one at T = %.4f, got %.10f' % (scene, pick_t, pick[0]))
    return out, bad


def test_link62(work):
    # DSMAX = 5, the value that used to lose the simple BP at 29.81; doc/links.md
    # (NTST 100): 10.0783 double, 17.5496 simple, 23.5720 double, 29.8077
    # simple, 29.93 double; at DSMAX = 5 the last is found by the dip test
    # in the step right after the located simple one, whose sigma_1 (1.6e-11)
    # is the dip's neighbour: judged against it instead of the other
    # neighbour (1.4e-7), sigma_2 = 8.0e-13 did not vanish and the double BP
    # counted as a pair (cont_special.c, dip_minimise's ref)
    want = [(10.0783, 'double'), (17.5496, 'simple'), (23.5720, 'double'), (29.8077, 'simple'), (29.9320, 'double')]
    out, bad = check_flat(
        work, 'link62', ['c.link62', 'c.link62mode'],
        "flat = run(e='braid_link', c='link62', NTST=50, DSMAX=5.0, %s, UZSTOP={'T': 30.5}, sv='flat')" % ICP,
        "for b in flat('BP'):\n"
        "    if b['kind'] == 'double' and 23.0 < b['T'] < 24.0:\n"
        "        d = run(b, e='braid_link', c='link62mode', NTST=50, %s, NMX=2)\n"
        "m = run(bp, e='braid_link', c='link62mode', NTST=50, %s, NMX=2)\n" % (ICP, ICP),
        want, 29.8077)
    a = out.find('PT     1: switching at a double branch point')
    if a < 0:
        bad.append('link62: the double BP at T = 23.57 is switched as a double one')
    if a < 0 or out.find('PT     1: switching at a simple branch point', a + 1) < 0:
        bad.append("link62: the scene's simple BP at T = 29.81 is switched as a simple one")
    assert not bad, bad


def test_link43(work):
    # doc/links.md and issue 16 (NTST 100): 10.7748 double, 17.74 and 20.6796
    # simple (the split 3-fold mode), 24.2269 double
    want = [(10.7748, 'double'), (17.74, 'simple'), (20.6796, 'simple'), (24.2269, 'double')]
    out, bad = check_flat(
        work, 'link43', ['c.link43', 'c.link43sym'],
        "flat = run(e='braid_link', c='link43', NTST=50, %s, UZSTOP={'T': 25.0}, sv='flat')" % ICP,
        "m = run(bp, e='braid_link_sym', c='link43sym', NTST=50, ICP=['T', 'eps13', 'F', 'h', 'Ham', 'Phi'],"
        " NMX=2)\n", want, 24.2269)
    if 'PT     1: switching at a simple branch point' not in out:
        bad.append('link43: the double BP of braid_link is simple in braid_link_sym (the switch)')
    assert not bad, bad


def test_link102(work):
    # issue 16 and doc/links.md (NTST 100): 10.8232, 17.7119, 24.2749 double
    # (modes 1-3), 30.7654 and 35.7497 simple (the split 5-fold mode)
    want = [(10.8232, 'double'), (17.7119, 'double'), (24.2749, 'double'), (30.7654, 'simple'), (35.7497, 'simple')]
    out, bad = check_flat(
        work, 'link102', ['c.link102', 'c.link102mode'],
        "flat = run(e='braid_link', c='link102', NTST=60, %s, UZSTOP={'T': 36.5}, sv='flat')" % ICP,
        "m = run(bp, e='braid_link', c='link102mode', NTST=60, %s, NMX=2)\n" % ICP, want, 35.7497)
    if 'PT     1: switching at a simple branch point' not in out:
        bad.append("link102: the scene's BP is switched as a simple one")
    assert not bad, bad


@pytest.mark.parametrize('ntst', [40, 55])
def test_link102_coarse_meshes(work, ntst):
    # BP location's last resort (cont_special.c: sv1_vanished, end_of_bracket):
    # at NTST 55 the regula falsi ran out of ITMX = 9 iterations at the simple
    # BP near T = 35.75 with sigma_1 = 5.5e-12, 5.8e-12 at its bracket's ends
    # (6.2e-10 at the step's), at NTST 40 the same at T = 30.77 (1.1e-13 at
    # both ends, 4.1e-8 at the step's) and at 35.75 (7.2e-11 at the ends,
    # 8.3e-10 at the step's, sigma_2 = 7.5e-8): the run said "could not
    # locate the branch point within ITMX=9 iterations" and the BP was not
    # labelled (4 BPs instead of 5).  Every BP the determinant's sign change
    # brackets is labelled now; T within 1e-3 of the NTST-100 values as above
    # (measured: 35.75007 at NTST 40, 35.74964 at NTST 55, against 35.74969)
    want = [(10.8232, 'double'), (17.7119, 'double'), (24.2749, 'double'), (30.7654, 'simple'), (35.7497, 'simple')]
    out, bad = check_flat(
        work, 'link102', ['c.link102'],
        "flat = run(e='braid_link', c='link102', NTST=%d, %s, UZSTOP={'T': 36.5}, sv='flat')" % (ntst, ICP),
        "", want, 35.7497)
    assert 'could not locate' not in out, out
    assert not bad, bad


def test_link62_dsmax5_ntst100(work):
    # The scene's mesh at DSMAX = 5 (c.link62 uses 1): the simple BP at
    # T = 29.8077 is located, and the next step (to T = 30.2039) holds the
    # double BP at 29.93, which the pencil test predicts (two crossings at
    # 0.3135 of the step); the dip test of that step dropped it because
    # sigma_1 at its start, the located BP, is ~0 (3.3e-13) and the dip's
    # sigma_1 was not below it (cont_special.c, cont_dip_in_step).  T against
    # the scene's own flat branch (DSMAX = 1, b.flat of make scenes), within
    # 1e-5: the simple BP is located to 6.3e-5 (DSMAX 1) and 6.4e-5 (DSMAX 5)
    # of arclength, where T moves by 0.08 per unit of arclength (measured:
    # 29.8077368913 here against 29.8077337640; 29.9319598949 against
    # 29.9319596620; the others within 4e-7).
    want = [(10.0782602960, 'double'), (17.5496073270, 'simple'), (23.5720279370, 'double'),
            (29.8077337640, 'simple'), (29.9319596620, 'double')]
    out, bad = check_flat(
        work, 'link62', ['c.link62'],
        "flat = run(e='braid_link', c='link62', DSMAX=5.0, %s, UZSTOP={'T': 30.5}, sv='flat')" % ICP,
        "", want, 29.8077)
    got = [float(l.split()[2]) for l in out.splitlines() if l.startswith('bp ')]
    if len(got) == len(want):
        bad += ['BP%d at T = %.4f, got %.7f' % (i, t, g) for i, ((t, _), g) in enumerate(zip(want, got), 1)
                if not abs(g - t) <= 1e-5]
    assert not bad, bad
