# SPDX-License-Identifier: GPL-3.0-or-later
"""AUTO's CLI commands the other test files do not show: pr/printconstant/pc
(the runner's constants after ld and after runs with overrides, printed as
a constants file that reads back to the same constants, unknown keys), s.c,
AUTO's aliases, append's other forms, merge of files, clean, auto (another
script in the same runner and namespace), plot.

Bratu's problem (runs/bratu/c.bratu): the constants file is the reference
for every value checked here; NMX = 5 runs keep the tests short."""
import math
import os
import struct

import pytest

import cable

from conftest import copy_in, run_script, snapshot


@pytest.fixture
def bratu(work):
    copy_in(work, 'runs/bratu/c.bratu')
    return cable.Runner()


# the constants-file lines pr() prints after ld(e='bratu', c='bratu', NTST=33, DS='-'):
# c.bratu's values (NDIM, NBC, NINT, ICP, NTST ... RL1, EPS*), AUTO's
# defaults for the rest (doc/constants.md), the two keywords applied
PR_LINES = ["e = 'bratu'",
            'unames = {1: \'u\', 2: "u\'"}',
            "parnames = {1: 'lambda'}",
            'NDIM = 2, IPS = 4, IRS = 0, ILP = 1',
            "ICP = ['lambda']",
            'NTST = 33, NCOL = 4, IAD = 3, ISP = 2, ISW = 1, IPLT = 0, NBC = 2, NINT = 0',
            'NMX = 60, NPR = 10, IID = 2, ITMX = 9, ITNW = 5, NWTN = 3, JAC = 1',
            'EPSL = 1e-08, EPSU = 1e-08, EPSS = 1e-07',
            'DS = -0.1, DSMIN = 1e-05, DSMAX = 0.5, IADS = 1',
            'NPAR = 36, LAB = 0, THL = {}, THU = {}',   # LAB: AUTO's parseC prints it there too
            'IIS = 3',
            'UZR = {}',
            'UZSTOP = {}',
            'STOP = []',
            'RL0 = -0.01, RL1 = 5.0, A0 = -1e+300, A1 = 1e+300',
            "LINSOLVER = 'condense', NSV = 0, NTHREADS = 0, BPDIR = 0, PREDICTOR = 1"]


def test_pr_after_load(bratu, capsys):
    ns = bratu.namespace()
    assert ns['pr'] is ns['printconstant'] is ns['pc']
    # before anything: AUTO's defaults
    assert ns['pr']('NTST') == 20 and ns['pr']('DS') == 0.01 and ns['pr']('ICP') == []
    assert ns['pr']('NDIM') is None   # not set: the problem's
    # ld(e=, c=) from STPNT: no solution, the runner's constants set
    assert ns['ld'](e='bratu', c='bratu', NTST=33, DS='-') is None
    assert ns['pc']('NTST') == 33 and ns['printconstant']('DS') == -0.1 and ns['pr']('NMX') == 60
    assert ns['pr']('ICP') == ['lambda'] and ns['pr']('e') == 'bratu' and ns['pr']('IRS') == 0
    assert ns['pr']('parnames') == {1: 'lambda'} and ns['pr']('NINT') == 0 and ns['pr']('RL1') == 5.0
    capsys.readouterr()
    assert ns['pr']() is None
    assert capsys.readouterr().out.splitlines() == PR_LINES


