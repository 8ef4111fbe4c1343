# SPDX-License-Identifier: GPL-3.0-or-later
"""Running a sweep on Dask distributed (doc/atlas.md): a local cluster of
this machine's cores by default, or the scheduler at an address.

Each task is submitted under the Dask key atlas-KEY (KEY: the hash of its
inputs).  Tasks whose directory OUT/tasks/NAME holds a result.json are not
submitted (a resumed sweep recomputes nothing finished); failed ones only
with retry_failed.  As each task finishes the table is rewritten
(atomically) from every finished task of the sweep.  A worker that dies
mid-task is replaced (local cluster: its nanny restarts it) and the
scheduler gives its task to another worker; after Dask's allowed failures
(distributed.scheduler.allowed-failures, 3) the task is recorded as failed.
"""

__all__ = ['TABLE_INTERVAL', 'read_result', 'remove_stale_partials',
           'read_flat', 'priority', 'Progress', 'run_sweep']

import json
import os
import shutil
import sys
import time

from .atlas_output import load_matplotlib, write_outputs
from .atlas_task import flat_dir, flat_has_solutions, run_flat, run_task


# seconds between rewrites of the table and summary while tasks finish
TABLE_INTERVAL = 1.0


def _result_path(sweep, t):
    return os.path.join(sweep.output, 'tasks', t.name, 'result.json')


def read_result(sweep, t):
    """The finished result of task t (None: not finished)."""
    p = _result_path(sweep, t)
    if not os.path.exists(p):
        return None
    with open(p) as fh:
        return json.load(fh)


def _record_failure(sweep, t, error):
    """A task Dask gave up on (its workers died): recorded as failed, as the
    task itself records an error (a directory with result.json)."""
    from .atomic import write_text as write_atomic
    d = os.path.join(sweep.output, 'tasks', t.name)
    os.makedirs(d, exist_ok=True)
    result = {'name': t.name, 'status': 'failed', 'error': error, 'wall': float('nan'), 'rows': [],
              'host': '', 'inputs': t.inputs}
    write_atomic(os.path.join(d, 'result.json'), json.dumps(result, indent=1) + '\n')
    return result


def remove_stale_partials(sweep):
    """Removes the partial directories this host's dead worker processes
    left (OUT/tasks/.NAME.partial-HOST-PID whose PID is not running, and
    OUT/flat/.NAME.again-HOST-PID, a flat branch computed again for its
    files)."""
    import socket
    tags = ['.%s-%s-' % (kind, socket.gethostname()) for kind in ('partial', 'again')]
    for d in (os.path.join(sweep.output, 'tasks'), os.path.join(sweep.output, 'flat')):
        for n in os.listdir(d) if os.path.isdir(d) else []:
            if n.startswith('.') and any(tag in n for tag in tags):
                try:
                    pid = int(n.rsplit('-', 1)[1])
                    os.kill(pid, 0)
                except ProcessLookupError:
                    shutil.rmtree(os.path.join(d, n), ignore_errors=True)
                except (ValueError, PermissionError):
                    pass


def read_flat(sweep, ft):
    """The finished result of the shared flat branch ft (None: not finished,
    or finished without its solutions, which run_flat computes again)."""
    final = flat_dir(sweep.output, ft.name)
    p = os.path.join(final, 'result.json')
    if not os.path.exists(p):
        return None
    with open(p) as fh:
        r = json.load(fh)
    return None if r['status'] == 'ok' and not flat_has_solutions(final) else r


def priority(t):
    """Dask priority (higher first): lower modes first, then smaller p (the
    cheap tasks; a sweep stopped early has the first modes of many
    families), then the sweep file's order (Dask keeps submission order
    among equal priorities)."""
    return -(1000 * t.inputs['mode'] + t.inputs['p'])


def _fmt_time(s):
    if s != s or s == float('inf'):
        return '?'
    s = int(round(s))
    return '%dh%02dm' % (s // 3600, s % 3600 // 60) if s >= 3600 else '%dm%02ds' % (s // 60,
                                                                                    s % 60)


class Progress:
    """Tasks done, running, failed and the estimated time left, on one line
    (rewritten in place on a terminal, a new line per change otherwise)."""

    def __init__(self, total, skipped, stream):
        self.total, self.skipped, self.stream = total, skipped, stream
        self.tty = hasattr(stream, 'isatty') and stream.isatty()
        self.done = self.failed = 0
        self.walls = []
        self.last = None
        self.t0 = time.time()

    def line(self, running, threads):
        left = self.total - self.skipped - self.done
        eta = float('nan')
        if self.walls and threads:
            mean = sum(self.walls) / len(self.walls)
            eta = left * mean / threads
        elif left == 0:
            eta = 0.0
        return ('atlas: %d/%d done (%d earlier), %d running, %d failed, %s elapsed, ETA %s'
                % (self.skipped + self.done, self.total, self.skipped, running, self.failed,
                   _fmt_time(time.time() - self.t0), _fmt_time(eta)))

    def show(self, running, threads, final=False):
        text = self.line(running, threads)
        key = text.split(', ETA')[0].rsplit(',', 1)[0]
        if self.tty:
            self.stream.write('\r' + text + ('\n' if final else ''))
            self.stream.flush()
        elif key != self.last or final:
            self.stream.write(text + '\n')
            self.stream.flush()
        self.last = key


