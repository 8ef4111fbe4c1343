# SPDX-License-Identifier: GPL-3.0-or-later
"""A run's b./s./d. files are on disk as it computes (doc/failures.md): after
SIGKILL at any moment they hold every published point, consistently, read
by cable and by AUTO-07p's own parsers; SIGINT and SIGTERM end a run after
the point being computed with a message, exit 130/143 and the files; two
writers of one name never mix their files; a bad output name is refused
before anything is computed; a user routine that ends the process or
returns a fatal status is named and the exit status is non-zero."""
import json
import re
import os
import shutil
import signal
import subprocess
import time

import pytest

from conftest import BUILD, PYTHON, ROOT

CABLE = os.path.join(BUILD, 'cable')
AUTO_PY = '/usr/lib/auto-07p/python'
KNOT = "e='braid_knot', c='knot72'"
NMX = 40          # the knot72 flat branch (it ends at RL1 after about 30 points; labels at its BPs)
POLL = 0.02       # seconds between looks at the files while a run goes

# AUTO-07p's parsers, in a python of their own: rows (PT, LAB, TY, PAR) of
# b.NAME's branches and solutions (LAB, PT, TY, PAR(1)) of s.NAME (PAR: the
# first column, PAR(1) in these tests).  numpy's
# alias np.bool, which auto-07p 0.9.2's Points.py still names, is restored
# for them.
AUTO_READ = r'''
import json, sys, warnings
warnings.simplefilter('ignore')
import numpy
numpy.bool = numpy.bool_
sys.path.insert(0, %r)
from auto import parseB, parseS
brs = parseB.parseBR(sys.argv[1])
sols = parseS.parseS(sys.argv[2])
# parseB's PT is None on some rows: a row's point number is its place in the branch
rows = [[i + 1, int(p['LAB']), int(p['TY number']), float(p[br.coordnames[0]])] for br in brs
        for i, p in enumerate(br)]
out = [[int(s['Label']), int(s['PT']), int(s['TY number']), float(s.PAR[0])] for s in sols]
print(json.dumps({'branches': len(brs), 'rows': rows, 'sols': out}))
''' % AUTO_PY


def env():
    return dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'), OPENBLAS_NUM_THREADS='1')


def auto_read(d, name):
    p = subprocess.run([PYTHON, '-c', AUTO_READ, os.path.join(d, 'b.' + name), os.path.join(d, 's.' + name)],
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)


def cable_labels(d, name):
    """The labels cable's loadbd reads from the files (in a fresh process)."""
    code = 'import cable, json; r = cable.loadbd(%r); print(json.dumps([s.LAB for s in r()]))' % name
    p = subprocess.run([PYTHON, '-c', code], capture_output=True, text=True, timeout=120, env=env(), cwd=d)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)


def check_files(d, name, ref=None, ended=False):
    """The files agree with each other (every labelled b row has its
    solution, in order, at the same point and parameter; the s-file's last
    solution whole; cable's loadbd reads the same labels) and, with ref (a
    complete run's rows), the rows are its first ones (ended: the last is
    the end point of a shorter run, an EP there).  Returns the rows."""
    got = auto_read(d, name)
    rows, sols = got['rows'], got['sols']
    assert got['branches'] == 1
    lab = [r for r in rows if r[1]]
    assert [(r[1], r[0], r[2]) for r in lab] == [tuple(s[:3]) for s in sols]
    for r, s in zip(lab, sols):
        # the b-file has 11 significant digits (ES19.10), the s-file too
        assert s[3] == pytest.approx(r[3], rel=1e-9, abs=1e-30)
    assert cable_labels(d, name) == [s[0] for s in sols]
    if ref is not None:
        assert len(rows) <= len(ref)
        for i, (r, q) in enumerate(zip(rows, ref)):
            assert r[:3] == q[:3] or (ended and i == len(rows) - 1 and r[2] == 9)
            # the same computation: equal to the printed digits
            assert r[3] == pytest.approx(q[3], rel=1e-9, abs=1e-30)
    return rows


def data_rows(path):
    """Complete data rows of a b-file as a reader sees it now (0: none)."""
    try:
        with open(path) as f:
            text = f.read()
    except OSError:
        return 0
    # a published file always ends with a whole line
    assert text == '' or text.endswith('\n')
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.startswith('   0')]
    if lines:
        assert len({len(ln.split()) for ln in lines}) == 1   # no torn row
    return len(lines)