def test_pr_after_runs(bratu):
    ns = bratu.namespace()
    pr = ns['pr']
    ns['ld'](e='bratu', c='bratu', NTST=33)
    r = ns['run'](NMX=5, UZR={'lambda': [0.5, 1]}, STOP=['UZ2'], THL={'lambda': 2})
    # the run's overrides are the runner's now; the load's NTST too
    assert pr('NMX') == 5 and pr('NTST') == 33 and pr('STOP') == ['UZ2']
    assert pr('UZR') == {'lambda': [0.5, 1.0]} and pr('THL') == {'lambda': 2.0}
    # what pr() shows is what the next run without a start uses: that run's constants
    before = dict(cable.Constants(bratu.session.constants()))
    r2 = ns['run']()
    assert dict(r2()[0].c) == before
    # a restart from a solution takes the solution's constants, then its keywords; IRS becomes
    # the solution's label, as AUTO's solution load sets it (IRS=1 given here does not count)
    ns['run'](r('UZ1'), NTST=40, NMX=3, IRS=1)
    assert pr('NTST') == 40 and pr('NMX') == 3 and pr('IRS') == r('UZ1')['LAB'] != 1
    assert pr('UZR') == {'lambda': [0.5, 1.0]}
    # s.c: the constants a solution was computed with (AUTO's s.c)
    assert r('UZ1').c['NTST'] == 33 and r('UZ1').c['NMX'] == 5 and r('UZ1').c['STOP'] == ['UZ2']


def test_restart_from_the_runners_solutions(bratu):
    """AUTO's runner keeps the solutions it last loaded or started from, and
    IRS: ld(s='x', IRS=3); run() restarts from label 3 of s.x, ld('NAME');
    run(IRS=4) from label 4 of s.NAME, and a run without a start repeats the
    last restart (auto-07p 0.9.2 on tests/data/autoeq/bratu_f90 does each of
    these).  The first row of a restart is its start, so its lambda is the
    label's; a start from STPNT is lambda = 0 (c.bratu)."""
    ns = bratu.namespace()
    r0 = ns['run'](e='bratu', c='bratu', NMX=30, UZR={'lambda': [1, 2, 3]}, sv='bratu')
    lam = {s['LAB']: s['lambda'] for s in r0()}
    assert [s['TY'] for s in r0()][:4] == ['EP', 'UZ', 'UZ', 'RG'] and lam[3] == pytest.approx(2.0, abs=1e-9)

    def first(**kw):
        return ns['run'](NMX=2, **kw)['lambda'][0]

    def near(lab):   # s.bratu holds lambda to the 11 digits of AUTO's format
        return pytest.approx(lam[lab], abs=1e-9)

    ns['ld'](s='bratu', IRS=3)
    assert ns['pr']('IRS') == 3
    assert first() == near(3)            # before: 0.0, the run started from STPNT
    assert first() == near(3)            # and again: the runner keeps s.bratu and IRS
    ns['ld']('bratu')
    assert first(IRS=4) == near(4) and abs(lam[4] - lam[3]) > 0.1
    assert first(s='bratu', IRS='UZ1') == near(2) and lam[2] == pytest.approx(1.0, abs=1e-9)
    assert first() == near(2) and ns['pr']('IRS') == 2
    assert first(IRS=0) == 0.0           # IRS=0: STPNT
    # a run from one solution: the next run without a start restarts from it too
    assert ns['run'](r0('UZ3'), NMX=2)['lambda'][0] == lam[5]
    assert first() == lam[5] and ns['pr']('IRS') == 5
    assert first(c='bratu') == 0.0       # c.bratu's IRS is 0
    # ld('NAME') without s.NAME forgets the runner's solutions (c.other names e='bratu')
    with open('c.other', 'w') as f:
        f.write("e = 'bratu'\nNDIM = 2\nICP = ['lambda']\n")
    assert ns['ld']('other') is None
    with pytest.raises(cable.CableError) as e:
        first(IRS=3)
    assert 'a restart needs solutions' in str(e.value)


