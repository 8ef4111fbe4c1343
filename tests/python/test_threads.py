# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python package from threads (doc/scripts.md, Threads): concurrent
run() calls on one runner (the module's own, cable.run) run one after the
other, and every one of them gives the branch a run alone gives; separate
runners run in separate threads at the same time with the same results.

Each case runs in a child interpreter: before the runner took a lock, two
threads calling cable.run() aborted the interpreter ("Fatal Python error:
PyEval_RestoreThread"), which would take pytest down with it.  Bratu's
branch (runs/bratu/c.bratu) is deterministic: a run gives the same numbers
bit for bit whatever else runs, so results are compared exactly."""
import os
import subprocess

from conftest import BUILD, PYTHON, copy_in

# Prints, per run, the principal parameter and L2-NORM columns (repr: every bit).
PRELUDE = r'''
import sys, threading
import cable
NMX = int(sys.argv[1])
def columns(r):
    return (tuple(float(x) for x in r['lambda']), tuple(float(x) for x in r['L2-NORM']))
def check(results, errors, n):
    if errors:
        print('ERRORS', errors)
    print('RUNS', len(results), 'OF', n)
    print('DISTINCT', len(set(results)))
    print('SERIAL', columns(cable.Runner().run(e='bratu', c='bratu', NMX=NMX)) in set(results))
'''

MODULE_RUNNER = PRELUDE + r'''
results, errors = [], []
def job():
    try:
        for _ in range(3):
            results.append(columns(cable.run(e='bratu', c='bratu', NMX=NMX)))
    except BaseException as e:
        errors.append(repr(e))
threads = [threading.Thread(target=job) for _ in range(4)]
for t in threads: t.start()
for t in threads: t.join()
check(results, errors, 12)
'''

SEPARATE_RUNNERS = PRELUDE + r'''
results, errors = [], []
def job(k):
    try:
        r = cable.Runner()
        for i in range(3):
            results.append(columns(r.run(e='bratu', c='bratu', NMX=NMX, sv='t%d_%d' % (k, i))))
    except BaseException as e:
        errors.append(repr(e))
threads = [threading.Thread(target=job, args=(k,)) for k in range(4)]
for t in threads: t.start()
for t in threads: t.join()
check(results, errors, 12)
import os
print('FILES', all(os.path.exists('%s.t%d_%d' % (x, k, i)) for x in 'bsd' for k in range(4) for i in range(3)))
'''

# One runner shared by threads that run, read its constants (pr) and load at once.
MIXED = PRELUDE + r'''
r = cable.Runner()
results, errors = [], []
def runs():
    try:
        for _ in range(4):
            results.append(columns(r.run(e='bratu', c='bratu', NMX=NMX)))
    except BaseException as e:
        errors.append(repr(e))
def reads():
    try:
        for _ in range(200):
            r.session.constants()
    except BaseException as e:
        errors.append(repr(e))
threads = [threading.Thread(target=runs) for _ in range(2)] + [threading.Thread(target=reads) for _ in range(2)]
for t in threads: t.start()
for t in threads: t.join()
check(results, errors, 8)
'''


def child(work, code, nmx=40):
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'), OPENBLAS_NUM_THREADS='1')
    p = subprocess.run([PYTHON, '-c', code, str(nmx)], capture_output=True, text=True, timeout=600, env=env,
                       cwd=str(work))
    return p.returncode, p.stdout, p.stderr


def lines(out):
    return [l for l in out.splitlines() if l.split(' ')[0] in ('ERRORS', 'RUNS', 'DISTINCT', 'SERIAL', 'FILES')]


def test_module_runner_from_threads(work):
    copy_in(work, 'runs/bratu/c.bratu')
    rc, out, err = child(work, MODULE_RUNNER)
    assert rc == 0, err[-2000:]
    assert 'Fatal Python error' not in err
    assert lines(out) == ['RUNS 12 OF 12', 'DISTINCT 1', 'SERIAL True']


def test_separate_runners_in_threads(work):
    copy_in(work, 'runs/bratu/c.bratu')
    rc, out, err = child(work, SEPARATE_RUNNERS)
    assert rc == 0, err[-2000:]
    assert lines(out) == ['RUNS 12 OF 12', 'DISTINCT 1', 'SERIAL True', 'FILES True']


def test_one_runner_runs_and_reads_from_threads(work):
    copy_in(work, 'runs/bratu/c.bratu')
    rc, out, err = child(work, MIXED)
    assert rc == 0, err[-2000:]
    assert lines(out) == ['RUNS 8 OF 8', 'DISTINCT 1', 'SERIAL True']
