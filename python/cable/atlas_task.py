# SPDX-License-Identifier: GPL-3.0-or-later
"""One atlas task, run on a Dask worker (or anywhere): the flat branch of a
(p,2) torus knot or link on one arm up to its mode-th branch point, the
branch from that point, and the rows of the cable knots or links found on
it, each derived from the computed branch with the package's analysis
(doc/atlas.md, 'What a row holds').

The task works in OUT/tasks/.NAME.partial-HOST-PID and renames that to
OUT/tasks/NAME when everything (b./s./d. files, log.txt, result.json) is
written: a task directory without the .partial prefix is complete, and a
worker that dies leaves only a partial directory, which nothing reads.
"""

__all__ = ['TASK_THREADS', 'GATE_VARIABLE', 'ROW_FIELDS', 'segments',
           'branch_rows', 'compute_flat', 'compute', 'flat_dir',
           'flat_has_solutions', 'run_flat', 'FLAT_AGAIN_RTOL', 'run_task']

import ctypes
import json
import os
import shutil
import socket
import sys
import threading
import time
import traceback

from . import _cable, explorer, scenes
from .commands import Runner, constant_text
from .atomic import write_text as write_atomic

# A task changes the process's current directory and its standard output
# (the engine prints to file descriptor 1): one task at a time per process.
_PROCESS_LOCK = threading.Lock()

_ICP = {('knot', False): ['T', 'L', 'L2', 'eps21', 'F', 'h', 'Ham'],
        ('knot', True): ['T', 'L', 'L2', 'eps21', 'eps13', 'F', 'h', 'Ham'],
        ('link', False): ['T', 'F', 'h', 'Ham', 'Phi'],
        ('link', True): ['T', 'eps13', 'F', 'h', 'Ham', 'Phi']}

# A task is one core's work: a Dask worker runs one task at a time and a
# machine has a worker per core, so the structured solver runs on one thread
# (NTHREADS; its results are the same bit for bit for every value, doc/engine.md)
# and so does the BLAS (run_task: the choice the cable program makes at start;
# a threaded OpenBLAS spent most of an atlas task spinning, doc/atlas.md 7).
# Neither is an input of the task's key: neither changes its result.
TASK_THREADS = 1

# A seam for the fault-injection test (tests/python/test_atlas.py): with
# CABLE_ATLAS_GATE=DIR set, a mode task, once its partial directory and pid
# are written, waits until the file DIR/NAME exists.  A test can then kill
# the worker of a task known to be running; without the gate, it races a
# task that takes well under a second.  Unset, nothing waits.
GATE_VARIABLE = 'CABLE_ATLAS_GATE'


def _wait_at_gate(name):
    gate = os.environ.get(GATE_VARIABLE)
    while gate and not os.path.exists(os.path.join(gate, name)):
        time.sleep(0.05)

ROW_FIELDS = ['family', 'kind', 'p', 'hand', 'Delta', 'arm', 'mode', 'direction', 'bp_T', 'bp_F',
              'bp_multiplicity',
              'formulation', 'segment', 'passages', 'companion', 'crossings', 'Lk', 'Lk_tube',
              'overlap_free',
              'LAB_free', 'T_free', 'F_free', 'LAB_free_end', 'T_free_end', 'F_free_end',
              'free_end', 'dmin',
              'pmin', 'err', 'wall', 'status', 'error', 'task']


def _constants_file(path, head, consts):
    lines = [head] + [constant_text(k, v) for k, v in consts.items()]
    write_atomic(path, '\n'.join(lines) + '\n')


def _problem(inp, sym):
    kind = inp['kind']
    e = 'braid_%s%s' % (kind, '_sym' if sym else '')
    par = {'Delta': inp['Delta'], 'T': 0.0}
    par['Ltot' if kind == 'knot' else 'L'] = inp['length']
    return e, par