def test_old_style_commands(work):
    """AUTO's older script style (AUTO-07p's demo nep): ld(...); run(); sv('NAME')
    saves the last run's output (AUTO: fort.7/8/9); sl('NAME') lists s.NAME's
    solutions, which answer to 'Type name' and 'Label' as AUTO's parseS ones do;
    ch('IRS', label) changes the runner's IRS, so run() restarts from that label
    of the runner's solutions (ld(c=..., s='NAME')); ap('NAME') appends the last
    run's output.  The elastica's BPs are at (n pi)^2 exactly."""
    copy_in(work, 'runs/elastica/c.elastica')
    ns = cable.Runner().namespace()
    ns['ld'](e='elastica', c='elastica', RL1=45)
    r1 = ns['run']()
    ns['sv']('el')                         # before: save() missing 1 required positional argument
    bps = [s for s in ns['sl']('el') if s['Type name'] == 'BP']
    assert [s['Label'] for s in bps] == [s['LAB'] for s in r1('BP')] and len(bps) == 2
    for s, n in zip(bps, (1, 2)):
        assert s['lambda'] == pytest.approx((n * math.pi) ** 2, rel=1e-8)
    ns['ld'](c='elastica', s='el', ISW=-1, DS=0.05, NMX=10, ISP=0)
    for s in ns['sl']('el'):
        if s['Type name'] == 'BP':
            ns['ch']('IRS', s['Label'])
            r = ns['run']()
            assert r['lambda'][0] == pytest.approx(s['lambda'], rel=1e-9)   # started at that BP
            assert max(r['L2-NORM']) > 0.1                                  # and left the straight rod
            ns['ap']('el')
    back = cable.Runner().loadbd('el')
    assert len(back) == 3 and len(back[0]()) == len(r1())
    # AUTO's NEWLAB, measured with auto-07p 0.9.2 on this script and
    # tests/data/autoeq/elastica_f: the runner's solutions are s.el as ld read
    # it (labels 1-4 on branch 1), so both switched runs are branch 2 and
    # their end points both label 5; read back, they are still two runs
    assert [(x['BR'], x['LAB'], x['TY']) for x in back()] == [
        (1, 1, 'EP'), (1, 2, 'BP'), (1, 3, 'BP'), (1, 4, 'EP'), (2, 5, 'EP'), (2, 5, 'EP')]
    # (AUTO's two end points: lambda = 10.0512 and 39.6706, after 10 steps from pi^2 and 4 pi^2)
    assert math.pi ** 2 < back[1]()[0]['PAR(1)'] < 4 * math.pi ** 2 < back[2]()[0]['PAR(1)']
    with pytest.raises(cable.CableError) as e:
        cable.Runner().namespace()['sv']('x')
    assert "no run yet" in str(e.value)


def test_pr_reads_back(bratu):
    """pr()'s text is a constants file: read back, it gives the same constants."""
    ns = bratu.namespace()
    ns['ld'](e='bratu', c='bratu')
    ns['run'](NMX=3, UZR={'lambda': 0.25}, UZSTOP={'lambda': 4.0}, PAR={'lambda': 0.0}, NTHREADS=1, DSMIN=2e-5)
    text = str(cable.Constants(bratu.session.constants()))
    assert "UZSTOP = {'lambda': 4.0}" in text and "PAR = {'lambda': 0.0}" in text
    with open('c.copy', 'w') as f:
        f.write(text)
    other = cable.Runner()
    other.namespace()['ld'](c='copy')
    assert dict(cable.Constants(other.session.constants())) == dict(cable.Constants(bratu.session.constants()))


def test_pr_errors(bratu, work):
    ns = bratu.namespace()
    with pytest.raises(cable.CableError) as e:
        ns['pr']('NTSX')
    assert str(e.value) == 'pr: NTSX: unknown key'
    with pytest.raises(cable.CableError) as e:
        ns['pc'](3)
    assert str(e.value) == "pr: pr('KEY') takes a constant's name, got a int"
    with pytest.raises(cable.CableError) as e:
        ns['run'](e='bratu', c='bratu', NMX=2)('EP1').c['NTSX']
    assert str(e.value) == 'NTSX: unknown key'
    rc, out, err = run_script(work, "ld(e='bratu', c='bratu')\nprint(pc('NTST'))\nx = pr('NTSX')\n")
    assert rc == 1 and out == '20\n'
    assert err == "cable: t.auto:3: pr: NTSX: unknown key\n    x = pr('NTSX')\n"
    # AUTO's shorthand: `pr` alone prints, `pc 'NMX'` is a call
    rc, out, err = run_script(work, "ld e='bratu', c='bratu', NMX=7\npr\nprint(pc('NMX'))\n")
    assert rc == 0, err
    assert 'NMX = 7, NPR = 10, IID = 2, ITMX = 9, ITNW = 5, NWTN = 3, JAC = 1' in out.splitlines()
    assert out.splitlines()[-1] == '7'


