"""make bench, the atlas part (scripts/bench-atlas.sh): cable.atlas on a
local Dask cluster of 1 and 2 workers, and the scheduler's overhead per task
with many more tasks than cores.  Prints a Markdown section.

  1. Speed-up: one sweep of real tasks (the (3,2), (5,2) knots and the (4,2),
     (6,2) links at one Delta, mode 1, NTST 20, 30 points from the branch
     point), run whole on 1 worker and then on 2 (fresh output each time);
     elapsed = run() from its call to its return (cluster start included,
     reported apart), and the sum of the tasks' own wall times.
  2. Overhead: N tasks whose work is a Newton solve and one step of the flat
     branch (NMX = 1: no branch point, so each is recorded as failed after
     going through the whole path: submission, scheduling, the task's
     directory, its result.json and rename, the table); overhead per task =
     (elapsed x workers - sum of the tasks' wall times) / N.
"""
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
    the tasks' own wall times, the cluster start, the counts)"""
    if os.path.exists(sweep.output):
        shutil.rmtree(sweep.output)
    counts = atlas.run(sweep, workers=workers, stream=_Null())
    rows = atlas.read_csv(os.path.join(sweep.output, 'atlas.csv'))
    walls = {r['task']: float(r['wall']) for r in rows if r['wall']}
    assert len(walls) == len(sweep.tasks) and counts['threads'] == workers
    return counts['elapsed'], sum(walls.values()), counts['cluster_start'], counts


def main():
    n_tiny = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    d = tempfile.mkdtemp(prefix='bench-atlas-')
    try:
        real = _sweep(d, 'real', REAL)
        e1, w1, s1, c1 = _timed(real, 1)
        e2, w2, s2, c2 = _timed(real, 2)
        print('### Speed-up, 1 against 2 local workers\n')
        print('%d real tasks (%s). Elapsed: from the first submission to the last result (the cluster '
              'start is apart); speed-up = elapsed(1) / elapsed(2).\n'
              % (len(real.tasks), ', '.join(t.name.rsplit('-', 1)[0] for t in real.tasks)))
        print('| workers | cluster start (s) | elapsed (s) | sum of task wall times (s) | failed | speed-up |')
        print('|---|---|---|---|---|---|')
        print('| 1 | %.1f | %.1f | %.1f | %d | 1 |' % (s1, e1, w1, c1['failed']))
        print('| 2 | %.1f | %.1f | %.1f | %d | %.2f |' % (s2, e2, w2, c2['failed'], e1 / e2))
        print()
        deltas = ', '.join('%.6f' % (0.001 + 1e-5 * k) for k in range(n_tiny))
        tiny = _sweep(d, 'tiny', TINY % deltas)
        e, w, s, c = _timed(tiny, 2)
        print('### Scheduler overhead per task, %d tasks on 2 workers\n' % len(tiny.tasks))
        print('Tasks of a Newton solve and one step each (NMX = 1, recorded as failed: no branch point), '
              'through the whole path (submission, scheduling, the task directory, result.json, the table '
              'at most once a second). Overhead per task = (elapsed x 2 - sum of task wall times) / tasks; '
              'a sweep of n tasks of wall time w on N worker processes takes about n (w + overhead) / N '
              'plus the cluster start.\n')
        print('| tasks | cluster start (s) | elapsed (s) | sum of task wall times (s) | overhead per task (ms) |')
        print('|---|---|---|---|---|')
        print('| %d | %.1f | %.1f | %.1f | %.1f |' % (len(tiny.tasks), s, e, w, 1000 * (e * 2 - w) / len(tiny.tasks)))
        print()
        print('Load while measuring (1-minute load average at the end): %.2f on %d cores.'
              % (os.getloadavg()[0], os.cpu_count()))
    finally:
        shutil.rmtree(d, ignore_errors=True)

if __name__ == '__main__':
    main()
