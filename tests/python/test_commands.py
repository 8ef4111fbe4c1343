# SPDX-License-Identifier: GPL-3.0-or-later
"""AUTO's commands on cable's engine, in-process (import cable) and through
`cable replay`: runs and restarts, label selection, results and solutions as
AUTO's objects, the file commands, exact error messages and statuses, a
script with arithmetic, def, a list comprehension, numpy and a Python-2
print, Ctrl-C during a run.

Bratu's problem u'' + lambda e^u = 0, u(0) = u(1) = 0 (c.bratu): its fold is
at lambda* = 3.513830719125162 (30-digit mpmath value, tests/test_plugin.c);
the engine locates the LP to its Newton tolerance, and NTST=20, NCOL=4
collocation is accurate to about 1e-10 there (measured 1.3e-13)."""
import os
import re
import signal
import subprocess
import time

import numpy as np
import pytest

import cable
from cable.script import py2_prints, shorthand

from conftest import BUILD, ROOT, copy_in, run_script, snapshot

LAMBDA_FOLD = 3.513830719125162


@pytest.fixture
def bratu(work):
    copy_in(work, 'runs/bratu/c.bratu', 'tests/data/cli/c.good')
    return cable.Runner()


def test_run_selection_and_columns(bratu):
    r = bratu.run(e='bratu', c='bratu', sv='lower')
    assert isinstance(r, cable.Result) and len(r) == 1
    labs = [s['LAB'] for s in r()]
    assert labs == list(range(1, len(labs) + 1)) and len(labs) == 8
    fold = r('LP1')
    assert fold['TY'] == 'LP' and fold.TY == 'LP'
    assert abs(fold['lambda'] - LAMBDA_FOLD) < 1e-8
    assert fold['lambda'] == fold.PAR['lambda'] == fold['PAR(1)'] == fold.PAR(1) == fold.PAR[0]
    assert r(fold['LAB'])['LAB'] == fold['LAB']
    assert len(r('LP')) == 1 and len(r('RG')) == 5 and [s.TY for s in r('EP')] == ['EP', 'EP']
    assert r('EP2')['LAB'] == 8
    # a branch's columns by name, as numpy arrays; r[0] and iteration give the branches
    lam = r['lambda']
    assert isinstance(lam, np.ndarray) and lam.shape == (60,)
    assert np.max(lam) == pytest.approx(LAMBDA_FOLD, abs=1e-8)
    assert np.array_equal(r[0]['lambda'], lam) and np.array_equal(r['PAR(1)'], lam)
    assert [len(b) for b in r] == [1]
    assert r['L2-NORM'].shape == (60,) and r['PT'][-1] == 60
    # the mesh and the components as numpy arrays
    t, u1 = fold['t'], fold['U(1)']
    assert t.shape == (81,) and u1.shape == (81,) and t[0] == 0 and t[-1] == 1
    assert fold.coordarray.shape == (2, 81) and np.array_equal(fold.coordarray[0], u1)
    assert abs(u1[0]) < 1e-12 and abs(u1[-1]) < 1e-12 and np.max(u1) > 1   # u(0) = u(1) = 0, the fold's bump
    assert os.path.exists('b.lower') and os.path.exists('s.lower') and os.path.exists('d.lower')


def test_restart_sum_and_numbering(bratu):
    r = bratu.run(e='bratu', c='bratu')
    fine = bratu.run(r('LP1'), NTST=40, NMX=10)
    both = r + fine
    assert len(both) == 2 and len(both()) == len(r()) + len(fine())
    # AUTO's NEWLAB: a plain restart (ISW=1) keeps its start's branch number;
    # its labels follow the largest label of r, the result the start was taken from
    assert [s['BR'] for s in r()] == [1] * 8 and fine()[0]['LAB'] == 9 and fine()[0]['BR'] == 1
    # the restart starts at the fold (its first point; the start is not labelled again)
    assert fine['lambda'][0] == pytest.approx(LAMBDA_FOLD, abs=1e-8) and fine['PT'][0] == 1
    # run(result, IRS=...) restarts from the label; without IRS from the last one
    again = bratu.run(both, IRS=3, NMX=3)
    assert again['lambda'][0] == pytest.approx(r(3)['lambda'], abs=1e-9)
    # the runner keeps the last run's constants (NTST=40 from the restart)
    s = bratu.load(r('LP1'))
    assert s['LAB'] == 3