def test_aliases():
    """AUTO's short names are the same commands."""
    ns = cable.Runner().namespace()
    aliases = {'run': ('r', 'rn'), 'load': ('ld',), 'save': ('sv',), 'loadbd': ('bd',), 'merge': ('mb',),
               'relabel': ('rl',), 'clean': ('cl',), 'delete': ('dl',), 'copy': ('cp',), 'append': ('ap',),
               'pr': ('printconstant', 'pc')}
    for name, short in aliases.items():
        for a in short:
            assert ns[a] is ns[name], (a, name)
    for name in ('cd', 'auto', 'wait', 'analyze', 'compare', 'plot', 'render'):
        assert callable(ns[name])
    for name in ('run', 'r', 'ld', 'pr', 'pc', 'printconstant', 'bd', 'sv', 'ap'):
        assert callable(getattr(cable, name))


def test_append_forms_merge_files_clean(bratu, capsys):
    ns = bratu.namespace()
    lower = ns['run'](e='bratu', c='bratu', NMX=5, sv='a')
    up = ns['run'](lower('EP1'), DS='-', NMX=3, sv='b')
    # append('A', 'B'): the files A appended to the files B
    ns['ap']('a', 'b')
    both = ns['bd']('b')
    assert [s['LAB'] for s in both()] == [s['LAB'] for s in up()] + [s['LAB'] for s in lower()]
    # append('A', x): the files A before x, as a result (nothing written)
    before = snapshot('.')
    joined = ns['ap']('a', up)
    assert isinstance(joined, cable.Result) and len(joined) == 2
    assert [s['LAB'] for s in joined()] == [s['LAB'] for s in lower()] + [s['LAB'] for s in up()]
    assert snapshot('.') == before
    # append('NAME') appends the last run's output (AUTO's fort.* files): up's branch after a's
    ns['ap']('a')
    assert [s['LAB'] for s in ns['bd']('a')()] == [s['LAB'] for s in lower()] + [s['LAB'] for s in up()]
    # merge('NAME'): the two directions from one start (STPNT, labelled in
    # both) joined in the files; the shared start keeps one label and the
    # labels are renumbered 1, 2, ... in the new order, as AUTO's merge does
    # (doc/scripts.md; test_auto_objects.py compares with auto-07p)
    down = ns['run'](e='bratu', c='bratu', DS='-', NMX=3)
    ns['sv'](lower + down, 'm')
    assert len(ns['bd']('m')) == 2
    ns['mb']('m')
    merged = ns['bd']('m')
    assert len(merged) == 1 and len(merged()) == len(lower()) + len(down()) - 1
    assert merged.getLabels() == list(range(1, len(merged()) + 1))
    # from lambda < 0 through the start (lambda = 0) to > 0
    assert merged('EP1')['lambda'] < 0 == merged('EP2')['lambda'] < merged('EP3')['lambda']
    # clean: nothing to delete; nothing changes
    before = snapshot('.')
    capsys.readouterr()
    ns['cl']()
    assert snapshot('.') == before
    assert 'nothing to delete' in capsys.readouterr().out


