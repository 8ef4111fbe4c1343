# SPDX-License-Identifier: GPL-3.0-or-later
"""Acceptance tests of what the link scenes runs/link62, runs/link43 and
runs/link102 claim beyond their branch points (issue 16): both halves of the
scene's mode branch (DS > 0 and DS < 0 from the branch point that the scene's
own branch_point(...) line selects), followed with the scene's constants files
on a coarse mesh, without the costly Lk/dmin columns and with a larger DSMAX,
to a UZ label at the caption's T, checking there
  - the companion knot type of the braid axis (name and handedness),
  - Lk (an integer for a link; a passage of the axis changes it by 2),
  - F against the value at NTST 100 (the scene's mesh).
link62's halves never reach the caption's T (both turn at T = -8.25): the
test checks that they turn between T = -8.26 and -8.0 and labels them at the
T of the scene's reported point instead (-7.106486484, doc/links.md 1.4),
where both halves cross it twice (STOP at the second UZ).

The tolerance on F is 5 times the coarse mesh's own error, measured on the
same path against NTST 100 (doc/links.md 1.5: 3e-5 to 2.7e-4 for link62
and link43 at NTST 40, up to 2.1e-2 for link102 at NTST 60).  The factor covers the
coarse mesh's dependence on the path: IAD = 3 places the mesh from the path's
history, so an engine change that moves the points of the path moves the
coarse F within its discretisation error.  Another branch or half differs by
far more: link43's halves differ by 2.03 in F at the caption's T, link62's two
crossings of its T by 114; the knot type and Lk change with a passage.
At these meshes and DSMAX every half takes the branch of the scene's NTST-100
path (the same folds and passages of the axis, compared label by label when
the meshes were chosen).  CABLE_TEST_QUICK skips them."""
import os
import shutil

import pytest

from conftest import ROOT, run_script

pytestmark = pytest.mark.skipif(bool(os.environ.get('CABLE_TEST_QUICK')),
                                reason='CABLE_TEST_QUICK: the link scene branches are skipped')

ICP = "ICP=['T', 'F', 'h', 'Ham', 'Phi']"
# Lk of a solution is an integer up to the evaluation's error: 2.3e-5 for
# link102 at NTST 100 (doc/links.md 1.4), at most 5e-6 on the coarse meshes
# here (measured); a passage of the axis changes Lk by 2
LK_TOL = 1e-3

# prints the branch's smallest T and the analysis of every UZ label of a half
REPORT = """
def report(name, m):
    print('tmin %s %.10f' % (name, min(m['T'])))
    for s in m('UZ'):
        a = analyze(s)
        print('uz %s %.10f %.12f %.10f %s %d' % (name, s['T'], s['F'], a['Lk'], a['knot'], a['hand']))
"""


def scene_selection(scene):
    """The scene's own branch_point(...) line, from runs/NAME/NAME.auto."""
    import re
    with open(os.path.join(ROOT, 'runs', scene, scene + '.auto')) as f:
        m = re.search(r"^bp = (branch_point\(flat, T=\([^)]*\), kind='\w+'\))$", f.read(), re.M)
    assert m, '%s: the scene selects its BP with branch_point(flat, T=(lo, hi), kind=...)' % scene
    return m.group(1)


def follow(work, scene, flat_run, mode_run):
    """The scene's flat branch (flat_run), the scene's branch point, both
    halves (mode_run % 'DS=...'); returns ({'f'|'b': [(T, F, Lk, knot, hand)]},
    {'f'|'b': smallest T}, problems)."""
    d = os.path.join(ROOT, 'runs', scene)
    for n in os.listdir(d):
        if n.startswith('c.'):
            shutil.copy(os.path.join(d, n), str(work))
    text = (REPORT + flat_run + "\n"
            "bp = " + scene_selection(scene) + "\n"
            "report('f', " + mode_run % 'DS=0.05' + ")\n"
            "report('b', " + mode_run % "DS='-'" + ")\n")
    rc, out, err = run_script(work, text)
    bad = [] if rc == 0 else ["%s: the scene's branch replays on the coarse mesh: %s" % (scene, err)]
    uz, tmin = {'f': [], 'b': []}, {}
    for line in out.splitlines():
        w = line.split()
        if len(w) == 7 and w[0] == 'uz':
            uz[w[1]].append((float(w[2]), float(w[3]), float(w[4]), w[5], int(w[6])))
        elif len(w) == 3 and w[0] == 'tmin':
            tmin[w[1]] = float(w[2])
    return uz, tmin, bad


def check_point(bad, what, pt, t, f100, ftol, knot, hand, lk):
    """One UZ label pt = (T, F, Lk, knot, hand) against the scene's claims."""
    if pt is None:
        bad.append('%s: a UZ label at T = %.8f' % (what, t))
        return
    tc, f, lkc, k, h = pt
    if not abs(tc - t) <= 1e-6:
        bad.append('%s: the UZ label is at T = %.8f, got %.10f' % (what, t, tc))
    if not abs(f - f100) <= ftol:
        bad.append('%s: F = %.10f (NTST 100) within %.1e, got %.10f' % (what, f100, ftol, f))
    if (k, h) != (knot, hand):
        bad.append('%s: the braid axis is a %s %s, got %s %s' % (what, 'right' if hand > 0 else 'left', knot,
                                                               'right' if h > 0 else 'left', k))
    if not abs(lkc - lk) <= LK_TOL:
        bad.append('%s: Lk = %d, got %.8f' % (what, lk, lkc))