def test_newlab_numbering(bratu):
    """AUTO-07p's NEWLAB (doc/auto-users.md, "Branch numbers"; each rule
    measured with auto-07p 0.9.2, tests/data/autoeq/numbering): a run's branch
    number and labels follow the largest branch number MBR and label MLAB of
    its restart data, the result or file its start comes from; none for a
    start from STPNT."""
    # two runs from STPNT (AUTO's demo nag): both branch 1, labels from 1
    up = bratu.run(e='bratu', c='bratu', NMX=5, sv='two')
    down = bratu.run(e='bratu', c='bratu', NMX=3, DS='-', ap='two')
    assert [(s.BR, s.LAB) for s in up()] == [(1, 1), (1, 2)]
    assert [(s.BR, s.LAB) for s in down()] == [(1, 1), (1, 2)]
    # read back, they are still two runs (split at the b-file's run headers,
    # as AUTO's parseB does, not where the branch number changes)
    back = bratu.loadbd('two')
    assert len(back) == 2 and [s.LAB for s in back()] == [1, 2, 1, 2]
    assert back[1]('EP2')['lambda'] == pytest.approx(down('EP2')['lambda'], abs=1e-9)
    assert down('EP2')['lambda'] < 0 < up('EP2')['lambda']
    # IRS picks the first solution with the label, as AUTO's FINDLB; a type
    # and count picks that solution, whatever its label ('EP4' is down's label 2),
    # and the runner keeps it for run() without a new IRS (AUTO's selected solution;
    # auto-07p 0.9.2 does each of these on the same two runs of its own bratu.f90:
    # ld(s='two', IRS='EP4'); run() starts at down's EP2, run(IRS=2) at up's)
    assert bratu.run(s='two', IRS=2, NMX=2)['lambda'][0] == pytest.approx(up('EP2')['lambda'], abs=1e-9)
    assert bratu.run(s='two', IRS='EP4', NMX=2)['lambda'][0] == pytest.approx(down('EP2')['lambda'], abs=1e-9)
    assert bratu.run(NMX=2)['lambda'][0] == pytest.approx(down('EP2')['lambda'], abs=1e-9)
    bratu.load(s='two', IRS='EP4')
    assert bratu.run(NMX=2)['lambda'][0] == pytest.approx(down('EP2')['lambda'], abs=1e-9)
    assert bratu.run(NMX=2, IRS=2)['lambda'][0] == pytest.approx(up('EP2')['lambda'], abs=1e-9)
    # without b.two the runs are told apart by their point numbers (each starts at PT 1)
    os.remove('b.two')
    assert [len(b()) for b in bratu.loadbd('two')] == [2, 2]
    # a plain restart from a solution of up (AUTO's demo exp): up's branch, labels after up's largest
    more = bratu.run(up('EP2'), NMX=3)
    assert [(s.BR, s.LAB) for s in more()] == [(1, 3)]
    # the bundle counts, not the solution (AUTO's _mbr, _mlab; demo spb's r1('UZ2')):
    # a run from up's first label numbers on after up's largest, 2
    assert [(s.BR, s.LAB) for s in bratu.run(up('EP1'), NMX=2)()] == [(1, 3)]
    both = up + more
    assert [(s.BR, s.LAB) for s in bratu.run(both('EP1'), NMX=2)()] == [(1, 4)]
    # a solution from a file's bundle: loadbd('NAME')'s largest, and ld's (its file's)
    bratu.save(up + more, 'three')
    assert [s.LAB for s in bratu.run(bratu.loadbd('three')(1), NMX=2)()] == [4]
    assert [s.LAB for s in bratu.run(bratu.load('three', e='bratu', IRS=1), NMX=2)()] == [4]
    # s= and IRS: the file's largest label and branch number
    assert [(s.BR, s.LAB) for s in bratu.run(s='three', IRS=1, NMX=2)()] == [(1, 4)]


def test_newlab_switch(work):
    """Switched runs (ISW=-1) are branch MBR + 1: both runs from the
    elastica's two BPs of branch 1 are branch 2 (AUTO's demo bvp), with the
    same labels; a switch from a BP taken from a bundle that also holds a
    branch 2 is branch 3."""
    copy_in(work, 'runs/elastica/c.elastica')
    r = cable.Runner()
    r1 = r.run(e='elastica', c='elastica', RL1=45)
    assert [(s.BR, s.LAB, s.TY) for s in r1()] == [(1, 1, 'EP'), (1, 2, 'BP'), (1, 3, 'BP'), (1, 4, 'EP')]
    a = r.run(r1('BP1'), ISW=-1, DS=0.05, NMX=5, ISP=0)
    b = r.run(r1('BP2'), ISW=-1, DS=0.05, NMX=5, ISP=0)
    assert [(s.BR, s.LAB) for s in a()] == [(s.BR, s.LAB) for s in b()] == [(2, 5)]
    c = r.run((r1 + a)('BP1'), ISW=-1, DS=0.05, NMX=2, ISP=0)
    assert [(s.BR, s.LAB) for s in c()] == [(3, 6)]


