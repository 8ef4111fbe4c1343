# SPDX-License-Identifier: GPL-3.0-or-later
"""AUTO-07p's CLI objects as AUTO's users know them (issue 26, item 3),
compared with auto-07p 0.9.2 on the same folder where it runs them.

The script below runs unchanged through `auto-07p` and `cable replay` on
tests/data/autoeq/bratu_f90 (Bratu's problem from STPNT, both directions,
NMX=12): AUTO's module imported by name, merge of a result and of files
with two names, getLabels, toArray, print(r), summary.  Their step-size
control differs (cable's 12th point is at another lambda), so the tests
compare what AUTO's objects are: labels, types, point numbers, row and
column counts, the table's layout; not the values of unlabelled points.
(auto-07p 0.9.2's parseB uses numpy.bool, which numpy 1.24 removed: the
script restores the alias first; it is a no-op for cable.)"""
import os
import re
import shutil
import subprocess

import numpy as np
import pytest

import cable

from conftest import BUILD, ROOT, PYTHON, run_script

AUTO = '/usr/bin/auto-07p'

SCRIPT = r'''
import numpy
numpy.bool = numpy.bool_
import AUTOclui
import AUTOCommands
from AUTOclui import *
r1 = AUTOclui.run(e='bratu', c='bratu', NMX=12, UZR={})
r2 = run(e='bratu', c='bratu', NMX=12, DS='-', UZR={})
r = r1 + r2
print("OUT labels", r.getLabels())
m = merge(r)
print("OUT merged", m.getLabels(), len(m))
for s in m(): print("OUT sol", s['LAB'], s['TY'], s['PT'], s['BR'])
print("OUT toArray", len(r1.toArray()), len(r1.toArray()[0]))
sv(r, 'two')
merge('two', 'merged')
print("OUT two", loadbd('two').getLabels())
print("OUT loaded", loadbd('merged').getLabels())
print("OUT rows", [len(b.toArray()) for b in loadbd('two')], [len(b.toArray()) for b in loadbd('merged')])
sv(loadbd('two'), 'again')
print("OUT resaved", len([l for l in open('b.again') if l.split() and l.split()[0] != '0']),
      len([l for l in open('b.two') if l.split() and l.split()[0] != '0']))
print("TABLE")
print(r1)
print("SUMMARY")
print(r1.summary())
print("END")
'''


def _folder(tmp, name):
    d = os.path.join(str(tmp), name)
    os.makedirs(d)
    for f in ('bratu.f90', 'c.bratu'):
        shutil.copy(os.path.join(ROOT, 'tests/data/autoeq/bratu_f90', f), d)
    with open(os.path.join(d, 'objects.auto'), 'w') as f:
        f.write(SCRIPT)
    return d


def _outs(text):
    return [ln[4:] for ln in text.splitlines() if ln.startswith('OUT ')]


def _table(text, start, end):
    block = text.split(start + '\n', 1)[1].split(end + '\n', 1)[0]
    return [ln.rstrip() for ln in block.splitlines() if ln.strip()]


