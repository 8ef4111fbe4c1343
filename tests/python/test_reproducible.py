# SPDX-License-Identifier: GPL-3.0-or-later
"""Replays are reproducible (issue 25, item 5): a short link scene (the
flat left-handed (10,2) link of runs/link102 on a coarse mesh to its first
branch point, and a branch switched there with a user zero) replayed by
`cable replay` several times on this machine writes byte-identical files:

  - twice in the same conditions;
  - with two other processes keeping both cores busy (the team's threads and
    the BLAS then run at other moments and in another order);
  - with NTHREADS=1 instead of the default, 2 on a machine with two cores
    (doc/engine.md promises the same results for every thread count);
  - with glibc's MALLOC_PERTURB_ (freshly allocated and freed heap memory
    filled with a byte pattern): a result that read uninitialised heap
    memory would change.

Every file the replay writes is compared (b., s., d. and the tables), not
only the numbers a scene prints."""
import os
import subprocess
import sys

from conftest import BUILD, copy_in

SCRIPT = """flat = run(e='braid_link', c='link102', NTST=40, NMX=35, NPR=10, sv='flat')
bp = flat('BP1')
mode = run(bp, e='braid_link', c='link102mode', NTST=40, NMX=25, NPR=5, UZR={'T': %s}, sv='mode')
branch_table('mode_table.txt', mode)
"""


def _replay(work, name, env_extra=None, threads=None):
    d = os.path.join(str(work), name)
    os.mkdir(d)
    for f in ('c.link102', 'c.link102mode'):
        with open(os.path.join(str(work), f)) as src, open(os.path.join(d, f), 'w') as dst:
            text = src.read()
            if threads is not None:
                text += '\nNTHREADS = %d\n' % threads
            dst.write(text)
    with open(os.path.join(d, 'r.auto'), 'w') as f:
        f.write(SCRIPT % 'bp[\'T\'] + 0.5')
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
    env.pop('OPENBLAS_NUM_THREADS', None)
    env.pop('CABLE_BLAS_THREADS', None)
    env.update(env_extra or {})
    p = subprocess.run([os.path.join(BUILD, 'cable'), 'replay', 'r.auto'], cwd=d, env=env, capture_output=True,
                       text=True, timeout=1800)
    assert p.returncode == 0, p.stdout + p.stderr
    files = {}
    for n in sorted(os.listdir(d)):
        if n in ('r.auto', 'c.link102', 'c.link102mode'):
            continue
        with open(os.path.join(d, n), 'rb') as f:
            files[n] = f.read()
    return files


def _same(a, b, what):
    assert sorted(a) == sorted(b), (what, sorted(a), sorted(b))
    differ = [n for n in a if a[n] != b[n]]
    assert not differ, '%s: files differ: %s' % (what, differ)


def test_replays_are_byte_identical(work):
    copy_in(work, 'runs/link102/c.link102', 'runs/link102/c.link102mode')
    first = _replay(work, 'one')
    assert {'b.flat', 's.flat', 'd.flat', 'b.mode', 's.mode', 'd.mode', 'mode_table.txt'} <= set(first)
    assert b'UZ' in first['b.mode'] or b'  -4 ' in first['b.mode']   # the user zero was located
    _same(first, _replay(work, 'two'), 'the same replay again')
    load = [subprocess.Popen([sys.executable, '-c', 'while True: pass']) for _ in range(2)]
    try:
        _same(first, _replay(work, 'loaded'), 'with two busy processes')
    finally:
        for p in load:
            p.kill()
            p.wait()
    _same(first, _replay(work, 'one_thread', threads=1), 'NTHREADS = 1')
    if (os.cpu_count() or 1) < 2:   # the default is 1 thread here: compare with 2 as well
        _same(first, _replay(work, 'two_threads', threads=2), 'NTHREADS = 2')
    _same(first, _replay(work, 'perturbed', {'MALLOC_PERTURB_': '165'}), 'MALLOC_PERTURB_=165')
