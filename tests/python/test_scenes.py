# SPDX-License-Identifier: GPL-3.0-or-later
"""The scene functions of the package (cable.scenes and the analysis exposed
from C): analyze() and branch_table() on a short flat-knot branch, whose
answers are known without the code under test (unknotted axis, Lk = 3.5 of
the (7,2) torus-knot ribbon, no overlap, p > 0 throughout); compare() on two
cheap flat branches with a UZ label each at the same T; overlap_free();
branch points chosen by what they are; the error paths, which write no
file."""
import math
import os

import pytest

import cable
from cable import scenes

from conftest import copy_in

FLAT = dict(e='braid_knot', IPS=4, TORUS=7, HAND=1, PAR={'Delta': 0.0051364907419, 'Ltot': 1.98889, 'T': 0},
            ICP=['T', 'L', 'L2', 'eps21', 'F'], NTST=40, NCOL=4, DS=1, DSMAX=1, NMX=6, NPR=2, ISP=0, ILP=0)


@pytest.fixture(scope='module')
def flat(tmp_path_factory):
    d = tmp_path_factory.mktemp('flat')
    here = os.getcwd()
    os.chdir(d)
    try:
        r = cable.Runner()
        yield r, r.run(**FLAT), d
    finally:
        os.chdir(here)


def test_analyze_and_branch_table(flat, monkeypatch):
    runner, r, d = flat
    monkeypatch.chdir(d)
    lab = runner.branch_table('t_compare.txt', r, paper={'knot': 'unknot', 'Lk': 3.5, 'psign': False,
                                                          'linked': True}, title='flat knot')
    # the branch is one overlap-free unknot stretch: the reported point is its first label
    assert lab == r('EP1')['LAB']
    a = runner.analyze(r(lab))
    assert a['psign'] == 0 and a['psign_s1'] == [] and a['overlap'] == [] and a['closure2'] == 0
    # Lk_defect: the ribbon quadrature on a converged NTST 40 knot (1e-6 as in test_braid_solutions)
    assert a['axis_kappa_max'] > 0 and a['pmin1'] > 0 and a['Lk_defect'] < 1e-6
    assert abs(a['Lk'] - 3.5) < 1e-6 and a['knot'] == 'unknot' and a['dmin'] > 1
    t = open('t_compare.txt').read()
    assert 'final knot type of the braid axis (decided from the branch): unknot' in t
    assert 'T = T1(0) = -T2(0)' in t
    assert 'unknot           yes' in t and '3.5              yes' in t and 'no               yes' in t
    # the strands form a (7,2) torus knot around the unknotted axis: Lk_tube = 3.5, linked
    assert 'yes (Lk_tube = 3.5)' in t
    runner.branch_table('t2_compare.txt', r, paper={'knot': 'right trefoil', 'Lk': 4.5})
    t2 = open('t2_compare.txt').read()
    assert 'right trefoil    NO' in t2 and '4.5              NO' in t2


def test_scene_errors_write_nothing(flat, monkeypatch):
    runner, r, d = flat
    monkeypatch.chdir(d)
    ns = runner.namespace()
    with pytest.raises(cable.CableError) as e:
        ns['branch_table']('t3_compare.txt', r, paper={'Knot': 'unknot'})
    assert str(e.value).startswith('branch_table: Knot: paper: keys are')
    with pytest.raises(cable.CableError):
        ns['branch_table']('t3_compare.txt', r('EP1'))
    assert not os.path.exists('t3_compare.txt')
    with pytest.raises(cable.CableError) as e:
        ns['render'](r('EP1'), 't.png', color='rainbow')
    assert str(e.value) == "render: color: color='pressure' is the only colour map"
    assert not os.path.exists('t.png')


def test_overlap_free_and_branch_points(flat, monkeypatch):
    runner, r, d = flat
    monkeypatch.chdir(d)
    iv = runner.overlap_free(r)
    ts = [s['T'] for s in r()]
    # free all along: one stretch from the first label to the last, ending with the branch
    assert len(iv) == 1 and iv[0][0] == ts[0] and iv[0][1] == ts[-1] and iv[0][4] == 1 and iv[0][5] == 0
    assert scenes.branch_points(r) == []