@pytest.fixture(scope='module')
def both(tmp_path_factory):
    tmp = tmp_path_factory.mktemp('objects')
    ca = _folder(tmp, 'cable')
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
    p = subprocess.run([os.path.join(BUILD, 'cable'), 'replay', 'objects.auto'], cwd=ca, env=env,
                       capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stderr
    out = {'cable': p.stdout}
    if os.access(AUTO, os.X_OK):
        au = _folder(tmp, 'auto')
        q = subprocess.run([AUTO, 'objects.auto'], cwd=au, capture_output=True, text=True, timeout=600,
                           env=dict(os.environ, PATH='/usr/bin:/bin'))
        assert q.returncode == 0 and 'END' in q.stdout, q.stdout[-2000:] + q.stderr[-2000:]
        out['auto'] = q.stdout
    return out


def test_objects_as_auto07p(both):
    """The same script through cable and auto-07p: AUTO's module names import,
    merge renumbers (the shared start keeps one label), merge('A', 'B')
    writes B and leaves A, getLabels and toArray's shape, print(r) and
    summary() are AUTO's table."""
    c = _outs(both['cable'])
    assert c[0] == 'labels [1, 2, 1, 2]'
    assert c[1] == 'merged [1, 2, 3] 1'
    assert c[2:5] == ['sol 1 EP 1 1', 'sol 2 EP 2 1', 'sol 3 EP 13 1']
    assert c[5] == 'toArray 12 4'      # 12 points, PAR(1) L2-NORM MAX U(1) MAX U(2)
    assert c[6] == 'two [1, 2, 1, 2]'  # merge('two', 'merged') leaves two as it was
    assert c[7] == 'loaded [1, 2, 3]'
    # loadbd keeps every row (12 and 2 points, 13 merged), and re-saving writes them all
    assert c[8] == 'rows [12, 2] [13]'
    assert c[9] == 'resaved 14 14'
    table = _table(both['cable'], 'TABLE', 'SUMMARY')
    assert table[0] == '  BR    PT  TY  LAB    PAR(1)        L2-NORM       MAX U(1)      MAX U(2)'
    assert [ln[:19] for ln in table[1:]] == ['   1     1  EP    1', '   1    12  EP    2']
    assert all(re.fullmatch(r'.{19}(  [ -]\d\.\d{5}E[+-]\d\d){4}', ln) for ln in table[1:]), table
    assert _table(both['cable'], 'SUMMARY', 'END') == table
    if 'auto' not in both:
        pytest.skip('auto-07p is not installed: cable checked against the recorded values only')
    a = _outs(both['auto'])
    assert c == a
    at = _table(both['auto'], 'TABLE', 'SUMMARY')
    assert at[0] == table[0]
    assert [ln[:19] for ln in at] == [ln[:19] for ln in table]
    assert [len(ln) for ln in at] == [len(ln) for ln in table]


@pytest.fixture
def bratu(work):
    for f in ('bratu.f90', 'c.bratu'):
        shutil.copy(os.path.join(ROOT, 'tests/data/autoeq/bratu_f90', f), str(work))
    return cable.Runner()


def test_merge_and_relabel_signatures(bratu):
    """merge('A', 'B') and relabel('A', 'B') as AUTO's: A's files
    transformed into B, A untouched; merge() merges the last run's result."""
    r1 = bratu.run(e='bratu', c='bratu', NMX=6, UZR={})
    r2 = bratu.run(e='bratu', c='bratu', NMX=6, DS='-', UZR={})
    bratu.save(r1 + r2, 'a')
    before = open('s.a').read()
    assert bratu.merge('a', 'b') is None
    assert open('s.a').read() == before
    assert bratu.loadbd('b').getLabels() == [1, 2, 3] and len(bratu.loadbd('b')) == 1
    assert bratu.relabel('a', 'c') is None
    assert bratu.loadbd('c').getLabels() == [1, 2, 3, 4] and open('s.a').read() == before
    with pytest.raises(cable.CableError, match="merge\\('A', 'B'\\): B must be a name"):
        bratu.namespace()['merge']('a', 3)
    with pytest.raises(cable.CableError, match="relabel\\(\\) works on the last run's output"):
        cable.Runner().namespace()['relabel']()
    # no argument: the last run's output (AUTO's fort.* files), here r2's one branch
    assert bratu.merge().getLabels() == r2.getLabels()


def test_plot_figures(bratu):
    """plot on names, results and solutions returns a matplotlib figure;
    plot('x.png', [result]) draws a result in memory into a file."""
    matplotlib = pytest.importorskip('matplotlib')
    from matplotlib.figure import Figure
    r = bratu.run(e='bratu', c='bratu', NMX=20, sv='flat')
    f = bratu.plot('flat')
    assert isinstance(f, Figure)
    line = f.axes[0].lines[0]
    assert np.array_equal(line.get_xdata(), bratu.loadbd('flat')['PAR(1)'])
    assert f.axes[0].get_xlabel() == 'PAR(1)' and f.axes[0].get_ylabel() == 'L2-NORM'
    g = bratu.plot(r, y='L2-NORM', title='Bratu')
    assert np.array_equal(g.axes[0].lines[0].get_ydata(), r['L2-NORM']) and g.axes[0].get_title() == 'Bratu'
    s = bratu.plot(r('LP1'))
    assert np.array_equal(s.axes[0].lines[0].get_xdata(), r('LP1')['t'])
    assert np.array_equal(s.axes[0].lines[0].get_ydata(), r('LP1')['U(1)'])
    assert isinstance(bratu.plot('x.png', [r]), Figure)
    with open('x.png', 'rb') as fh:
        assert fh.read(8) == b'\x89PNG\r\n\x1a\n'
    assert matplotlib is not None


def _dat_dirs():
    import tempfile
    d = tempfile.gettempdir()
    return sorted(n for n in os.listdir(d) if n.startswith('cable-dat-'))


def test_start_from_data_columns(work):
    """run(u, ...) with u AUTO's columns [[t...], [u1...], [u2...]] (a list
    or a numpy array) is the run a dat= file with the same rows gives (that
    one is compared with auto-07p in tests/test_auto07p.c, folder
    bratu_dat): the same branch bit for bit."""
    src = os.path.join(ROOT, 'tests/data/autoeq/bratu_dat')
    for f in os.listdir(src):
        shutil.copy(os.path.join(src, f), str(work))
    rn = cable.Runner()
    before = _dat_dirs()
    a = rn.run(e='bratu', c='bratudat')
    rows = np.loadtxt('bratu.dat')
    b = rn.run(rows.T, e='bratu', c='bratudat')
    c = rn.run(rows.T.tolist(), e='bratu', c='bratudat')
    for k in ('PAR(1)', 'L2-NORM', 'TY', 'LAB'):
        assert np.array_equal(a[k], b[k]) and np.array_equal(a[k], c[k]), k
    assert len(a['PT']) > 10 and a.getLabels() == b.getLabels()
    run = rn.namespace()['run']
    with pytest.raises(cable.CableError, match='t \\(the first column\\) must increase'):
        run(rows[::-1].T, e='bratu', c='bratudat')
    with pytest.raises(cable.CableError, match='a point solution'):
        run([0.0, 1.0, 2.0], e='bratu', c='bratudat')
    with pytest.raises(cable.CableError, match='not for load'):
        rn.namespace()['load'](rows.T, e='bratu', c='bratudat')
    assert _dat_dirs() == before   # the temporary dat files are gone


def test_auto_names_cable_lacks_are_documented():
    """Every callable name of AUTO's AUTOclui that a cable script does not
    have is listed in doc/scripts.md (its table of AUTO's names cable lacks)."""
    auto_py = '/usr/lib/auto-07p/python'
    if not os.path.isdir(auto_py):
        pytest.skip('auto-07p is not installed')
    p = subprocess.run([PYTHON, '-c', 'import AUTOclui\nprint(" ".join(n for n in dir(AUTOclui) if not '
                        'n.startswith("_") and callable(getattr(AUTOclui, n))))'],
                       env=dict(os.environ, PYTHONPATH='%s/auto:%s' % (auto_py, auto_py)),
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    auto_names = p.stdout.split()
    assert len(auto_names) > 150
    have = set(cable.Runner().namespace())
    with open(os.path.join(ROOT, 'doc/scripts.md')) as f:
        doc = f.read()
    section = doc.split('### AUTO names cable does not have', 1)[1].split('\n## ', 1)[0]
    # the first column of the table's rows
    listed = set()
    for ln in section.splitlines():
        if ln.startswith('| `'):
            listed.update(re.findall(r'`([A-Za-z_][A-Za-z0-9_]*)`', ln.split('|')[1]))
    missing = [n for n in auto_names if n not in have and n not in listed]
    assert not missing, 'not in cable and not in doc/scripts.md: %s' % missing
    wrongly = [n for n in listed if n in have and n in auto_names]
    assert not wrongly, 'listed as missing but cable has them: %s' % wrongly


def test_auto_module_names_in_process(bratu):
    """import cable users get AUTO's module names inside the package."""
    from cable import AUTOclui, AUTOCommands
    assert callable(AUTOclui.run) and callable(AUTOCommands.merge) and 'mb' in AUTOclui.__all__


def test_loadbd_rows_names_and_problem_from_the_files(work):
    """loadbd without a constants file: every b-file row, the parameter
    names of the b-file's header (parnames), and the problem its header
    records (e=), so a run from a loaded solution needs no e=, as in AUTO."""
    for f in ('bratu.f90', 'c.bratu'):
        shutil.copy(os.path.join(ROOT, 'tests/data/autoeq/bratu_f90', f), str(work))
    with open('c.bratu', 'a') as f:
        f.write("parnames = {1: 'lam'}\n")
    r = cable.Runner().run(e='bratu', c='bratu', NMX=40, sv='lower')
    os.remove('c.bratu')
    fresh = cable.Runner()
    x = fresh.loadbd('lower')
    # the files hold 11 significant digits (ES19.10E3): a relative 5e-11
    assert len(x['lam']) == 40 and np.allclose(x['lam'], r['lam'], rtol=1e-10, atol=0)
    assert np.allclose(x['L2-NORM'], r['L2-NORM'], rtol=1e-10, atol=0) and x.getLabels() == r.getLabels()
    assert x('LP1')['lam'] == pytest.approx(r('LP1')['lam'], rel=1e-10)
    assert x.branches[0].e == 'bratu'
    y = fresh.run(x('LP1'), NMX=3)   # the problem from the file
    assert y.branches[0].e == 'bratu' and len(y['lam']) == 3
    fresh.save(x, 'again')
    rows = [ln for ln in open('b.lower') if ln.split()[0] != '0']
    assert [ln for ln in open('b.again') if ln.split()[0] != '0'] == rows
    assert open('s.again').read() == open('s.lower').read()


HEADER_KEYS = ['NDIM', 'IPS', 'IRS', 'ILP', 'NTST', 'NCOL', 'IAD', 'ISP', 'ISW', 'IPLT', 'NBC', 'NINT', 'NMX', 'NPR',
               'ITMX', 'ITNW', 'NWTN', 'JAC', 'NPAR', 'DS', 'DSMIN', 'DSMAX', 'RL0', 'RL1', 'A0', 'A1', 'EPSL',
               'EPSU', 'EPSS']

WRITE = r'''
import numpy
numpy.bool = numpy.bool_
r1 = run(e='bratu', c='bratu', NMX=6, UZR={}, NTST=7, DS=0.07, EPSL=3e-7, RL1=9.5, A1=55, ITMX=11, NPR=3, DSMAX=0.3)
r2 = run(e='bratu', c='bratu', NMX=5, UZR={}, NTST=9, DS='-', IAD=2, ISP=1, EPSS=2e-5, RL0=-3, A0=-1)
sv(r1 + r2, 'two')
'''

READ = r'''
b = loadbd('two')
for k in range(len(b)):
    for key in %r:
        print("OUT", k, key, b[k].c[key])
print("END")
''' % HEADER_KEYS


def test_loadbd_header_constants(tmp_path):
    """loadbd('NAME') without c.NAME: each branch's c holds what its b-file
    section's header records (AUTO's parseB: RL0 RL1 A0 A1 from the first
    header line, every KEY = VALUE of the others), per branch; in a fresh
    script, so nothing comes from the runs that wrote the file.  Before,
    only NDIM, NBC, NINT and IPS were read, and a result had no .c."""
    outs = {}
    for who in ('cable', 'auto'):
        if who == 'auto' and not os.access(AUTO, os.X_OK):
            continue
        d = tmp_path / who
        d.mkdir()
        for f in ('bratu.f90', 'c.bratu'):
            shutil.copy(os.path.join(ROOT, 'tests/data/autoeq/bratu_f90', f), str(d))
        (d / 'write.auto').write_text(WRITE)
        (d / 'read.auto').write_text(READ)
        for script in ('write.auto', 'read.auto'):
            if who == 'cable':
                env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
                p = subprocess.run([os.path.join(BUILD, 'cable'), 'replay', script], cwd=str(d), env=env,
                                   capture_output=True, text=True, timeout=600)
            else:
                p = subprocess.run([AUTO, script], cwd=str(d), capture_output=True, text=True, timeout=600,
                                   env=dict(os.environ, PATH='/usr/bin:/bin'))
            assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
        assert 'END' in p.stdout, p.stdout[-2000:] + p.stderr[-2000:]
        outs[who] = _outs(p.stdout)
    c = dict((tuple(ln.split()[:2]), ln.split()[2]) for ln in outs['cable'])
    # the values the two runs were given, per branch
    want = {('0', 'NTST'): '7', ('0', 'DS'): '0.07', ('0', 'EPSL'): '3e-07', ('0', 'RL1'): '9.5',
            ('0', 'A1'): '55.0', ('0', 'ITMX'): '11', ('0', 'NPR'): '3', ('0', 'DSMAX'): '0.3',
            ('1', 'NTST'): '9', ('1', 'IAD'): '2', ('1', 'ISP'): '1', ('1', 'EPSS'): '2e-05',
            ('1', 'RL0'): '-3.0', ('1', 'A0'): '-1.0'}
    for k, v in want.items():
        assert float(c[k]) == float(v), (k, c[k], v)
    assert len(c) == 2 * len(HEADER_KEYS)
    if 'auto' not in outs:
        pytest.skip('auto-07p is not installed: cable checked against the values given only')
    a = dict((tuple(ln.split()[:2]), ln.split()[2]) for ln in outs['auto'])
    assert set(a) == set(c)
    for k in a:
        assert float(c[k]) == float(a[k]), (k, c[k], a[k])
