# SPDX-License-Identifier: GPL-3.0-or-later
"""cable.atlas (doc/atlas.md): a tiny sweep (the (3,2) knot and the (4,2)
link, one Delta, mode 1, a coarse mesh) on a local Dask cluster of two
workers; the same sweep interrupted and resumed (on a cluster of `dask
scheduler` and `dask worker` reached by its address) recomputes nothing
finished;
a worker killed during a task leaves the sweep complete with every finished
row intact; bad sweep files are refused before any task starts."""
import json
import os
import signal
import subprocess
import time

import pytest

from cable import atlas, atlas_task

from conftest import BUILD, PYTHON

TINY = """\
# the tiny sweep of tests/python/test_atlas.py
deltas = [0.005]
modes = [1]

[[family]]
kind = "knot"
p = [3]

[[family]]
kind = "link"
p = [4]

[mesh]
NTST = 30
NCOL = 4

[flat]
DSMAX = 10.0

[branch]
NMX = 30
NPR = 10
"""

# Lk = Tw + Wr of a closed ribbon: a half-integer for a knot, an integer for
# a link; on the flat (p,2) braid and on the branch from its branch point
# until the axis passes through itself it is hand x p/2.  The quadrature of
# Tw and Wr on NTST = 30 is far better than 0.01; a wrong topology is off by 1.
LK_TOL = 0.01
TIMEOUT = 600


def _write(work, text, name='tiny.toml'):
    p = os.path.join(str(work), name)
    with open(p, 'w') as f:
        f.write(text)
    return p


def _env():
    return dict(os.environ, PYTHONPATH=os.path.join(BUILD, 'python'), PYTHONDONTWRITEBYTECODE='1')