def _flat_constants(inp):
    e, par = _problem(inp, False)
    c = {'e': e, 'NDIM': 21, 'IPS': 4, 'ICP': _ICP[(inp['kind'], False)], 'TORUS': inp['p'],
         'HAND': inp['hand'],
         'PAR': par, 'NTST': inp['mesh']['NTST'], 'NCOL': inp['mesh']['NCOL'], 'JAC': 1, 'ISP': 2,
         'ILP': 0,
         'NSV': 2}
    c.update(inp['flat'])
    c['NTHREADS'] = TASK_THREADS
    c['DS'] = inp['arm'] * abs(c['DS'])
    c['STOP'] = ['BP%d'
                 % inp['bps']]   # BPs of the other arm never come: the run goes one way from T = 0
    return c


def _branch_constants(inp, sym):
    e, _ = _problem(inp, sym)
    c = {'e': e, 'NDIM': 21, 'IPS': 4, 'ICP': _ICP[(inp['kind'], sym)],
         'NTST': inp['mesh']['NTST'],
         'NCOL': inp['mesh']['NCOL'], 'JAC': 1, 'ISW': -1, 'ISP': 0, 'ILP': 0}
    c.update(inp['branch'])
    c['NTHREADS'] = TASK_THREADS
    return c


def _family(inp):
    return '%s(%d,2)' % (inp['kind'], inp['p'])


def _knot_text(a):
    return '%s%s' % ('right ' if a['hand'] > 0 else 'left ' if a['hand'] < 0 else '', a['knot'])


def segments(br):
    """Index ranges [i0, i1] of the labelled solutions of engine branch br
    between which the braid axis does not pass through itself (cable's
    axis-passage count between consecutive labels is 0): along each the
    knot type of the axis and Lk cannot change.  The branch's first point
    (its branch point) starts the first."""
    out, i0 = [], 0
    for i in range(br.nsol - 1):
        count, _, _ = _cable.passages(br, i, br, i + 1)
        if count:
            out.append((i0, i))
            i0 = i + 1
    out.append((i0, br.nsol - 1))
    return out


def branch_rows(mode_result, bp, lk_bp, base):
    """The rows of a mode branch: one per stretch without axis self-passage
    (segments), from its analysis at the stretch's first overlap-free
    labelled solution (dmin > 1) or, if the tubes overlap all along it, at
    its last labelled solution."""
    br = mode_result.branches[0]
    sols = mode_result()
    t = [s['T'] for s in sols]
    # the first point is the branch point (the switch's first record; see doc/atlas.md)
    t[0] = bp['T']
    d = [_cable.tube_dmin(br, i) for i in range(br.nsol)]
    rows = []
    for k, (i0, i1) in enumerate(segments(br)):
        free = [i for i in range(i0, i1 + 1) if d[i] > 1.0]
        first = free[0] if free else None
        at = first if first is not None else i1
        try:
            a = _cable.analyze(br, at)
        except _cable.CableError as e:   # no knot type while the axis passes itself
            rows.append(dict(base, segment=k, companion='not analysable: %s' % e, overlap_free=0))
            continue
        end = first
        while end is not None and end + 1 <= i1 and d[end + 1] > 1.0:
            end += 1
        if end is None:
            why = ''
        elif end < i1:
            why = 'overlap'
        elif i1 == br.nsol - 1:
            why = 'branch end'
        else:
            why = 'passage'
        row = dict(base, segment=k, passages=(a['Lk'] - lk_bp) / 2, companion=_knot_text(a),
                   crossings=a['crossings'], Lk=a['Lk'], Lk_tube=a['lk_in_tube'],
                   overlap_free=int(first is not None),
                   dmin=d[at], pmin=a['pmin'], err=a['err'], free_end=why)
        if first is not None:
            row.update(LAB_free=sols[first].LAB, T_free=t[first], F_free=sols[first]['F'],
                       LAB_free_end=sols[end].LAB, T_free_end=t[end], F_free_end=sols[end]['F'])
        rows.append(row)
    return rows