def test_files_commands(bratu):
    r = bratu.run(e='bratu', c='bratu', sv='one')
    bratu.save(r('LP1'), 'fold')
    f = bratu.loadbd('fold')
    assert len(f()) == 1 and f()[0]['lambda'] == pytest.approx(LAMBDA_FOLD, abs=1e-8)
    back = bratu.loadbd('one')
    assert [s['LAB'] for s in back()] == [s['LAB'] for s in r()]
    bratu.copy('one', 'two')
    assert snapshot('.')['s.two'] == snapshot('.')['s.one']
    up = bratu.run(r('EP1'), DS='-', NMX=5)
    bratu.append(up, 'two')
    assert len(bratu.loadbd('two')()) == len(r()) + len(up())
    m = bratu.merge(r + up)
    assert len(m) == 1   # the two directions from one start joined
    rl = bratu.relabel(m)
    assert [s['LAB'] for s in rl()] == list(range(1, len(rl()) + 1))
    bratu.relabel('two')
    assert [s['LAB'] for s in bratu.loadbd('two')()] == list(range(1, len(r()) + len(up()) + 1))
    bratu.delete('two')
    assert not any(os.path.exists(p) for p in ('b.two', 's.two', 'd.two'))
    os.mkdir('sub')
    bratu.cd('sub')
    assert os.path.basename(os.getcwd()) == 'sub'
    bratu.cd('..')
    bratu.clean()
    bratu.wait()   # stdin is not a terminal: returns at once
    ld = bratu.load('one', e='bratu', IRS=3)   # no c.one: the problem is given
    assert ld['LAB'] == 3


def test_errors_in_process(bratu):
    with pytest.raises(cable.CableError) as e:
        bratu.namespace()['run'](e='bratu', c='good', NMXX=3)
    assert str(e.value) == "run: NMXX: unknown key (in 'NMXX=3')" and e.value.status == -2
    r = bratu.run(e='bratu', c='good')
    with pytest.raises(cable.CableError) as e:
        r('BP7')
    assert str(e.value) == 'BP7: no such label in the result'
    with pytest.raises(cable.CableError) as e:
        r(99)
    assert str(e.value) == '99: no such label in the result'


def script_error(work, text, name='bad.auto'):
    before = snapshot(work)
    rc, out, err = run_script(work, text, name)
    after = snapshot(work)
    del after[name]
    before.pop(name, None)
    return rc, err, before == after


def test_script_errors(work):
    copy_in(work, 'tests/data/cli/c.good')
    rc, err, same = script_error(work, "r = run(e='bratu', c='good')\nx = run(r, NMXX=3, sv='x')\n")
    assert rc == 1 and same
    assert err.splitlines()[0] == "cable: bad.auto:2: run: NMXX: unknown key (in 'NMXX=3')"
    assert err.splitlines()[1] == "    x = run(r, NMXX=3, sv='x')"
    rc, err, same = script_error(work, "r = run(e='bratu', c='good', sv='g')\nx = r('BP7')\n")
    assert rc == 1 and err == "cable: bad.auto:2: BP7: no such label in the result\n    x = r('BP7')\n"
    rc, err, same = script_error(work, "r = run(e='bratu', c='good')\nx = = 3\n")
    assert rc == 1 and same and err == 'cable: bad.auto:2: SyntaxError: invalid syntax\n    x = = 3\n'
    rc, err, same = script_error(work, "r = run(e='bratu', c='good', NTST=-5)\n")
    assert rc == 1 and same and err.startswith('cable: bad.auto:1: run: NTST: must be an integer >= 1')
    rc, err, same = script_error(work, "r = run(e='bratu', c='nosuch')\n")
    assert rc == 1 and same and err.startswith('cable: bad.auto:1: run: ') and 'c.nosuch' in err
    rc, err, same = script_error(work, "r = run(e='bratu', c='good')\nsave(r, '')\n")
    assert rc == 1 and same and err.startswith('cable: bad.auto:2: save: the second argument must be a non-empty')
    # an error in a function the script defines names the line in the function
    rc, err, same = script_error(work, "def f(r):\n    return r('UZ9')\nr = run(e='bratu', c='good')\nf(r)\n")
    assert rc == 1 and err.startswith('cable: bad.auto:2: UZ9: no such label')


