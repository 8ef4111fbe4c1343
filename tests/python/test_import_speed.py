# SPDX-License-Identifier: GPL-3.0-or-later
"""`import cable` runs as fast as the cable program (issue 26, item 5).

The same braid run (the flat (7,2) knot, 24 steps) by `cable run` and inside
a fresh `import cable` host (plain python3 with numpy, a Jupyter (IPython)
kernel, and a Dask worker),
with the environment's OPENBLAS_NUM_THREADS removed as a user's shell has
it: the CPU time of the run inside Python may exceed the program's by at most
20 %.  Before libcable.so and the extension carried their own one-thread BLAS
(continuation/base/blas_private.c) the threaded OpenBLAS shared with numpy spun
its threads: 6.4 s of CPU against 1.6 s on this run (2 cores).  CPU times
are taken as the best of three runs each, interleaved, so that a burst of
load on the shared machine hits both sides alike.  The host's own BLAS keeps
its thread count (numpy's OpenBLAS is not changed by importing cable), and
both runs give the same b-file rows bit for bit."""
import os
import resource
import shutil
import subprocess

import pytest

from conftest import BUILD, ROOT, PYTHON

NMX = 24
RUN_KW = "e='braid_knot', c='knot72', NMX=%d" % NMX

CHILD = r'''
import sys, time
import numpy
import cable
t0 = time.process_time()
cable.run(%s, sv=sys.argv[1])
print('CPU %%.6f' %% (time.process_time() - t0))
''' % RUN_KW


def _env():
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'))
    for k in ('OPENBLAS_NUM_THREADS', 'OMP_NUM_THREADS', 'GOTO_NUM_THREADS', 'CABLE_BLAS_THREADS'):
        env.pop(k, None)
    return env


def _cli_cpu(work, name):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([os.path.join(BUILD, 'cable'), 'run', 'c=knot72', 'e=braid_knot', 'NMX=%d' % NMX,
                    'sv=' + name], cwd=str(work), env=_env(), check=True, capture_output=True, timeout=600)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def _py_cpu(work, name):
    p = subprocess.run([PYTHON, '-c', CHILD, name], cwd=str(work), env=_env(), check=True, capture_output=True,
                       text=True, timeout=600)
    return float([ln for ln in p.stdout.splitlines() if ln.startswith('CPU ')][-1].split()[1])


def _rows(path):
    """The b-file's point rows (its header names the sv= file)."""
    with open(path) as f:
        return [ln for ln in f if ln.split() and ln.split()[0] != '0']


@pytest.fixture
def knot(work):
    shutil.copy(os.path.join(ROOT, 'runs/knot72/c.knot72'), str(work))
    return work


def test_import_cable_as_fast_as_the_program(knot):
    cli, py = [], []
    for k in range(3):
        cli.append(_cli_cpu(knot, 'cli%d' % k))
        py.append(_py_cpu(knot, 'py%d' % k))
    print('CPU s, cable run: %s; import cable: %s' % (cli, py))
    assert min(py) <= 1.2 * min(cli), 'import cable: %.2f s CPU, cable run: %.2f s' % (min(py), min(cli))
    assert _rows(os.path.join(str(knot), 'b.py0')) == _rows(os.path.join(str(knot), 'b.cli0'))


def test_host_blas_untouched(work):
    """numpy's threaded OpenBLAS keeps the thread count the host gave it."""
    code = r'''
import ctypes, ctypes.util, numpy
lib = None
for name in ('libopenblas.so.0', 'libblas.so.3'):
    try:
        l = ctypes.CDLL(name, mode=getattr(__import__('os'), 'RTLD_NOLOAD', 4))
        l.openblas_get_num_threads
        lib = l
        break
    except (OSError, AttributeError):
        pass
if lib is None:
    print('NOOPENBLAS')
else:
    lib.openblas_set_num_threads(2)
    import cable
    print('THREADS', lib.openblas_get_num_threads())
'''
    p = subprocess.run([PYTHON, '-c', code], env=_env(), check=True, capture_output=True, text=True, timeout=120)
    if 'NOOPENBLAS' in p.stdout:
        pytest.skip("numpy's BLAS is not OpenBLAS here")
    assert 'THREADS 2' in p.stdout, p.stdout


KERNEL_CLIENT = r'''
import sys
import jupyter_client
code = sys.stdin.read()
km = jupyter_client.KernelManager(kernel_name='python3')
km.start_kernel(cwd=sys.argv[1])
try:
    kc = km.client()
    kc.start_channels()
    kc.wait_for_ready(timeout=120)
    out = []

    def hook(msg):
        if msg['msg_type'] == 'stream' and msg['content']['name'] == 'stdout':
            out.append(msg['content']['text'])
    reply = kc.execute_interactive(code, output_hook=hook, timeout=600)
    kc.stop_channels()
finally:
    km.shutdown_kernel(now=True)
if reply['content']['status'] != 'ok':
    sys.exit('kernel: %r' % (reply['content'],))
print(''.join(out))
'''


def _kernel_cpu(work, name):
    """The run in a fresh IPython kernel, driven by a client in a child
    interpreter: a Jupyter client in pytest's own process can hang on the
    event loop an earlier test (Dask's in-process client) left behind."""
    code = CHILD.replace('sys.argv[1]', repr(name))
    p = subprocess.run([PYTHON, '-c', KERNEL_CLIENT, str(work)], input=code, env=_env(), check=True,
                       capture_output=True, text=True, timeout=900)
    return float([ln for ln in p.stdout.splitlines() if ln.startswith('CPU ')][-1].split()[1])


def test_jupyter_kernel_as_fast_as_the_program(knot):
    """The same in an IPython kernel (what a notebook runs), started as
    Jupyter starts it."""
    pytest.importorskip('jupyter_client')
    pytest.importorskip('ipykernel')
    cli, py = [], []
    for k in range(3):
        cli.append(_cli_cpu(knot, 'cli%d' % k))
        py.append(_kernel_cpu(knot, 'kernel%d' % k))
    print('CPU s, cable run: %s; Jupyter kernel: %s' % (cli, py))
    assert min(py) <= 1.2 * min(cli), 'Jupyter kernel: %.2f s CPU, cable run: %.2f s' % (min(py), min(cli))


def test_dask_worker_as_fast_as_the_program(knot):
    distributed = pytest.importorskip('distributed')

    def task(path, name):
        import os as _os
        import time as _time
        _os.chdir(path)
        import cable as _cable
        t0 = _time.process_time()
        _cable.run(e='braid_knot', c='knot72', NMX=NMX, sv=name)
        return _time.process_time() - t0

    saved = {k: os.environ.pop(k) for k in ('OPENBLAS_NUM_THREADS', 'OMP_NUM_THREADS', 'GOTO_NUM_THREADS',
                                            'CABLE_BLAS_THREADS') if k in os.environ}
    try:
        with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None,
                                      env={'PYTHONPATH': os.path.join(BUILD, 'python')}) as cluster, \
                distributed.Client(cluster) as client:
            cli, py = [], []
            for k in range(3):
                cli.append(_cli_cpu(knot, 'cli%d' % k))
                py.append(client.submit(task, str(knot), 'dask%d' % k, pure=False).result(timeout=600))
    finally:
        os.environ.update(saved)
    print('CPU s, cable run: %s; Dask worker: %s' % (cli, py))
    assert min(py) <= 1.2 * min(cli), 'Dask worker: %.2f s CPU, cable run: %.2f s' % (min(py), min(cli))