def wait_rows(proc, path, k):
    """Waits (reading the file as a concurrent reader would) until it has k rows."""
    while data_rows(path) < k:
        assert proc.poll() is None, 'the run ended before it had %d points' % k
        time.sleep(POLL)


def start(d, args, replay=None):
    if replay is not None:
        with open(os.path.join(d, 'k.auto'), 'w') as f:
            f.write(replay)
        cmd = [CABLE, 'replay', 'k.auto']
    else:
        cmd = [CABLE, 'run'] + args
    out = open(os.path.join(d, 'log'), 'w')
    err = open(os.path.join(d, 'err'), 'w')
    p = subprocess.Popen(cmd, cwd=d, stdout=out, stderr=err, env=env())
    out.close()
    err.close()
    return p


def read(d, name):
    with open(os.path.join(d, name)) as f:
        return f.read()


def knot_dir(tmp_path, sub):
    d = tmp_path / sub
    d.mkdir()
    shutil.copy(os.path.join(ROOT, 'runs/knot72/c.knot72'), d)
    return str(d)


@pytest.fixture(scope='module')
def reference(tmp_path_factory):
    """The rows of the complete run that the killed runs cut short."""
    d = knot_dir(tmp_path_factory.mktemp('ref'), 'ref')
    p = subprocess.run([CABLE, 'run', 'c=knot72', 'NMX=%d' % NMX, 'sv=flat'], cwd=d, capture_output=True, text=True,
                       env=env(), timeout=600)
    assert p.returncode == 0, p.stderr
    rows = check_files(d, 'flat')
    # the branch leaves RL1 = 34 at its 29th or 30th point, an EP, with the
    # start and its four double BPs labelled.  Which of the two depends on
    # whether a double BP is found by the pencil test inside its step (the
    # next step starts at the BP) or by the dip test after it (the grid goes
    # on from the point behind it): rounding decides near sigma_1 ~ 1e-6,
    # 29 on one CI machine, 30 on an AMD EPYC with the same code.  The tests
    # compare the killed runs with this machine's own complete run.
    assert len(rows) < NMX and rows[-1][2] == 9 and rows[-1][3] > 34.0
    assert sum(1 for r in rows if r[1]) == 6 and sum(1 for r in rows if r[2] == 6) == 4
    return rows


def no_leftovers(d, name):
    names = os.listdir(d)
    assert '.cable-' + name not in names
    assert not [n for n in names if n.startswith('.') and '.tmp' in n], names
    for k in 'bsd':
        assert not os.path.islink(os.path.join(d, k + '.' + name))


@pytest.mark.parametrize('k', [1, 6, 17])
def test_sigkill_cable_run_keeps_every_published_point(tmp_path, reference, k):
    d = knot_dir(tmp_path, 'kill')
    p = start(d, ['c=knot72', 'NMX=%d' % NMX, 'sv=flat'])
    wait_rows(p, os.path.join(d, 'b.flat'), k)
    p.kill()
    p.wait()
    rows = check_files(d, 'flat', reference)
    assert k <= len(rows) < len(reference)
    # the d-file says the run was cut short
    assert read(d, 'd.flat').rstrip().endswith('the points above are complete')
    # the log went out line by line: the start's line is there
    assert 'BR    1  PT     1  TY EP  LAB    1' in read(d, 'log')
    # the next writer of the name takes the killed one's leftovers over
    p = subprocess.run([CABLE, 'run', 'c=knot72', 'NMX=3', 'sv=flat'], cwd=d, capture_output=True, text=True,
                       env=env(), timeout=600)
    assert p.returncode == 0, p.stderr
    no_leftovers(d, 'flat')
    assert len(check_files(d, 'flat', reference, ended=True)) == 3


@pytest.mark.parametrize('k', [2, 11])
def test_sigkill_cable_replay_keeps_every_published_point(tmp_path, reference, k):
    d = knot_dir(tmp_path, 'killr')
    p = start(d, None, "flat = run(%s, NMX=%d, sv='flat')\n" % (KNOT, NMX))
    wait_rows(p, os.path.join(d, 'b.flat'), k)
    p.send_signal(signal.SIGKILL)
    p.wait()
    # killed while computing (the whole branch has about 30 points)
    assert k <= len(check_files(d, 'flat', reference)) < len(reference)