def first(pts):
    return pts[0] if pts else None


def test_link62_branch(work):
    # the scene: flat run at DSMAX 1 (c.link62); DSMAX 5 finds the same simple
    # BP at 29.81 (test_link_scenes.py), the mode branch at DSMAX 15 instead of 2
    t_rep, t_cap = -7.106486484, -11.46623
    uz, tmin, bad = follow(
        work, 'link62',
        "flat = run(e='braid_link', c='link62', NTST=40, DSMAX=5.0, %s, UZSTOP={'T': 30.5}, sv='flat')" % ICP,
        "run(bp, e='braid_link', c='link62mode', NTST=40, DSMAX=15.0, %s, %%s, UZR={'T': [%r, %r]}, "
        "STOP=['UZ2'], NPR=1000)" % (ICP, t_rep, t_cap))
    # NTST 100, the same path (DSMAX 5): F = 313.2745120201 (DS > 0) and
    # 313.2745121946 (DS < 0; doc/links.md 1.4: 313.2745120156 on the
    # scene's path); NTST 40 is 1.4e-4 and 2.7e-4 above (doc/links.md 1.5)
    for half, f100 in [('f', 313.2745120201), ('b', 313.2745121946)]:
        what = 'link62 %s half' % ('DS > 0' if half == 'f' else 'DS < 0')
        pts = uz[half]
        if any(abs(p[0] - t_cap) <= 1e-6 for p in pts):
            bad.append('%s: does not reach the caption T = %.5f' % (what, t_cap))
        if not -8.26 <= tmin.get(half, 0.0) <= -8.0:
            bad.append('%s: turns at T = -8.25 (its smallest T on the path, sampled every step), got %s'
                       % (what, tmin.get(half)))
        # the first crossing of t_rep: the overlap-free right trefoil, Lk 3
        check_point(bad, what, first(pts), t_rep, f100, 1.35e-3, 'trefoil', 1, 3)
        if len(pts) != 2:
            bad.append('%s: crosses T = %.5f twice (on the way to the fold and back), got %s' % (what, t_rep, pts))
    assert not bad, bad


def test_link43_branch(work):
    # the scene: mode branch at DSMAX 2 in braid_link_sym, here DSMAX 15
    t_cap = -14.4933
    uz, tmin, bad = follow(
        work, 'link43',
        "flat = run(e='braid_link', c='link43', NTST=40, %s, UZSTOP={'T': 25.0}, sv='flat')" % ICP,
        "run(bp, e='braid_link_sym', c='link43sym', NTST=40, DSMAX=15.0, "
        "ICP=['T', 'eps13', 'F', 'h', 'Ham', 'Phi'], %%s, NMX=1000, UZR={'T': %r}, UZSTOP={'T': %r}, NPR=1000)"
        % (t_cap, t_cap))
    # NTST 100: the scene's UZ label on its DS > 0 half, F = 630.4347132;
    # DS < 0 half 632.46714 (doc/links.md 4.3); NTST 40 is 1.7e-4 and 3e-5
    # above (doc/links.md 1.5)
    for half, f100 in [('f', 630.4347132), ('b', 632.46714)]:
        what = 'link43 %s half' % ('DS > 0' if half == 'f' else 'DS < 0')
        check_point(bad, what, first(uz[half]), t_cap, f100, 8.5e-4, 'torus(4,3)', 1, 9)
    assert not bad, bad


def test_link102_branch(work):
    # the scene: mode branch at DSMAX 2, here DSMAX 20; NTST 60: at NTST 50
    # the location of the scene's BP at T = 35.75 fails (doc/links.md 1.5)
    t_cap = -14.63829
    uz, tmin, bad = follow(
        work, 'link102',
        "flat = run(e='braid_link', c='link102', NTST=60, %s, UZSTOP={'T': 36.5}, sv='flat')" % ICP,
        "run(bp, e='braid_link', c='link102mode', NTST=60, DSMAX=20.0, %s, %%s, UZR={'T': %r}, "
        "UZSTOP={'T': %r}, NPR=1000)" % (ICP, t_cap, t_cap))
    # NTST 100: the scene's UZ labels, 927.3203863 (DS > 0) and 927.3205449
    # (DS < 0); NTST 60 is up to 2.1e-2 above (doc/links.md 1.5)
    for half, f100 in [('f', 927.3203863), ('b', 927.3205449)]:
        what = 'link102 %s half' % ('DS > 0' if half == 'f' else 'DS < 0')
        check_point(bad, what, first(uz[half]), t_cap, f100, 0.105, 'torus(5,4)', 1, 15)
    assert not bad, bad