def compute_flat(inp):
    """The flat branch of a FlatTask in the current directory (c.flat,
    b./s./d.flat); returns what its mode tasks need: its branch points on
    the arm (label, T, F, the detector's kind, which the s-file does not
    store) and where it ended."""
    runner = Runner()
    fc = _flat_constants(inp)
    _constants_file('c.flat', '# flat branch of the atlas (cable.atlas)', fc)
    flat = runner.run(c='flat', e=fc['e'], sv='flat')
    bps = [{'LAB': b.LAB, 'T': b['T'], 'F': b['F'], 'kind': scenes.bp_kind(b)}
           for b in flat('BP') if b['T'] * inp['arm'] > 0]
    return {'bps': bps, 'end_T': flat()[-1]['T']}


def compute(inp, times, flat, flat_dir):
    """The task's branch and analysis in the current directory, from the
    mode-th branch point of the flat branch flat (a run_flat result) whose
    files are in flat_dir; returns its rows (a failed step raises).  times
    (a dict) receives the wall seconds of its stages: flat (the shared
    flat branch's own wall time, spent once for all its mode tasks),
    branch (the run, its b./s./d. files included) and analysis (the rest:
    loading the branch point, the rows)."""
    t0 = time.time()
    times['flat'] = flat['wall']
    for f in ('c.flat', 'b.flat', 's.flat', 'd.flat'):
        if os.path.exists(os.path.join(flat_dir, f)):
            shutil.copyfile(os.path.join(flat_dir, f), f)
    if flat['status'] != 'ok':
        raise _cable.CableError('the flat branch %s failed: %s' % (flat['name'], flat['error']))
    fi = flat['inputs']
    bps = flat['bps']
    if len(bps) < inp['mode']:
        fc = fi['flat']
        raise _cable.CableError('the flat branch has %d branch point(s) on the %s arm up to T = '
                                '%.6g (NMX = %d, '
                                'RL0..RL1 = %g..%g): no branch point %d'
                                % (len(bps), '+' if inp['arm'] > 0 else '-', flat['end_T'],
                                   fc['NMX'], fc['RL0'],
                                   fc['RL1'], inp['mode']))
    bp = bps[inp['mode'] - 1]
    runner = Runner()
    start = [s for s in runner.loadbd('flat')('BP') if s.LAB == bp['LAB']]
    if len(start) != 1:
        raise _cable.CableError('s.flat of %s has %d solutions labelled %d (a BP expected)'
                                % (flat['name'], len(start), bp['LAB']))
    start = start[0]
    # doc/links.md, 2: double BPs switch in the S0-symmetric formulation
    # (switch 'sym', the default), or on the plain problem along every
    # direction of the bifurcation equations (switch 'auto'/'plain'): every
    # branch of the mode-th branch point (cable.explorer.follow)
    switch = inp.get('switch', 'sym')
    sym = bp['kind'] == 'double' and switch == 'sym'
    bc = _branch_constants(inp, sym)
    _constants_file('c.branch', '# the branch from branch point %d (cable.atlas)'
                    % inp['mode'], bc)
    lk_bp = _cable.analyze(*start.branch)['Lk']
    t1 = time.time()
    # e= and ICP are given to run() as well (follow does): from a start solution the runner
    # keeps the start's problem over a constants file's e (measured: c.branch's e =
    # 'braid_knot_sym' alone left the switch in braid_knot)
    followed = explorer.follow(runner, start, inp['kind'], switch, folds=0, sv='branch',
                              bp_kind=bp['kind'])
    t2 = time.time()
    times['branch'] = t2 - t1
    rows = []
    for k, n, e, mode, _ in followed:
        base = {'family': _family(inp), 'kind': inp['kind'], 'p': inp['p'], 'hand': inp['hand'],
                'Delta': inp['Delta'],
                'arm': inp['arm'], 'mode': inp['mode'], 'direction': k, 'bp_T': bp['T'],
                'bp_F': bp['F'],
                'bp_multiplicity': 2 if bp['kind'] == 'double' else 1, 'formulation': e}
        rows += branch_rows(mode, bp, lk_bp, base)
    times['analysis'] = time.time() - t2 + (t1 - t0)
    return rows