def test_script_python(work):
    copy_in(work, 'runs/bratu/c.bratu')
    text = '''import math
import numpy as np

def scaled(x, k=2):
    return k * x / 2 + 0 * math.pi

r = run(e='bratu', c='bratu')
lams = [s['lambda'] for s in r() if s['TY'] in ('RG', 'LP')]
big = max(lams)
print "max lambda %.10f" % scaled(big)
print 'numpy max %.10f, %d points' % (np.max(r['lambda']), len(r['lambda'])),
print
x = 2*math.pi - 3 ** 2 / 4.0
print('arith', x, len(lams), r('LP1').PAR['lambda'] == big)
'''
    rc, out, err = run_script(work, text)
    assert rc == 0, err
    assert 'max lambda %.10f' % LAMBDA_FOLD in out
    assert 'numpy max %.10f, 60 points \n' % LAMBDA_FOLD in out
    assert 'arith %r 6 True' % (2 * 3.141592653589793 - 2.25) in out


def test_py2_prints():
    assert py2_prints('print "a", 1\n') == 'print("a", 1)\n'
    assert py2_prints('if x:\n    print "a" % (1, 2)  # c\n') == 'if x:\n    print("a" % (1, 2))  # c\n'
    assert py2_prints('print\n') == 'print()\n'
    assert py2_prints('print "a",\n') == "print(\"a\", end=' ')\n"
    assert py2_prints('print("a")\nx = "print 1"\n') == 'print("a")\nx = "print 1"\n'
    assert py2_prints('for i in r: print i; y = 1\n') == 'for i in r: print(i); y = 1\n'


def test_shorthand_rewrite():
    """AUTO's CLI rewrites a statement `name args` as `name(args)` when name
    is a callable it knows (interactiveBindings.processShorthand): the
    commands and the builtins; nothing else changes."""
    ns = cable.Runner().namespace()
    assert shorthand("ld 'x'\n", ns) == "ld('x')\n"
    assert shorthand("sv r, 'a'  # save\n", ns) == "sv(r, 'a')  # save\n"
    assert shorthand('cl\n', ns) == 'cl()\n'
    assert shorthand("run [1]\n", ns) == "run([1])\n"
    # indexing, assignment, calls, attribute access, operators, continuation
    # lines, strings and names that are not callables keep their meaning
    same = ['x [1]\n', 'ld = 3\n', "ld('x')\n", 'run.__doc__\n', 'ld == 3\n', 'ld + 1\n', 'ld in xs\n',
            "r = run(e='a',\n        c='b')\n", 'x 3\n', 'y = """\nld "x"\n"""\n', 'd = {ld: 1}\n']
    for text in same:
        assert shorthand(text, ns) == text, text
    # print is a builtin: Python 2's print statement
    assert shorthand('print -1\n', ns) == 'print(-1)\n'
    assert shorthand('print xs [1]\n', ns) == 'print(xs [1])\n'


def test_shorthand_replay(work):
    """AUTO's own demo scripts' print statements and `ld 'x'` lines run as
    AUTO runs them: strings, %, commas, a trailing comma (Python 2 keeps the
    line open), inside a for, and `xs [1]` still indexing."""
    copy_in(work, 'runs/bratu/c.bratu')
    text = ("pgm = 'int'\n"
            "print \"\\nDemo %s is started\"%pgm\n"
            "print \"Branch \" , 2 , \"***\"\n"
            "for i in range(2):\n"
            "    print i, pgm\n"
            "print 'no newline',\n"
            "print(pgm)\n"
            "xs = [5, 6]\n"
            "print xs [1]\n"
            "x = xs [1]\n"
            "print 'x', x\n"
            "r = run(e='bratu', c='bratu', sv='lower')\n"
            "cl\n"
            "ld e='bratu', c='bratu', s='lower'\n"
            "bd 'lower'\n"
            "s = ld 'bratu'\n")
    rc, out, err = run_script(work, text)
    # the last line is no shorthand (an assignment): the error names it
    assert rc == 1 and err.startswith('cable: t.auto:16: SyntaxError'), err
    text = text[:text.rindex('s = ld')]
    rc, out, err = run_script(work, text)
    assert rc == 0, err
    lines = out.splitlines()
    assert lines[:7] == ['', 'Demo int is started', 'Branch  2 ***', '0 int', '1 int', 'no newline int', '6'], out
    assert 'x 6' in lines
    assert os.path.exists('b.lower') and os.path.exists('s.lower')