def _client(scheduler, workers):
    from distributed import Client, LocalCluster
    if scheduler:
        return Client(scheduler), None
    n = workers or os.cpu_count() or 1
    # one thread per worker process: a task owns its process's directory and stdout
    cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                           dashboard_address=None,
                           silence_logs=40)
    return Client(cluster), cluster


def run_sweep(sweep, scheduler=None, workers=None, retry_failed=False, stream=None):
    """Runs the tasks of sweep not yet finished; returns a dict with the
    counts: total, skipped (finished before), computed, failed,
    failed_earlier (skipped tasks whose recorded status is failed), and when
    tasks ran: cluster_start (s to start or reach the cluster), elapsed (s
    from the first submission to the last result), threads (the cluster's
    worker threads at the end)."""
    from distributed import wait
    # noqa: the name differs between versions
    from distributed.client import TimeoutError as DaskTimeout
    stream = stream or sys.stderr
    load_matplotlib()   # before any task, so that an interrupt cannot land in its import
    os.makedirs(os.path.join(sweep.output, 'tasks'), exist_ok=True)
    remove_stale_partials(sweep)
    todo, skipped, failed_earlier = [], 0, 0
    known = {}   # task name -> result of the finished tasks (the table is made from these)
    for t in sweep.tasks:
        r = read_result(sweep, t)
        if r is not None and (r['status'] == 'ok' or not retry_failed):
            skipped += 1
            failed_earlier += r['status'] != 'ok'
            known[t.name] = r
            continue
        if r is not None:
            shutil.rmtree(os.path.dirname(_result_path(sweep, t)))
        todo.append(t)
    prog = Progress(len(sweep.tasks), skipped, stream)
    counts = {'total': len(sweep.tasks), 'skipped': skipped, 'computed': 0, 'failed': 0,
              'failed_earlier': failed_earlier}

    def table():
        write_outputs(sweep, [(t, known[t.name]) for t in sweep.tasks if t.name in known])

    if not todo:
        table()
        prog.show(0, 0, final=True)
        return counts
    t_start = time.time()
    client, cluster = _client(scheduler, workers)
    counts['cluster_start'] = time.time() - t_start
    t_submit = time.time()
    dirty, written = False, 0.0
    try:
        by_key = {}
        futures = []
        flats = {}   # flat key -> its finished result or the future computing it (once per sweep)
        # submitted in priority order as well: with Dask's default (no queuing on the scheduler)
        # every
        # task goes to a worker at once, and the workers were seen to run them in submission order
        for t in sorted(todo, key=lambda x: -priority(x)):
            ft = t.flat
            if ft.key not in flats:
                r = read_flat(sweep, ft)
                if r is not None and r['status'] != 'ok' and retry_failed:
                    shutil.rmtree(flat_dir(sweep.output, ft.name))
                    r = None
                # a flat branch runs before the mode tasks that wait for it (Dask's dependencies)
                flats[ft.key] = r if r is not None else client.submit(
                    run_flat, ft.inputs, ft.name, sweep.output, key='atlas-flat-' + ft.key,
                    pure=False,
                    priority=priority(t) + 1)
            f = client.submit(run_task, t.inputs, t.name, sweep.output, flats[ft.key],
                              key='atlas-' + t.key,
                              pure=False, priority=priority(t))
            by_key[f.key] = t
            futures.append(f)
        pending = set(futures)
        while pending:
            try:
                done, pending = wait(pending, timeout=1.0, return_when='FIRST_COMPLETED')
            except (DaskTimeout, TimeoutError):
                done = set()
            for f in done:
                t = by_key[f.key]
                if f.status == 'finished':
                    r = f.result()
                else:
                    r = _record_failure(sweep, t, '%s: %s'
                                        % (type(f.exception()).__name__, f.exception()))
                known[t.name] = r
                prog.done += 1
                counts['computed'] += 1
                if r['status'] != 'ok':
                    prog.failed += 1
                    counts['failed'] += 1
                elif r['wall'] == r['wall']:
                    prog.walls.append(r['wall'])
            # the table at most once a second (and at the end): each task's own result is on disk
            # already
            if done:
                dirty = True
            if dirty and (not pending or time.time() - written >= TABLE_INTERVAL):
                table()
                dirty, written = False, time.time()
            threads = sum(client.nthreads().values())
            proc = client.processing()
            running = min(threads, sum(1 for ks in proc.values() for k in ks if k in by_key))
            prog.show(running, threads)
        counts['elapsed'] = time.time() - t_submit
        counts['threads'] = sum(client.nthreads().values())
        prog.show(0, 0, final=True)
    finally:
        if dirty:   # interrupted: the table of what finished
            table()
        client.close()
        if cluster is not None:
            cluster.close()
        remove_stale_partials(sweep)
    return counts