def _flush_all():
    """Python's and C's buffered standard streams (the engine prints with C's stdio)."""
    sys.stdout.flush()
    sys.stderr.flush()
    ctypes.CDLL(None).fflush(None)


def _redirect(path):
    _flush_all()
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o644)
    saved = os.dup(1), os.dup(2)
    os.dup2(fd, 1)
    os.dup2(fd, 2)
    os.close(fd)
    return saved


def _restore(saved):
    _flush_all()
    os.dup2(saved[0], 1)
    os.dup2(saved[1], 2)
    os.close(saved[0])
    os.close(saved[1])


def _in_directory(final, inputs, work, complete=None):
    """Runs work() (returning the result's fields; raising: the error is
    recorded) in a partial directory, then complete(part, result) if given,
    and renames the directory to final when its result.json is written;
    returns the result (final's, unchanged, when it exists already).  One
    at a time per process (the current directory and file descriptors 1, 2
    are the process's)."""
    done = os.path.join(final, 'result.json')
    if os.path.exists(done):
        with open(done) as fh:
            return json.load(fh)
    parent, name = os.path.split(final)
    with _PROCESS_LOCK:
        part = os.path.join(parent, '.%s.partial-%s-%d'
                            % (name, socket.gethostname(), os.getpid()))
        if os.path.exists(part):
            shutil.rmtree(part)
        os.makedirs(part)
        write_atomic(os.path.join(part, 'task.json'), json.dumps(inputs, indent=1, sort_keys=True)
                     + '\n')
        write_atomic(os.path.join(part, 'pid'), '%d\n' % os.getpid())
        here = os.getcwd()
        _cable.blas_single_thread()
        t0 = time.time()
        saved = _redirect(os.path.join(part, 'log.txt'))
        try:
            os.chdir(part)
            fields, status, error = work(), 'ok', ''
        except Exception as e:   # recorded in the result: the sweep goes on
            _flush_all()
            with open(os.path.join(part, 'log.txt'), 'a') as fh:
                fh.write(traceback.format_exc())
            fields, status, error = {}, 'failed', '%s: %s' % (type(e).__name__, e)
        finally:
            os.chdir(here)
            _restore(saved)
        wall = time.time() - t0
        result = {'name': name, 'status': status, 'error': error, 'wall': wall}
        result.update(fields)
        result.update(host=socket.gethostname(), inputs=inputs)
        if complete is not None:
            complete(part, result)
        return _finish(part, final, result)


def _finish(part, final, result):
    """Writes result.json into part and renames it to final (another worker
    that finished the same task first wins: its result is kept)."""
    done = os.path.join(final, 'result.json')
    write_atomic(os.path.join(part, 'result.json'), json.dumps(result, indent=1) + '\n')
    os.remove(os.path.join(part, 'pid'))
    # another worker finished it meanwhile (a retried task): keep the first
    if os.path.exists(final):
        shutil.rmtree(part)
        with open(done) as fh:
            return json.load(fh)
    os.rename(part, final)
    return result


def flat_dir(out_dir, flat_name):
    return os.path.join(out_dir, 'flat', flat_name)


def flat_has_solutions(final):
    """Whether the flat branch in directory final has its solutions (s.flat),
    which its mode tasks start from (a fresh clone has only its result)."""
    return os.path.exists(os.path.join(final, 's.flat'))


def run_flat(inputs, name, out_dir):
    """Computes the shared flat branch of a FlatTask into OUT/flat/NAME
    (c.flat, b./s./d.flat, log.txt, result.json with its branch points)
    unless it is there already; returns its result.  Its files are kept
    whatever the sweep records: its mode tasks, run later or elsewhere,
    start from its s-file."""
    os.makedirs(os.path.join(out_dir, 'flat'), exist_ok=True)
    final = flat_dir(out_dir, name)
    result = _in_directory(final, inputs, lambda: compute_flat(inputs))
    if result['status'] == 'ok' and not flat_has_solutions(final):
        _restore_flat_files(final, inputs, name, result)
    return result