def test_fail_and_kind(work):
    """fail('text') stops a script with the text (main's scene builtin;
    raising CableError does the same); sol['kind'] is the detector's BP kind
    (cable_solution.bp_kind): '' for points that are no BP."""
    copy_in(work, 'runs/bratu/c.bratu')
    rc, out, err = run_script(work, "r = run(e='bratu', c='bratu')\nfail('no fold with 3 < lambda < 4')\n"
                                    "r = run(e='bratu', c='bratu')\n")
    assert rc == 1 and err.splitlines()[0] == 'cable: t.auto:2: fail: no fold with 3 < lambda < 4', err
    rc, out, err = run_script(work, 'fail(3)\n')
    assert rc == 1 and err.splitlines()[0] == 'cable: t.auto:1: fail: fail() takes the message as a string', err
    r = cable.Runner().run(e='bratu', c='bratu')
    assert [s['kind'] for s in r()] == [''] * len(r()) and r('LP1').kind == ''


def test_ctrl_c_stops_a_run(work):
    """SIGINT during a long run: the run stops after the point being
    computed, its files hold every point so far (doc/failures.md), the files
    saved before are complete, status 130."""
    copy_in(work, 'runs/bratu/c.bratu')
    with open('long.auto', 'w') as f:
        f.write("first = run(e='bratu', c='bratu', sv='first')\n"
                "print('long run starts', flush=True)\n"
                "long = run(first('EP1'), DS=1e-6, DSMIN=1e-7, DSMAX=1e-6, NMX=100000000, NPR=0, sv='long')\n")
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
    # SIGINT as at a terminal, even when the test itself runs in a background
    # job (which inherits SIGINT ignored, and CPython then keeps it ignored)
    p = subprocess.Popen([os.path.join(BUILD, 'cable'), 'replay', 'long.auto'], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env=env, start_new_session=True,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    line = ''
    while 'long run starts' not in line:
        line = p.stdout.readline()
        assert line, 'the script ended early: ' + p.stderr.read()
    time.sleep(1.0)
    t0 = time.monotonic()
    p.send_signal(signal.SIGINT)
    try:
        out, err = p.communicate(timeout=120)
    finally:
        if p.poll() is None:   # never leave the long run behind
            p.kill()
            p.wait()
    assert p.returncode == 130
    assert err.startswith('cable: long.auto:3: stopped by SIGINT: '), err
    m = re.search(r'interrupted after PT (\d+) .*its (\d+) points \(0 labelled\) are in b.long, s.long, d.long', err)
    assert m and m.group(1) == m.group(2), err
    with open('b.long') as f:
        rows = [ln for ln in f if ln.strip() and not ln.startswith('   0')]
    assert len(rows) == int(m.group(1)) and not os.path.islink('b.long')
    assert time.monotonic() - t0 < 60
    r = cable.Runner().loadbd('first')
    assert len(r()) == 8


def test_run_name_is_e_and_c(bratu):
    """run('NAME') is AUTO's e='NAME', c='NAME': the package passes the name
    through to the session (the C side decides, doc/auto-users.md)."""
    r = bratu.run('bratu', sv='byname')
    assert abs(r('LP1')['lambda'] - LAMBDA_FOLD) < 1e-8
    with pytest.raises(cable.CableError) as e:
        bratu.run('nosuch')
    assert 'nosuch' in str(e.value)


def test_fold_run_through_python(work):
    """ISW=2 fold continuation (runs/link62fold) through the package: the
    scene's fold runs (AUTO's two: starting data, then the curve) from
    tests/data/fold/s.link62lp (its LP at NTST = 40, as
    tests/test_fold_scene.c) reaches Delta = 0.0163 at the T where the
    ordinary branch at that fixed Delta has its LP (both located to the
    Newton tolerances, far below 1e-7)."""
    copy_in(work, 'runs/link62fold/c.link62mode', 'runs/link62fold/c.link62fold', 'tests/data/fold/s.link62lp')
    rn = cable.Runner()
    # AUTO's first run at the LP generates the starting data: five points,
    # one label (its EP, TY 59), branch IRS; the curve restarts from it
    st = rn.run(s='link62lp', IRS='LP1', c='link62fold', NTST=40, IAD=0, ISP=0, sv='foldstart')
    assert len(st()) == 1 and st()[0].TY == 'EP' and len(st['Delta']) == 5
    f = rn.run(st('EP1'), NTST=40, IAD=0, ISP=0, NMX=8, NPR=100, UZR={'Delta': [0.0163]}, sv='fold')
    c = rn.run(s='link62lp', IRS='LP1', c='link62mode', NTST=40, IAD=0, ISW=1, ILP=1, ISP=0, ITMX=24,
               PAR={'Delta': 0.0163}, DS=-0.01, DSMAX=0.2, NMX=30, STOP=['LP1'], sv='chk')
    u, lp = f('UZ1'), c('LP1')
    assert abs(u['Delta'] - 0.0163) <= 1e-9 * 0.0163
    assert abs(lp['Delta'] - 0.0163) <= 1e-14 * 0.0163
    assert abs(u['T'] - lp['T']) <= 1e-7 * abs(lp['T'])
    # run(f), AUTO's third run of its demo int: a restart from the fold run
    # takes the fold run's own constants (ISW=2, the original NDIM, ICP), so
    # it continues the fold curve from f's last point, in f's direction
    # (before: "ICP must list the 2 free parameter(s)", the extended problem's
    # constants had been kept)
    g = rn.run(f, NMX=3, UZR={}, sv='fold2')
    df, dg = f['Delta'], g['Delta']
    assert len(dg) == 3 and dg[0] == df[-1]
    step = df[-1] - df[-2]
    assert all((dg[i + 1] - dg[i]) * step > 0 for i in range(2))
    # AUTO's NEWLAB for ISW=2: the starting-data run from an LP (ISW=-2 inside
    # AUTO) is a new branch, MBR + 1, its label after the largest of
    # s.link62lp; the fold curve restarted from it keeps that branch number
    src = rn.sl('link62lp')
    nbr = max(x.BR for x in src) + 1
    assert {x.BR for x in st()} == {nbr} and st()[0].LAB == max(x.LAB for x in src) + 1
    assert {x.BR for x in f()} == {nbr} and f()[0].LAB == st()[0].LAB + 1
    assert {x.BR for x in g()} == {nbr} and g()[0].LAB == f()[-1].LAB + 1


def test_problem_keys_and_prepare(work):
    """The braid problems prepare themselves from their keys and PAR={...}
    (plug-in ABI 2, issue 13): every run from STPNT works through the
    package, and bad keys are refused naming the key (ported from main's
    tests/test_script.c)."""
    rn = cable.Runner()
    cases = [
        # no constants file and no recommended constants (bratu): AUTO's IPS=1, refused
        (dict(e='bratu'), "<no constants file>: IPS: IPS=1 (not set: AUTO's default) is a problem type "
                               "cable does not solve: cable solves boundary-value problems (IPS=4); write IPS = 4 "
                               "in the constants file (or give IPS=4)"),
        # a braid problem's first run from keywords takes its recommended constants (IPS=4 among them)
        (dict(e='braid_knot'), "PAR: a braid start needs the strand distance: PAR={'Delta': ...}"),
        (dict(e='braid_knot', IPS=4), "PAR: a braid start needs the strand distance: PAR={'Delta': ...}"),
        (dict(e='braid_link_sym', IPS=4), "e: 'braid_link_sym' has no start from STPNT: restart from a stored "
                                   "solution (run(sol) or IRS with s=)"),
        (dict(e='braid_knot', TORUS=-3), "TORUS: must be an integer in 0..1001, got -3 (the start from STPNT: "
                                         "the (p,2) torus knot (odd p) or link (even p >= 2); 0: the two rings) "
                                         "(in 'TORUS=-3')"),
        (dict(e='braid_knot', HAND='up'), "HAND: unknown value string 'up' (handedness of the start: 1 or "
                                          "'right', -1 or 'left') (in 'HAND='up'')"),
        (dict(e='bratu', TORUS=7), "TORUS: unknown key (in 'TORUS=7')"),
    ]
    for kw, msg in cases:
        with pytest.raises(cable.CableError) as e:
            rn.run(**kw)
        assert str(e.value) == msg, (kw, str(e.value))
    assert os.listdir('.') == []
