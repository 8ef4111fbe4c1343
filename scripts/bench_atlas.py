# SPDX-License-Identifier: GPL-3.0-or-later
"""make bench, the atlas part (scripts/bench-atlas.sh): cable.atlas on a
local Dask cluster of 1 and 2 workers, and the scheduler's overhead per task
with many more tasks than cores.  Prints a Markdown section.

  1. Speed-up: one sweep of real tasks (the (3,2), (5,2) knots and the (4,2),
     (6,2) links at one Delta, mode 1, NTST 20, 30 points from the branch
     point), run whole on 1 worker and then on 2 (fresh output each time);
     elapsed = run() from its call to its return (cluster start included,
     reported apart), and the sum of the tasks' own wall times and of
     their shared flat branches' (each a Dask task of its own).
  2. Overhead: N atlas tasks, each two Dask tasks: a flat branch of a Newton
     solve and one step (NMX = 1) and the task, which finds no branch point
     on it and is recorded as failed after going through the whole path
     (submission, scheduling, the dependency, the directories, result.json
     and rename, the table); overhead per Dask task = (elapsed x workers -
     sum of the Dask tasks' wall times) / their number.
"""
import json
import os
import shutil
import sys
import tempfile

from cable import atlas

REAL = """\
deltas = [0.005]
modes = [1]
[[family]]
kind = "knot"
p = [3, 5]
[[family]]
kind = "link"
p = [4, 6]
[mesh]
NTST = 20
NCOL = 4
[flat]
DSMAX = 10.0
[branch]
NMX = 30
NPR = 10
"""

TINY = """\
deltas = [%s]
modes = [1]
[[family]]
kind = "knot"
p = [3]
[mesh]
NTST = 10
NCOL = 3
[flat]
NMX = 1
[record]
files = false
"""


class _Null:
    def write(self, s):
        pass

    def flush(self):
        pass

    def isatty(self):
        return False


def _sweep(d, name, text):
    p = os.path.join(d, name + '.toml')
    with open(p, 'w') as f:
        f.write(text)
    return atlas.load(p)


def _timed(sweep, workers):
    """(elapsed from the first submission to the last result, the sum of
    the wall times of the Dask tasks (the atlas tasks and the shared flat
    branches they start from), the cluster start, the counts with
    'dask_tasks', their number)"""
    if os.path.exists(sweep.output):
        shutil.rmtree(sweep.output)
    counts = atlas.run(sweep, workers=workers, stream=_Null())
    rows = atlas.read_csv(os.path.join(sweep.output, 'atlas.csv'))
    walls = {r['task']: float(r['wall']) for r in rows if r['wall']}
    assert len(walls) == len(sweep.tasks) and counts['threads'] == workers
    flats = {t.flat.name for t in sweep.tasks}
    for name in flats:
        with open(os.path.join(sweep.output, 'flat', name, 'result.json')) as f:
            walls[name] = json.load(f)['wall']
    counts['dask_tasks'] = len(walls)
    return counts['elapsed'], sum(walls.values()), counts['cluster_start'], counts


def main():
    n_tiny = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    d = tempfile.mkdtemp(prefix='bench-atlas-')
    try:
        real = _sweep(d, 'real', REAL)
        e1, w1, s1, c1 = _timed(real, 1)
        e2, w2, s2, c2 = _timed(real, 2)
        print('### Speed-up, 1 against 2 local workers\n')
        print('%d real tasks (%s) and their %d flat branches. Elapsed: from the first submission to the last '
              'result (the cluster start is apart); speed-up = elapsed(1) / elapsed(2).\n'
              % (len(real.tasks), ', '.join(t.name.rsplit('-', 1)[0] for t in real.tasks),
                 c1['dask_tasks'] - len(real.tasks)))
        print('| workers | cluster start (s) | elapsed (s) | sum of task wall times (s) | failed | speed-up |')
        print('|---|---|---|---|---|---|')
        print('| 1 | %.1f | %.1f | %.1f | %d | 1 |' % (s1, e1, w1, c1['failed']))
        print('| 2 | %.1f | %.1f | %.1f | %d | %.2f |' % (s2, e2, w2, c2['failed'], e1 / e2))
        print()
        deltas = ', '.join('%.6f' % (0.001 + 1e-5 * k) for k in range(n_tiny))
        tiny = _sweep(d, 'tiny', TINY % deltas)
        e, w, s, c = _timed(tiny, 2)
        n = c['dask_tasks']
        print('### Scheduler overhead per task, %d atlas tasks (%d Dask tasks) on 2 workers\n'
              % (len(tiny.tasks), n))
        print('Each atlas task is two Dask tasks here: its flat branch (a Newton solve and one step, NMX = 1) '
              'and the task proper, which finds no branch point on it and is recorded as failed, through the '
              'whole path (submission, scheduling, a dependency, the task directories, result.json, the table '
              'at most once a second). Overhead per Dask task = (elapsed x 2 - sum of the Dask tasks\' wall '
              'times) / Dask tasks; a sweep of n Dask tasks of wall time w on N worker processes takes about '
              'n (w + overhead) / N plus the cluster start (the real atlas: one flat branch per family, Delta '
              'and arm, shared by its modes).\n')
        print('| atlas tasks | Dask tasks | cluster start (s) | elapsed (s) | sum of Dask task wall times (s) | '
              'overhead per Dask task (ms) |')
        print('|---|---|---|---|---|---|')
        print('| %d | %d | %.1f | %.1f | %.1f | %.1f |' % (len(tiny.tasks), n, s, e, w, 1000 * (e * 2 - w) / n))
        print()
        print('Load while measuring (1-minute load average at the end): %.2f on %d cores.'
              % (os.getloadavg()[0], os.cpu_count()))
    finally:
        shutil.rmtree(d, ignore_errors=True)

if __name__ == '__main__':
    main()