def test_auto_runs_another_script(work):
    """auto('other.auto') runs another script in the same runner and
    namespace (AUTO's auto command); an error in it names its file and line."""
    copy_in(work, 'runs/bratu/c.bratu')
    with open('other.auto', 'w') as f:
        f.write("y = x * 2\nld(e='bratu', c='bratu', NTST=21)\nprint 'other', y\n")
    rc, out, err = run_script(work, "x = 3\nauto('other.auto')\nprint('back', y, pr('NTST'))\n")
    assert rc == 0, err
    assert out.splitlines()[-2:] == ['other 6', 'back 6 21']
    with open('bad_other.auto', 'w') as f:
        f.write("z = 1\nr = run(e='bratu', c='bratu', NMXX=1)\n")
    rc, out, err = run_script(work, "auto('bad_other.auto')\n")
    assert rc == 1
    first = err.splitlines()[0]
    assert first.startswith('cable: ') and first.endswith("bad_other.auto:2: run: NMXX: unknown key (in 'NMXX=1')")
    rc, out, err = run_script(work, 'auto()\n')
    assert rc == 1 and err.splitlines()[0] == 'cable: t.auto:1: auto: auto needs a script name'


def png_size(path):
    """(width, height) from a PNG file's IHDR chunk."""
    with open(path, 'rb') as f:
        head = f.read(24)
    assert head[:8] == b'\x89PNG\r\n\x1a\n' and head[12:16] == b'IHDR', path
    return struct.unpack('>II', head[16:24])


def test_plot(bratu, capsys):
    """plot(): a bifurcation diagram of saved results, PNG or SVG; marks on
    the (T, F) axes only, never a half-written file."""
    ns = bratu.namespace()
    r = ns['run'](e='bratu', c='bratu', sv='lower')
    ns['plot']('lower.png', ['lower'], x='lambda', y='L2-NORM', title='Bratu')
    w, h = png_size('lower.png')
    assert w > 100 and h > 100
    ns['plot']('lower.svg', ['lower'], x='lambda', y='L2-NORM')
    assert open('lower.svg').read().lstrip().startswith(('<?xml', '<svg'))
    assert 'diagram written to lower.svg' in capsys.readouterr().out
    with pytest.raises(cable.CableError) as e:
        ns['plot']('m.png', ['lower'], marks=[[r('LP1'), 'fold']], x='lambda')
    assert str(e.value) == 'plot: marks: marks are drawn on the default (T, F) axes only'
    with pytest.raises(cable.CableError):
        ns['plot']('n.png', ['nosuch'], x='lambda', y='L2-NORM')
    assert not os.path.exists('m.png') and not os.path.exists('n.png')


def test_python_m_cable(work):
    """`python3 -m cable X.auto` runs a script as `cable replay X.auto` does:
    the same output, the same error line and exit status; no script is a
    usage error (status 2)."""
    import subprocess
    from conftest import BUILD, PYTHON
    copy_in(work, 'runs/bratu/c.bratu')
    text = ("r = run(e='bratu', c='bratu', NMX=5)\n"
            "print 'labels', [s['LAB'] for s in r()], len(r('BP')), pc('NMX')\n"
            "x = r('LP1')\n")
    with open('m.auto', 'w') as f:
        f.write(text)
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
    p = subprocess.run([PYTHON, '-m', 'cable', 'm.auto'], capture_output=True, text=True, env=env, timeout=600)
    rc, out, err = run_script(work, text, 'm.auto')
    assert p.returncode == rc == 1
    assert p.stderr == err == "cable: m.auto:3: LP1: no such label in the result\n    x = r('LP1')\n"
    assert [l for l in p.stdout.splitlines() if l.startswith('labels')] == ['labels [1, 2] 0 5']
    assert [l for l in out.splitlines() if l.startswith('labels')] == ['labels [1, 2] 0 5']
    p = subprocess.run([PYTHON, '-m', 'cable'], capture_output=True, text=True, env=env, timeout=60)
    assert p.returncode == 2 and p.stderr.startswith('usage: python3 -m cable SCRIPT')
