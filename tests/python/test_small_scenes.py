# SPDX-License-Identifier: GPL-3.0-or-later
"""Acceptance tests of the small scenes runs/bratu, runs/elastica and
runs/torus (ported from tests/test_scenes.c): each scene's own script is
replayed (`cable replay`) in a scratch directory with its constants files,
then a second script loads what it saved and prints what the scene claims,
which is checked against closed forms:
  bratu: the fold at lambda* = 3.513830719125162 (the root of the closed
    form's fold condition; tests/bench_testproblems.c);
  elastica: branch points of the straight rod at lambda = (k pi)^2,
    k = 1, 2, 3 (RL1 = 100), and the two directions of the buckled branch
    from the first one at the same lambda point by point (theta -> -theta);
  torus: the flat (p,2) torus knots and links it starts have
    Lk = Tw + Wr = hand * p/2 (torus.auto: half-integers for knots, integers
    for links, within 1e-6) and an unknotted braid axis.
A scene that changes what it computes fails here (make check)."""
import math
import os
import shutil

from conftest import ROOT, run_script

PI = math.pi


def replay_scene(work, scene, check_text):
    """The scene replayed in work, then check_text; returns check_text's stdout."""
    d = os.path.join(ROOT, 'runs', scene)
    for n in os.listdir(d):
        shutil.copy(os.path.join(d, n), str(work))
    with open(os.path.join(d, scene + '.auto')) as f:
        text = f.read()
    rc, out, err = run_script(work, text, scene + '.auto')
    assert rc == 0, '%s: the scene replays: %s' % (scene, err)
    rc, out, err = run_script(work, check_text, 'check.auto')
    assert rc == 0, '%s: its saved results load and analyse: %s' % (scene, err)
    return out


def lines(out, prefix):
    return [l[len(prefix):] for l in out.splitlines() if l.startswith(prefix)]


def test_bratu(work):
    out = replay_scene(work, 'bratu', "r = loadbd('bratu')\n"
                                      "print('folds %d' % len(r[0]('LP')))\n"
                                      "print('fold %.17g' % r('LP1')['lambda'])\n")
    assert lines(out, 'folds ') == ['1'], 'bratu: one fold on the lower branch'
    # NTST 20, NCOL 4: collocation error of order h^8 at the mesh points, far
    # below 1e-8; the location tolerance EPSS 1e-7 of a step <= 0.5
    lam = float(lines(out, 'fold ')[0])
    assert abs(lam - 3.513830719125162) <= 1e-7 * 3.513830719125162, 'bratu: the fold at lambda* (closed form)'


def test_elastica(work):
    out = replay_scene(work, 'elastica',
                       "r = loadbd('elastica')\n"
                       "for b in r[0]('BP'):\n"
                       "    print('bp %.17g' % b['lambda'])\n"
                       "print('kinds %s' % ' '.join(b.kind for b in r[0]('BP')))\n"
                       "up, down = r[1](), r[2]()\n"
                       "print('halves %d %d' % (len(up), len(down)))\n"
                       "d = max(abs(u['lambda'] - w['lambda']) for u, w in zip(up, down))\n"
                       "print('mirror %.17g %.17g' % (d, max(u['lambda'] for u in up)))\n")
    bps = [float(x) for x in lines(out, 'bp ')]
    assert len(bps) == 3, 'elastica: three branch points below RL1 = 100'
    for k, lam in enumerate(bps, 1):
        # NTST 50, NCOL 5 and EPSS 1e-10: both far below 1e-8
        assert abs(lam - (k * PI) ** 2) <= 1e-8 * (k * PI) ** 2, 'elastica: BP%d at (%d pi)^2' % (k, k)
    # read back from s.elastica: the kind comes from d.elastica (a BP with no
    # dip-test note was found by a sign change of the determinant: simple)
    assert lines(out, 'kinds ') == ['simple simple simple'], 'elastica: the BPs of the straight rod are simple'
    nu, nd = (int(x) for x in lines(out, 'halves ')[0].split())
    assert nu > 2 and nu == nd, 'elastica: both directions from BP1 have labelled points'
    d, m = (float(x) for x in lines(out, 'mirror ')[0].split())
    assert d <= 1e-9 * PI * PI, 'elastica: the two directions at the same lambda point by point (theta -> -theta)'
    assert m > PI * PI + 0.01, 'elastica: the buckled branch leaves BP1 to larger lambda'


TORUS = [('knot72_right', 3.5), ('knot72_left', -3.5), ('knot52_right', 2.5), ('knot312_right', 15.5),
         ('knot12_right', 0.5), ('link62_left', -3.0), ('link42_right', 2.0), ('link202_left', -10.0)]


def test_torus(work):
    text = ''.join("a = analyze(loadbd('%s')('EP1'))\n"
                   "print('lk %s %%.17g %%.17g %%.17g %%s' %% (a['Lk'], a['Tw'], a['Wr'], a['knot']))\n" % (n, n)
                   for n, _ in TORUS)
    out = replay_scene(work, 'torus', text)
    bad = []
    for name, want in TORUS:
        got = lines(out, 'lk %s ' % name)
        if not got:
            bad.append('%s: not analysed' % name)
            continue
        lk, tw, wr, knot = got[0].split()
        lk, tw, wr = float(lk), float(tw), float(wr)
        if not abs(lk - want) <= 1e-6:
            bad.append("%s: Lk = hand p/2 (torus.auto's 1e-6): %.17g" % (name, lk))
        if not abs(tw + wr - lk) <= 1e-9:
            bad.append('%s: Lk = Tw + Wr: %.17g + %.17g != %.17g' % (name, tw, wr, lk))
        if knot != 'unknot':
            bad.append("%s: the braid axis is unknotted (got '%s')" % (name, knot))
    assert not bad, bad
