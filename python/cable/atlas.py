# SPDX-License-Identifier: GPL-3.0-or-later
"""cable.atlas: an atlas of cable knots and links, computed on Dask
distributed (doc/atlas.md).

    cable atlas sweep.toml                      a local cluster of this machine's cores
    cable atlas sweep.toml --workers 2
    cable atlas sweep.toml --scheduler tcp://host:8786
    cable atlas sweep.toml --check              check the file, list the tasks, run nothing

From Python:

    from cable import atlas
    sweep = atlas.load('sweep.toml')            # SweepError: file, line, key
    counts = atlas.run(sweep, workers=2)        # OUT/atlas.csv, OUT/summary.svg, OUT/tasks/NAME/
"""
import argparse
import sys

from .atlas_output import read_csv, write_outputs
from .atlas_run import run_sweep
from .atlas_sweep import Sweep, SweepError, Task, load
from .atlas_task import ROW_FIELDS, run_task

__all__ = ['load', 'run', 'run_task', 'write_outputs', 'read_csv', 'Sweep', 'SweepError', 'Task',
           'ROW_FIELDS',
           'main']


def run(sweep, scheduler=None, workers=None, retry_failed=False, stream=None):
    """Runs a sweep (a Sweep or a file name); returns the counts (total,
    skipped, computed, failed)."""
    if isinstance(sweep, str):
        sweep = load(sweep)
    return run_sweep(sweep, scheduler=scheduler, workers=workers, retry_failed=retry_failed,
                     stream=stream)


def main(argv=None):
    ap = argparse.ArgumentParser(prog='cable atlas',
                                 description='an atlas of cable knots and links on Dask '
                                 '(doc/atlas.md)')
    ap.add_argument('sweep', help='the sweep file (TOML)')
    ap.add_argument('--scheduler',
                    help='address of a running Dask scheduler (default: a local cluster)')
    ap.add_argument('--workers', type=int,
                    help='local cluster: number of worker processes (default: cores)')
    ap.add_argument('--retry-failed', action='store_true', help='compute the failed tasks again')
    ap.add_argument('--check', action='store_true',
                    help='check the sweep file and list its tasks; run nothing')
    a = ap.parse_args(argv)
    if a.workers is not None and a.workers < 1:
        print('cable atlas: --workers must be at least 1', file=sys.stderr)
        return 2
    try:
        sweep = load(a.sweep)
    except SweepError as e:
        print('cable atlas: %s' % e, file=sys.stderr)
        return 1
    if a.check:
        for t in sweep.tasks:
            print(t.name)
        print('%d tasks; output in %s' % (len(sweep.tasks), sweep.output))
        return 0
    try:
        c = run(sweep, scheduler=a.scheduler, workers=a.workers, retry_failed=a.retry_failed)
    except KeyboardInterrupt:
        print('\ncable atlas: interrupted; finished tasks are kept, run again to resume',
              file=sys.stderr)
        return 130
    earlier = c.get('failed_earlier', 0)
    print('cable atlas: %d tasks: %d finished earlier%s, %d computed (%d failed); table '
          '%s/atlas.csv'
          % (c['total'], c['skipped'], ' (%d of them failed: --retry-failed computes them again)'
             % earlier
             if earlier else '', c['computed'], c['failed'], sweep.output))
    # non-zero while the table holds a failed task, whenever it failed
    return 1 if c['failed'] or earlier else 0


if __name__ == '__main__':
    sys.exit(main())