def _start(path, workers=2, scheduler=None, env=None):
    how = ['--scheduler', scheduler] if scheduler else ['--workers', str(workers)]
    return subprocess.Popen([PYTHON, '-m', 'cable.atlas', path] + how, env=dict(_env(), **(env or {})),
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


class _Cluster:
    """A Dask cluster as on a real machine: `dask scheduler` and one
    single-threaded `dask worker`, separate processes, stopped at the end."""

    def __init__(self, work):
        self.file = os.path.join(str(work), 'scheduler.json')
        log = open(os.path.join(str(work), 'cluster.log'), 'w')
        self.procs = [subprocess.Popen(['dask', 'scheduler', '--scheduler-file', self.file, '--host', '127.0.0.1',
                                        '--port', '0', '--no-dashboard'], env=_env(), stdout=log, stderr=log)]
        t0 = time.time()
        while not os.path.exists(self.file) and time.time() - t0 < 120:
            time.sleep(0.1)
        time.sleep(0.2)
        with open(self.file) as f:
            self.address = json.load(f)['address']
        self.procs.append(subprocess.Popen(['dask', 'worker', self.address, '--nthreads', '1', '--nworkers', '1',
                                            '--no-dashboard', '--local-directory', str(work)], env=_env(),
                                           stdout=log, stderr=log))

    def stop(self):
        for p in reversed(self.procs):
            p.terminate()
        for p in self.procs:
            try:
                p.wait(timeout=30)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()


def _finish(proc):
    out, err = proc.communicate(timeout=TIMEOUT)
    return proc.returncode, out, err


def _results(sweep):
    """{task name: bytes of result.json} of the finished tasks."""
    out = {}
    for t in sweep.tasks:
        p = os.path.join(sweep.output, 'tasks', t.name, 'result.json')
        if os.path.exists(p):
            with open(p, 'rb') as f:
                out[t.name] = f.read()
    return out


def _wait_for(cond, proc, what):
    t0 = time.time()
    while not cond():
        if proc.poll() is not None:
            return False
        if time.time() - t0 > TIMEOUT:
            pytest.fail('timed out waiting for %s' % what)
        time.sleep(0.1)
    return True


def _check_rows(sweep):
    rows = atlas.read_csv(os.path.join(sweep.output, 'atlas.csv'))
    by_family = {}
    for r in rows:
        by_family.setdefault(r['family'], []).append(r)
    assert sorted(by_family) == ['knot(3,2)', 'link(4,2)']
    for fam, rs in by_family.items():
        kind, p, hand = ('knot', 3, 1) if fam.startswith('knot') else ('link', 4, -1)
        for r in rs:
            assert r['status'] == 'ok', r
            assert (r['kind'], int(r['p']), int(r['hand'])) == (kind, p, hand)
            assert float(r['Delta']) == 0.005 and int(r['mode']) == 1
            # the knotting arm: a knot's own handedness, a link's opposite (T > 0 for both here)
            assert int(r['arm']) == 1 and float(r['bp_T']) > 0
            assert float(r['wall']) > 0
        first = rs[0]
        # the branch's first stretch: no axis self-passage yet, the flat braid's Lk and an unknotted axis
        assert int(first['segment']) == 0 and abs(float(first['passages'])) < LK_TOL
        assert abs(float(first['Lk']) - hand * p / 2) < LK_TOL
        assert first['companion'] == 'unknot' and int(first['crossings']) == 0
        # Lk inside the tube = Lk minus the writhe of the companion's minimal diagram (0 for the unknot)
        assert abs(float(first['Lk_tube']) - float(first['Lk'])) < 1e-12
        # every knot BP is double (D_p symmetry, p odd); the (4,2) link's mode 1 is its p/2-fold
        # pattern, which splits into two simple BPs (doc/links.md, 2)
        assert int(first['bp_multiplicity']) == (2 if kind == 'knot' else 1)
        assert first['formulation'] == ('braid_knot_sym' if kind == 'knot' else 'braid_link')
        # the first point of the stretch is the branch point; the tubes are apart there
        assert int(first['overlap_free']) == 1 and float(first['T_free']) == float(first['bp_T'])
        assert float(first['dmin']) > 1.0
    return rows


def test_tiny_sweep_interrupted_and_resumed(work):
    path = _write(work, TINY)
    sweep = atlas.load(path)
    assert len(sweep.tasks) == 2
    proc = _start(path)
    # interrupt (Ctrl-C) as soon as the first task has finished
    _wait_for(lambda: _results(sweep), proc, 'a finished task')
    if proc.poll() is None:
        proc.send_signal(signal.SIGINT)
    rc, out, err = _finish(proc)
    before = _results(sweep)
    assert before, err
    assert rc in (0, 130), err
    # resumed on a cluster reached by its scheduler's address
    cluster = _Cluster(work)
    try:
        rc, out, err = _finish(_start(path, scheduler=cluster.address))
    finally:
        cluster.stop()
    assert rc == 0, err
    after = _results(sweep)
    assert len(after) == 2
    for name, data in before.items():   # finished before the interruption: not recomputed, not rewritten
        assert after[name] == data, name
    assert '%d finished earlier, %d computed (0 failed)' % (len(before), 2 - len(before)) in out, out
    rows = _check_rows(sweep)
    # a third run: everything is finished, nothing is computed, the table is the same
    with open(os.path.join(sweep.output, 'atlas.csv')) as f:
        table = f.read()
    rc, out, err = _finish(_start(path))
    assert rc == 0 and '2 finished earlier, 0 computed' in out, out + err
    assert _results(sweep) == after
    with open(os.path.join(sweep.output, 'atlas.csv')) as f:
        assert f.read() == table
    assert len(rows) >= 2
    with open(os.path.join(sweep.output, 'summary.svg')) as f:
        svg = f.read()
    # drawn by matplotlib (text kept as text), the families as its labels
    assert '<svg' in svg and 'Matplotlib' in svg, svg[:300]
    assert 'knot(3,2) R' in svg and 'link(4,2) L' in svg
    for t in sweep.tasks:   # each task's b./s./d. files
        for f in ('b.flat', 's.flat', 'd.flat', 'b.branch', 's.branch', 'd.branch', 'c.flat', 'c.branch'):
            assert os.path.exists(os.path.join(sweep.output, 'tasks', t.name, f)), (t.name, f)
    assert not [n for n in os.listdir(os.path.join(sweep.output, 'tasks')) if n.startswith('.')]


def test_worker_killed_during_a_task(work):
    path = _write(work, TINY)
    sweep = atlas.load(path)
    tasks_dir = os.path.join(sweep.output, 'tasks')
    # each task waits at the gate (cable.atlas_task.GATE_VARIABLE) until its
    # file exists there: one task finishes, the other is killed while running
    gate = os.path.join(str(work), 'gate')
    os.makedirs(gate)
    proc = _start(path, env={atlas_task.GATE_VARIABLE: gate})
    state = {}

    def running():
        """{task name: pid} of the tasks with a partial directory and a pid."""
        out = {}
        for n in os.listdir(tasks_dir) if os.path.isdir(tasks_dir) else []:
            p = os.path.join(tasks_dir, n, 'pid')
            if n.startswith('.') and os.path.exists(p):
                try:
                    out[n[1:].split('.partial-')[0]] = int(open(p).read())
                except (ValueError, OSError):   # being written or just removed
                    pass
        return out

    def first_running():
        state['running'] = running()
        return bool(state['running'])

    assert _wait_for(first_running, proc, 'a running task'), _finish(proc)
    first = sorted(state['running'])[0]
    open(os.path.join(gate, first), 'w').close()

    def first_done_other_running():
        state['done'] = _results(sweep)
        state['running'] = running()
        return first in state['done'] and state['running']

    assert _wait_for(first_done_other_running, proc, 'a finished and a running task'), _finish(proc)
    assert list(state['done']) == [first]
    (killed, pid), = state['running'].items()
    os.kill(pid, signal.SIGKILL)
    open(os.path.join(gate, killed), 'w').close()
    rc, out, err = _finish(proc)
    assert rc == 0, err
    after = _results(sweep)
    assert sorted(after) == sorted([first, killed])
    assert after[first] == state['done'][first]
    for name, data in after.items():
        assert json.loads(data)['status'] == 'ok', name
    _check_rows(sweep)
    # the retried task ran in another worker process and has its rows
    assert json.loads(after[killed])['rows']
    assert not [n for n in os.listdir(tasks_dir) if n.startswith('.')]


BAD = [
    # (what is wrong, text replaced, by what, line and key in the message)
    ('unknown top-level key', 'modes = [1]\n', 'modes = [1]\nmodez = [2]\n', 'tiny.toml:4: modez: unknown key'),
    ('unknown family key', 'p = [3]\n', 'p = [3]\nhand = 1\n', 'tiny.toml:8: family[1].hand: unknown key'),
    ('even knot', 'p = [3]\n', 'p = [3, 4]\n', 'tiny.toml:7: family[1].p: no (4,2) torus knot'),
    ('odd link', 'p = [4]\n', 'p = [5]\n', 'tiny.toml:11: family[2].p: no (5,2) torus link'),
    ('Delta beyond contact', 'deltas = [0.005]', 'deltas = [0.005, 0.2]', 'tiny.toml:2: deltas: Delta = 0.2 is impossible for a knot'),
    ('mode 0', 'modes = [1]', 'modes = [0]', 'tiny.toml:3: modes: a mode is'),
    ('unknown constant', 'NMX = 30\n', 'NMX = 30\nNTSR = 3\n', 'tiny.toml:22: branch.NTSR: unknown key'),
    ('bad mesh', 'NCOL = 4', 'NCOL = 9', 'tiny.toml:15: mesh.NCOL: out of range'),
    ('not TOML', 'NCOL = 4', 'NCOL = = 4', 'tiny.toml: not a TOML file'),
]


@pytest.mark.parametrize('what,old,new,msg', BAD, ids=[b[0] for b in BAD])
def test_bad_sweep_file(work, what, old, new, msg):
    assert old in TINY
    path = _write(work, TINY.replace(old, new, 1))
    with pytest.raises(atlas.SweepError) as e:
        atlas.load(path)
    assert msg in str(e.value), str(e.value)
    # the command line (cable atlas) says the same, exits non-zero and starts nothing
    p = subprocess.run([os.path.join(BUILD, 'cable'), 'atlas', path, '--workers', '1'], capture_output=True,
                       text=True, timeout=120)
    assert p.returncode == 1 and p.stderr.startswith('cable atlas: ') and msg in p.stderr, p.stderr
    assert not os.path.exists(os.path.join(str(work), 'tiny'))


def test_task_keys_follow_inputs(work):
    """A task's key is a hash of its inputs: the same sweep gives the same
    keys, a changed mesh or constant changes every key, a reordered file
    does not."""
    k1 = [t.key for t in atlas.load(_write(work, TINY)).tasks]
    assert [t.key for t in atlas.load(_write(work, TINY, 'b.toml')).tasks] == k1
    k2 = [t.key for t in atlas.load(_write(work, TINY.replace('NMX = 30', 'NMX = 31'), 'c.toml')).tasks]
    assert not set(k1) & set(k2)
    swapped = TINY.replace('[flat]\nDSMAX = 10.0\n\n', '') + '\n[flat]\nDSMAX = 10.0\n'
    assert sorted(t.key for t in atlas.load(_write(work, swapped, 'd.toml')).tasks) == sorted(k1)
    assert len(set(k1)) == 2


def test_failing_task_is_recorded(work):
    """A task whose flat branch stops before its branch point (NMX = 2)
    records the error as its result; the table lists it as failed."""
    path = _write(work, TINY.replace('DSMAX = 10.0', 'DSMAX = 10.0\nNMX = 2').replace('p = [4]', 'p = [6]'))
    sweep = atlas.load(path)
    t = sweep.tasks[0]
    r = atlas.run_task(t.inputs, t.name, sweep.output)
    assert r['status'] == 'failed' and r['rows'] == []
    assert 'no branch point 1' in r['error'] and 'NMX = 2' in r['error'], r['error']
    d = os.path.join(sweep.output, 'tasks', t.name)
    with open(os.path.join(d, 'result.json')) as f:
        assert json.load(f)['error'] == r['error']
    assert os.path.exists(os.path.join(d, 'b.flat')) and 'Traceback' in open(os.path.join(d, 'log.txt')).read()
    # finished (failed) tasks are not run again: the same call returns the recorded result
    assert atlas.run_task(t.inputs, t.name, sweep.output) == r
    rows = atlas.write_outputs(sweep)
    assert len(rows) == 1 and rows[0]['status'] == 'failed' and rows[0]['task'] == t.name
    table = atlas.read_csv(os.path.join(sweep.output, 'atlas.csv'))
    assert table[0]['status'] == 'failed' and table[0]['error'] == r['error'] and table[0]['Lk'] == ''


def _openblas_threads():
    """OpenBLAS's thread count in this process (None: no OpenBLAS loaded)."""
    import ctypes
    for lib in ('libblas.so.3', 'libopenblas.so.0'):
        try:
            h = ctypes.CDLL(lib, mode=os.RTLD_NOLOAD | os.RTLD_LAZY)
        except OSError:
            continue
        f = getattr(h, 'openblas_get_num_threads', None)
        if f is not None:
            return f()
    return None


def test_task_runs_on_one_core(work, monkeypatch):
    """A task is one core's work (doc/atlas.md, 7): its runs have NTHREADS = 1
    (not an input of its key: the engine's results are the same for every
    NTHREADS), the process's OpenBLAS is asked for one thread (a threaded one
    spun on the shared cores), and result.json splits the task's wall time
    into its stages."""
    from cable import _cable
    monkeypatch.delenv('CABLE_BLAS_THREADS', raising=False)
    before = _openblas_threads()
    path = _write(work, TINY.replace('p = [4]', 'p = [6]').replace('NMX = 30', 'NMX = 4'))
    sweep = atlas.load(path)
    assert all('NTHREADS' not in t.inputs['flat'] and 'NTHREADS' not in t.inputs['branch'] for t in sweep.tasks)
    t = sweep.tasks[0]
    r = atlas.run_task(t.inputs, t.name, sweep.output)
    assert r['status'] == 'ok', r['error']
    d = os.path.join(sweep.output, 'tasks', t.name)
    for c in ('c.flat', 'c.branch'):
        assert 'NTHREADS=1\n' in open(os.path.join(d, c)).read(), c
    if before is not None:   # OpenBLAS is this machine's BLAS (Debian's default alternative)
        assert _openblas_threads() == 1
        monkeypatch.setenv('CABLE_BLAS_THREADS', '2')   # the user's override, as for the cable program
        _cable.blas_single_thread()
        assert _openblas_threads() == 2
        monkeypatch.delenv('CABLE_BLAS_THREADS')
        _cable.blas_single_thread()
        assert _openblas_threads() == 1
    times = r['times']
    assert set(times) == {'flat', 'branch', 'analysis', 'total'}
    assert all(v >= 0 for v in times.values()) and times['total'] == r['wall']
    # the flat branch is the shared one's (its own result.json), computed before the task
    with open(os.path.join(sweep.output, 'flat', r['flat'], 'result.json')) as f:
        assert times['flat'] == json.load(f)['wall']
    assert times['branch'] + times['analysis'] <= times['total']


def test_flat_branch_shared_by_modes(work):
    """A sweep computes a family's flat branch once per (family, Delta, arm),
    to its highest mode's branch point, as a keyed result of its own
    (OUT/flat/NAME), and each mode task starts from it.  The branch points
    are those of a flat run that stops at the task's own branch point (the
    run is the same up to there: equal bit for bit), and a resumed sweep
    reuses the flat branch."""
    path = _write(work, TINY.replace('modes = [1]', 'modes = [1, 2]').replace('p = [4]', 'p = [6]')
                  .replace('kind = "link"', 'kind = "knot"').replace('p = [6]', 'p = [5]')
                  .replace('NMX = 30', 'NMX = 6'))
    sweep = atlas.load(path)
    assert [(t.inputs['p'], t.inputs['mode']) for t in sweep.tasks] == [(3, 1), (3, 2), (5, 1), (5, 2)]
    flats = {t.flat.key for t in sweep.tasks}
    assert len(flats) == 2 and all(t.flat.inputs['bps'] == 2 for t in sweep.tasks)
    rc, out, err = _finish(_start(path, workers=1))
    assert rc == 0 and '4 computed (0 failed)' in out, out + err
    fdir = os.path.join(sweep.output, 'flat')
    assert sorted(os.listdir(fdir)) == sorted({t.flat.name for t in sweep.tasks})
    results = {t.name: json.loads(d) for t, d in zip(sweep.tasks, [_results(sweep)[t.name] for t in sweep.tasks])}
    for t in sweep.tasks:
        r = results[t.name]
        assert r['status'] == 'ok' and r['flat'] == t.flat.name
        with open(os.path.join(fdir, t.flat.name, 'result.json')) as f:
            flat = json.load(f)
        assert flat['status'] == 'ok' and len(flat['bps']) == 2
        bp = flat['bps'][t.inputs['mode'] - 1]
        assert r['rows'][0]['bp_T'] == bp['T'] and r['rows'][0]['bp_F'] == bp['F']
        assert r['rows'][0]['bp_multiplicity'] == 2 == (2 if bp['kind'] == 'double' else 1)
        # the flat run stopped at the task's own branch point (run_task alone) finds it bit for bit
        if t.inputs['mode'] == 1 and t.inputs['p'] == 3:
            alone = atlas.run_task(t.inputs, t.name, os.path.join(str(work), 'alone'))
            assert alone['flat'] != t.flat.name and alone['rows'][0]['bp_T'] == bp['T']
            assert alone['rows'][0]['bp_F'] == bp['F']
    # resumed after the flat branches (not the tasks) finished: the flat branches are not recomputed
    keep = {n: os.stat(os.path.join(fdir, n, 'result.json')).st_mtime_ns for n in os.listdir(fdir)}
    for t in sweep.tasks:
        import shutil
        shutil.rmtree(os.path.join(sweep.output, 'tasks', t.name))
    rc, out, err = _finish(_start(path, workers=1))
    assert rc == 0 and '0 finished earlier, 4 computed (0 failed)' in out, out + err
    assert {n: os.stat(os.path.join(fdir, n, 'result.json')).st_mtime_ns for n in os.listdir(fdir)} == keep
    for t in sweep.tasks:
        assert json.loads(_results(sweep)[t.name])['rows'][0]['bp_T'] == results[t.name]['rows'][0]['bp_T']


def test_flat_branch_without_its_files(work):
    """The repository keeps a sweep's result.json files, not its b./s./d.
    files: a sweep resumed in a fresh clone computes a finished flat branch
    again for its solutions, keeps its result.json, and refuses (the task
    fails, saying why) when the branch points differ from the kept ones."""
    path = _write(work, TINY)
    sweep = atlas.load(path)
    rc, out, err = _finish(_start(path, workers=1))
    assert rc == 0 and '2 computed (0 failed)' in out, out + err
    before = _results(sweep)
    fdir = os.path.join(sweep.output, 'flat')
    knot, link = sweep.tasks
    kept = {}
    for n in os.listdir(fdir):
        for f in os.listdir(os.path.join(fdir, n)):
            if f[:2] in ('b.', 's.', 'd.') or f == 'log.txt':
                os.remove(os.path.join(fdir, n, f))
        with open(os.path.join(fdir, n, 'result.json'), 'rb') as f:
            kept[n] = f.read()
    # a wrong kept branch point (another T) for the link's flat branch
    with open(os.path.join(fdir, link.flat.name, 'result.json')) as f:
        bad = json.load(f)
    bad['bps'][0]['T'] += 0.5
    with open(os.path.join(fdir, link.flat.name, 'result.json'), 'w') as f:
        json.dump(bad, f, indent=1)
    import shutil
    for t in sweep.tasks:
        shutil.rmtree(os.path.join(sweep.output, 'tasks', t.name))
    rc, out, err = _finish(_start(path, workers=1))
    assert rc == 1 and '2 computed (1 failed)' in out, out + err   # a failed task: exit status 1
    after = {t.name: json.loads(d) for t, d in zip(sweep.tasks, [_results(sweep)[t.name] for t in sweep.tasks])}
    assert after[knot.name]['status'] == 'ok'
    def rows(r):   # the computed fields (not the wall time)
        return [{k: v for k, v in row.items() if k != 'wall'} for row in r['rows']]

    assert rows(after[knot.name]) == rows(json.loads(before[knot.name]))
    with open(os.path.join(fdir, knot.flat.name, 'result.json'), 'rb') as f:
        assert f.read() == kept[knot.flat.name]
    assert os.path.exists(os.path.join(fdir, knot.flat.name, 's.flat'))
    assert after[link.name]['status'] == 'failed'
    assert 'other branch points than its result.json' in after[link.name]['error'], after[link.name]['error']
    assert not os.path.exists(os.path.join(fdir, link.flat.name, 's.flat'))
    assert not [n for n in os.listdir(fdir) if n.startswith('.')]
    # run again: nothing to compute, but the table still holds the failed
    # task: exit status 1 (it was 0, as if the atlas were complete)
    rc, out, err = _finish(_start(path, workers=1))
    assert rc == 1 and '2 finished earlier (1 of them failed' in out and '0 computed' in out, out + err


def test_switch_auto_on_a_cluster(work):
    """switch = "auto" (cable.explorer.follow): a task follows every direction the bifurcation
    equations give at its branch point on the plain problem, or the S0 formulation at a double
    point when they give none; run on `dask scheduler` and `dask worker` processes.  The
    switch enters the task's inputs (its key), the default "sym" does not."""
    text = TINY.replace('modes = [1]', 'modes = [1]\nswitch = "auto"')
    text = text[:text.index('[[family]]\nkind = "link"')] + text[text.index('[mesh]'):]
    path = _write(work, text, 'auto.toml')
    sweep = atlas.load(path)
    assert len(sweep.tasks) == 1 and sweep.tasks[0].inputs['switch'] == 'auto'
    assert 'switch' not in atlas.load(_write(work, TINY)).tasks[0].inputs
    cluster = _Cluster(work)
    try:
        rc, out, err = _finish(_start(path, scheduler=cluster.address))
    finally:
        cluster.stop()
    assert rc == 0 and '1 computed (0 failed)' in out, out + err
    with open(os.path.join(sweep.output, 'tasks', sweep.tasks[0].name, 'result.json')) as f:
        res = json.load(f)
    assert res['status'] == 'ok', res['error']
    rows = res['rows']
    assert rows and all(r['status'] == 'ok' for r in rows)
    dirs = sorted({r['direction'] for r in rows})
    assert dirs == list(range(1, len(dirs) + 1))
    # one branch in the S0 formulation, or every direction of the plain problem's equations
    forms = {r['formulation'] for r in rows}
    assert forms == {'braid_knot_sym'} and dirs == [1] or forms == {'braid_knot'}
    for k in dirs:
        first = [r for r in rows if r['direction'] == k][0]
        assert first['segment'] == 0 and abs(first['Lk'] - 1.5) < LK_TOL and first['companion'] == 'unknot'
    assert atlas.read_csv(os.path.join(sweep.output, 'atlas.csv'))[0]['direction'] == '1'