def test_branch_points_by_kind(work):
    """The flat (7,2) knot's branch points are double (D7 symmetry, located by
    the singular-value test, doc/knot72.md): selected by kind and T window."""
    copy_in(work, 'runs/knot72/c.knot72')
    r = cable.Runner().run(e='braid_knot', c='knot72', NTST=20, NCOL=4, NMX=20, sv='flat')
    bps = r('BP')
    assert len(bps) >= 2
    assert all(scenes.bp_kind(b) == 'double' for b in bps)
    # the engine's notes reach the d-file too
    assert open('d.flat').read().count('NOTE: double branch point') >= len(bps)
    assert scenes.branch_points(r, kind='double') == bps and scenes.branch_points(r, kind='simple') == []
    t1 = bps[1]['T']
    assert [b['LAB'] for b in scenes.branch_points(r, T=(t1 - 1e-9, t1 + 1e-9))] == [bps[1]['LAB']]
    assert r('BP1') == bps[0] and r('BP2') == bps[1] and r(bps[1]['LAB']) == bps[1]
    # read back from the files: the kinds and notes come from d.flat (the
    # s-file, AUTO's format, has no place for them), so a script that
    # restarts from saved files selects the same BPs (a new runner given the
    # constants and so the parameter names first, as AUTO's ld(e=, c=))
    rn = cable.Runner()
    assert rn.load(e='braid_knot', c='knot72') is None
    back = rn.loadbd('flat')
    assert [(b['LAB'], b.kind, b.note) for b in back('BP')] == [(b['LAB'], 'double', b.note) for b in bps]
    assert scenes.branch_point(back, T=(t1 - 1e-9, t1 + 1e-9), kind='double')['LAB'] == bps[1]['LAB']
    # re-saved, the notes go with them
    rn.save(back, 'again')
    assert [b.kind for b in rn.loadbd('again')('BP')] == ['double'] * len(bps)
    # without the d-file the kind is unknown: ''
    os.remove('d.flat')
    assert [b.kind for b in rn.loadbd('flat')('BP')] == [''] * len(bps)


SMALL = """r = run(e='braid_knot', c='knot72', NTST=20, NCOL=4, ISP=0, NMX=30, UZSTOP={'T': 4.0})
r = r + run(e='braid_knot', c='knot72', NTST=20, NCOL=4, ISP=0, NMX=30, UZSTOP={'T': 4.0},
            PAR={'Delta': 0.006, 'Ltot': 1.98889, 'T': 0.0})
u = r('UZ')
"""


def test_compare_small(work):
    """Two flat branches (Delta 0.0051 and 0.006, so different F) with a UZ
    label each at T = 4: compare takes the crossing whose F is nearest the
    target, and refuses rows it cannot match without leaving a table file."""
    copy_in(work, 'runs/knot72/c.knot72')
    runner = cable.Runner()
    ns = runner.namespace()
    exec(SMALL, ns)
    r, u = ns['r'], ns['u']
    assert len(u) == 2
    f0, f1 = u[0]['F'], u[1]['F']
    assert abs(f0 - f1) > 0.1   # the picks below are told apart by F
    rows = runner.compare('small.txt', [['one', r, 4.0, f0 - 0.01, 3.5], ['two', r, 4.0, f1 + 0.01, 3.5],
                                        ['sol', u[1], 4.0, 100.0, 3.5]])
    want = [('one', u[0]['LAB'], 2, 1), ('two', u[1]['LAB'], 2, 2), ('sol', u[1]['LAB'], 1, 1)]
    for d, (name, lab, nuz, k) in zip(rows, want):
        assert (d['name'], d['LAB'], d['uz_at_T'], d['uz_chosen']) == (name, lab, nuz, k)
        assert d['rel'] == pytest.approx(abs(d['F'] - d['F_paper']) / d['F_paper'], rel=1e-15)
    assert os.path.exists('small.txt')
    bad = [("['x', r, 7.0, 100.0, 3.5]", 'no UZ label at T = 7'),
           ("['x', u[0], 5.0, 100.0, 3.5]", 'not the target T'),
           ("['x', r, 4.0, 100.0]", 'must be [name, result or solution, T_target'),
           ("['x', 3, 4.0, 100.0, 3.5]", 'must be a result or a solution')]
    for row, want_msg in bad:
        with pytest.raises(cable.CableError) as e:
            eval("compare('bad.txt', [['ok', r, 4.0, 100.0, 3.5], %s])" % row, ns)
        assert want_msg in str(e.value) and 'row 2' in str(e.value)
        assert not os.path.exists('bad.txt')


def test_render(flat, monkeypatch, capsys):
    """render(): a shaded picture of a braid solution (PNG of the asked size,
    square), with the tube meshes for ParaView (VTK PolyData) and Blender
    (ASCII PLY); bad arguments write nothing."""
    import struct
    runner, r, d = flat
    monkeypatch.chdir(d)
    ns = runner.namespace()
    sol = r('EP1')
    ns['render'](sol, 'k.png', view=[0, 0, 1], size=160, color='pressure', vtp='k.vtp', ply='k.ply')
    with open('k.png', 'rb') as f:
        head = f.read(24)
    assert head[:8] == b'\x89PNG\r\n\x1a\n' and struct.unpack('>II', head[16:24]) == (160, 160)
    assert open('k.vtp').read().count('<VTKFile type="PolyData"') == 1
    assert open('k.ply').read().startswith('ply\nformat ascii 1.0\n')
    assert 'label %d rendered to k.png' % sol['LAB'] in capsys.readouterr().out
    with pytest.raises(cable.CableError) as e:
        ns['render'](sol, 'v.png', view=[0, 1])
    assert str(e.value) == 'render: view: view=[x, y, z]'
    with pytest.raises(cable.CableError) as e:
        ns['render'](r, 'v.png')
    assert str(e.value) == "render: render(sol, 'fig.png', view=[x, y, z], ...)"
    assert not os.path.exists('v.png')