@pytest.mark.parametrize('sig,status', [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
@pytest.mark.parametrize('how', ['run', 'replay'])
def test_sigint_sigterm_end_the_run_with_its_files(tmp_path, reference, sig, status, how):
    d = knot_dir(tmp_path, 'sig')
    if how == 'run':
        p = start(d, ['c=knot72', 'NMX=%d' % NMX, 'sv=flat'])
    else:
        p = start(d, None, "flat = run(%s, NMX=%d, sv='flat')\nprint('not reached')\n" % (KNOT, NMX))
    wait_rows(p, os.path.join(d, 'b.flat'), 4)
    p.send_signal(sig)
    assert p.wait(timeout=600) == status
    err = read(d, 'err')
    name = 'SIGINT' if sig == signal.SIGINT else 'SIGTERM'
    assert name in err and "branch 1 of e='braid_knot' interrupted after PT" in err
    assert 'are in b.flat, s.flat, d.flat' in err
    rows = check_files(d, 'flat', reference)
    assert len(rows) >= 4 and ('after PT %d ' % rows[-1][0]) in err
    no_leftovers(d, 'flat')
    assert 'ended: interrupted' in read(d, 'd.flat')
    log = read(d, 'log')
    assert 'BR    1  PT     1  TY EP  LAB    1' in log and 'not reached' not in log


def test_keyboard_interrupt_in_python_keeps_branch_and_files(tmp_path):
    d = knot_dir(tmp_path, 'py')
    code = r'''
import json, os, signal, threading, time
import cable
def interrupt():
    while True:
        try:
            with open('b.flat') as f:
                if sum(1 for ln in f if ln.strip() and not ln.startswith('   0')) >= 3:
                    break
        except OSError:
            pass
        time.sleep(0.02)
    os.kill(os.getpid(), signal.SIGINT)
threading.Thread(target=interrupt, daemon=True).start()
try:
    cable.run(e='braid_knot', c='knot72', NMX=%d, sv='flat')
    print(json.dumps({'interrupted': False}))
except KeyboardInterrupt as e:
    print(json.dumps({'interrupted': True, 'notes': getattr(e, '__notes__', []),
                      'points': len(e.result['T']), 'labels': [s.LAB for s in e.result()]}))
''' % NMX
    p = subprocess.run([PYTHON, '-c', code], capture_output=True, text=True, timeout=600, env=env(), cwd=d)
    assert p.returncode == 0, p.stderr
    got = json.loads(p.stdout.strip().splitlines()[-1])
    assert got['interrupted']
    assert any('are in b.flat, s.flat, d.flat' in n for n in got['notes'])
    rows = check_files(d, 'flat')
    assert got['points'] == len(rows) >= 3
    assert got['labels'] == [r[1] for r in rows if r[1]]


def test_log_lines_go_to_sys_stdout_as_points_are_computed(tmp_path):
    """Each labelled point's line reaches Python's sys.stdout (what a
    notebook shows) while the run is still computing, and an
    'accepted and ignored' note is printed once, not before every run."""
    d = knot_dir(tmp_path, 'out')
    code = r'''
import json, sys
import cable
seen = []
class Out:
    def write(self, text):
        for line in text.splitlines():
            if 'LAB' in line or 'note:' in line or 'branch 1:' in line:
                try:
                    with open('b.flat') as f:
                        rows = sum(1 for ln in f if ln.strip() and not ln.startswith('   0'))
                except OSError:
                    rows = -1
                seen.append([line.strip(), rows])
        return len(text)
    def flush(self):
        pass
real, sys.stdout = sys.stdout, Out()
cable.run(e='braid_knot', c='knot72', NMX=12, MXBF=5, sv='flat')
cable.run(e='braid_knot', c='knot72', NMX=3, MXBF=5, sv='flat2')
sys.stdout = real
print(json.dumps(seen))
'''
    p = subprocess.run([PYTHON, '-c', code], capture_output=True, text=True, timeout=600, env=env(), cwd=d)
    assert p.returncode == 0, p.stderr
    seen = json.loads(p.stdout.strip().splitlines()[-1])
    lines = [s[0] for s in seen]
    assert sum('accepted and ignored' in ln and 'MXBF' in ln for ln in lines) == 1
    # the first branch's lines: LAB 1 (the start) and LAB 2 (a BP) while it computes
    lab = [s for s in seen if s[0].startswith('BR    1') and 'LAB    2' in s[0]]
    assert lab and 'T = ' in lab[0][0]
    end = [s for s in seen if s[0].startswith('branch 1:')][0]
    # when the LAB 2 line came, the files held fewer points than at the end
    assert 0 < lab[0][1] < end[1] == 12


def test_two_writers_of_one_name_do_not_mix(tmp_path, reference):
    """The second writer waits for the first and its files are the result
    (before, each process renamed its three files when it ended: the longer
    first run overwrote the second's, and a close finish mixed them)."""
    d = knot_dir(tmp_path, 'two')
    a = start(d, ['c=knot72', 'NMX=%d' % NMX, 'sv=flat'])
    wait_rows(a, os.path.join(d, 'b.flat'), 2)
    b = subprocess.Popen([CABLE, 'run', 'c=knot72', 'NMX=5', 'sv=flat'], cwd=d, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env=env())
    out_b, err_b = b.communicate(timeout=900)
    assert a.wait(timeout=900) == 0 and b.returncode == 0, err_b
    assert 'waiting: another process is writing b.flat, s.flat, d.flat' in out_b
    assert len(check_files(d, 'flat', reference, ended=True)) == 5
    no_leftovers(d, 'flat')


@pytest.mark.parametrize('name,why', [('a/b', 'not a plain file name'), ('x' * 240, 'characters, at most')])
def test_bad_output_name_is_refused_before_computing(tmp_path, name, why):
    d = knot_dir(tmp_path, 'bad')
    p = subprocess.run([CABLE, 'run', 'c=knot72', 'NMX=%d' % NMX, 'sv=' + name], cwd=d, capture_output=True,
                       text=True, env=env(), timeout=600)
    assert p.returncode == 1
    assert 'sv' in p.stderr and why in p.stderr
    assert 'BR ' not in p.stdout and 'branch 1' not in p.stdout   # nothing was computed
    code = "import cable\ntry:\n    cable.run(e='braid_knot', c='knot72', sv=%r)\nexcept cable.CableError as e:\n" \
           "    print('refused:', e)\n" % name
    p = subprocess.run([PYTHON, '-c', code], capture_output=True, text=True, timeout=600, env=env(), cwd=d)
    assert 'refused:' in p.stdout and why in p.stdout and 'BR ' not in p.stdout


def bratu_with(tmp_path, line):
    """tests/data/autoeq/bratu_f90 with line added at the top of FUNC."""
    d = tmp_path / 'eq'
    d.mkdir()
    src = os.path.join(ROOT, 'tests/data/autoeq/bratu_f90')
    shutil.copy(os.path.join(src, 'c.bratu'), d)
    with open(os.path.join(src, 'bratu.f90')) as f:
        text = f.read()
    text = text.replace('  F(1) = U(2)\n', '  %s\n  F(1) = U(2)\n' % line, 1)
    (d / 'bratu.f90').write_text(text)
    return str(d)


@pytest.mark.parametrize('stmt', ['STOP', 'ERROR STOP'])
@pytest.mark.parametrize('how', ['run', 'replay'])
def test_fortran_stop_in_func_is_reported_with_files(tmp_path, stmt, how):
    # lambda passes 1.5 after the UZ at 1 (PT 8 of this branch)
    d = bratu_with(tmp_path, 'IF (PAR(1) > 1.5D0) %s' % stmt)
    if how == 'run':
        p = subprocess.run([CABLE, 'run', 'bratu', 'sv=bratu'], cwd=d, capture_output=True, text=True, env=env(),
                           timeout=600)
    else:
        (tmp_path / 'eq' / 'k.auto').write_text("r = run('bratu', sv='bratu')\nprint('not reached')\n")
        p = subprocess.run([CABLE, 'replay', 'k.auto'], cwd=d, capture_output=True, text=True, env=env(),
                           timeout=600)
    assert p.returncode != 0
    assert re.search(r'the FUNC routine of equation file (\./)?bratu\.f90 ended the process', p.stderr)
    assert "during branch 1 of e='bratu'" in p.stderr and 'the points so far are in b.bratu' in p.stderr
    assert 'not reached' not in p.stdout
    got = auto_read(d, 'bratu')
    lab = [r for r in got['rows'] if r[1]]
    assert [r[1] for r in lab] == [s[0] for s in got['sols']] and len(got['rows']) >= 8
    assert any(r[2] == -4 for r in lab)   # the UZ at lambda = 1 is on disk


def test_plugin_fatal_return_ends_cable_run_nonzero(tmp_path):
    d = tmp_path / 'plug'
    d.mkdir()
    shutil.copy(os.path.join(ROOT, 'tests/data/autoeq/bratu_c/c.bratu'), d)
    with open(os.path.join(ROOT, 'tests/plugins/bratu_plugin.c')) as f:
        src = f.read().replace('  double lambda = par[0];\n', '  double lambda = par[0];\n  if (lambda > 1.5) return -3;\n', 1)
    (d / 'fatal_src.txt').write_text(src)
    subprocess.run(['cc', '-shared', '-fPIC', '-x', 'c', '-I', os.path.join(ROOT, 'include'), 'fatal_src.txt',
                    '-o', 'fatal.so', '-lm'], cwd=str(d), check=True)
    p = subprocess.run([CABLE, 'run', 'e=fatal', 'c=bratu', 'sv=f'], cwd=str(d), capture_output=True, text=True,
                       env=env(), timeout=600)
    assert p.returncode == 1
    assert 'the FUNC routine of plug-in ./fatal.so returned -3 (fatal)' in p.stderr
    assert 'are in b.f, s.f, d.f' in p.stderr


@pytest.mark.parametrize('stmt,sig,text', [('abort();', signal.SIGABRT, 'aborted the process (SIGABRT'),
                                           ('*(volatile int *)0 = 1;', signal.SIGSEGV, 'crashed (SIGSEGV'),
                                           ('exit(0);', None, 'ended the process with exit status 0')])
def test_c_equation_file_that_ends_the_process_is_named(tmp_path, stmt, sig, text):
    d = tmp_path / 'ceq'
    d.mkdir()
    src = os.path.join(ROOT, 'tests/data/autoeq/bratu_c')
    shutil.copy(os.path.join(src, 'c.bratu'), d)
    with open(os.path.join(src, 'bratu.c')) as f:
        code = f.read()
    code = code.replace('  f[0] = u[1];\n', '  if (par[0] > 1.5) { %s }\n  f[0] = u[1];\n' % stmt, 1)
    code = code.replace('#include "auto_f2c.h"\n', '#include "auto_f2c.h"\n#include <stdlib.h>\n', 1)
    (d / 'bratu.c').write_text(code)
    p = subprocess.run([CABLE, 'run', 'bratu', 'sv=bratu'], cwd=str(d), capture_output=True, text=True, env=env(),
                       timeout=600)
    assert p.returncode == (-sig if sig else 1), (p.returncode, p.stderr)
    assert re.search(r'the FUNC routine of equation file (\./)?bratu\.c ' + re.escape(text), p.stderr), p.stderr
    assert 'the points so far are in b.bratu, s.bratu, d.bratu' in p.stderr
    got = auto_read(str(d), 'bratu')
    assert [r[1] for r in got['rows'] if r[1]] == [s[0] for s in got['sols']] and len(got['rows']) >= 8


def test_progress_line_on_a_terminal_names_the_parameter(tmp_path):
    """The live progress line (stderr, when it is a terminal) names the
    continuation parameter as the user wrote it (T), not PAR(1)."""
    import pty
    d = knot_dir(tmp_path, 'tty')
    master, slave = pty.openpty()
    p = subprocess.Popen([CABLE, 'run', 'c=knot72', 'NMX=4', 'sv=flat'], cwd=d, stdout=subprocess.DEVNULL,
                         stderr=slave, env=env())
    os.close(slave)
    chunks = []
    while True:
        try:
            data = os.read(master, 4096)
        except OSError:   # the terminal closed with the process
            break
        if not data:
            break
        chunks.append(data)
    os.close(master)
    assert p.wait(timeout=600) == 0
    text = b''.join(chunks).decode(errors='replace')
    assert 'point     2  T = ' in text and 'PAR(1)' not in text, text