# Two computations of one flat branch agree to rounding (the engine is
# deterministic on one machine; another machine's BLAS may round
# differently): their branch points' T agree far better than this, and a
# different branch point (another label or kind) differs by O(1).
FLAT_AGAIN_RTOL = 1e-6


def _restore_flat_files(final, inputs, name, kept):
    """A finished flat branch whose b./s./d. files are missing (the
    repository keeps a sweep's result.json files, not its solutions: a fresh
    clone resumes from them) is computed again in a directory of its own;
    its files move into final if its branch points are the kept ones, else
    CableError.  s.flat moves last: its presence marks final as usable."""
    again_dir = os.path.join(os.path.dirname(final), '.%s.again-%s-%d'
                             % (name, socket.gethostname(), os.getpid()))
    if os.path.exists(again_dir):
        shutil.rmtree(again_dir)
    try:
        again = _in_directory(again_dir, inputs, lambda: compute_flat(inputs))
        if again['status'] != 'ok':
            raise _cable.CableError('the flat branch %s, computed again for its solutions, '
                                    'failed: %s'
                                    % (name, again['error']))
        same = [(a['LAB'], a['kind']) for a in again['bps']] == [(k['LAB'], k['kind'])
                                                                 for k in kept['bps']] and all(
            abs(a['T'] - k['T']) <= FLAT_AGAIN_RTOL * max(1.0, abs(k['T']))
            for a, k in zip(again['bps'], kept['bps']))
        if not same:
            raise _cable.CableError('the flat branch %s computed again has other branch points '
                                    'than its result.json '
                                    '(%s, kept %s): remove %s to recompute its tasks'
                                    % (name, [(a['LAB'], a['T']) for a in again['bps']],
                                       [(k['LAB'], k['T']) for k in kept['bps']], final))
        for f in ('b.flat', 'd.flat', 's.flat'):
            if os.path.exists(os.path.join(again_dir, f)):
                os.replace(os.path.join(again_dir, f), os.path.join(final, f))
    finally:
        shutil.rmtree(again_dir, ignore_errors=True)


def run_task(inputs, name, out_dir, flat=None):
    """Runs one task into OUT/tasks/NAME (see the module's text) unless it
    is there already; returns its result dict (status 'ok' or 'failed',
    rows, wall time, the stages' times).  flat: the result of the flat
    branch it starts from (run_flat; a sweep shares one between a
    family's modes); None: its own, run to its mode-th branch point.  An
    error of the computation is recorded, not raised."""
    final = os.path.join(out_dir, 'tasks', name)
    if os.path.exists(os.path.join(final, 'result.json')):
        with open(os.path.join(final, 'result.json')) as fh:
            return json.load(fh)
    os.makedirs(os.path.join(out_dir, 'tasks'), exist_ok=True)
    if flat is None:
        from .atlas_sweep import FlatTask, flat_inputs
        ft = FlatTask(flat_inputs(inputs, inputs['mode']))
        flat = run_flat(ft.inputs, ft.name, out_dir)
    times = {}

    def work():
        _wait_at_gate(name)
        return {'rows': compute(inputs, times, flat,
                                os.path.abspath(flat_dir(out_dir, flat['name'])))}

    def complete(part, result):
        result.setdefault('rows', [])
        for r in result['rows']:
            r.update(wall=result['wall'], status=result['status'], error='', task=name)
        times['total'] = result['wall']
        result['times'] = times
        result['flat'] = flat['name']
        if not inputs.get('files', True):
            for f in os.listdir(part):
                if f[:2] in ('b.', 's.', 'd.'):
                    os.remove(os.path.join(part, f))

    return _in_directory(final, inputs, work, complete)
