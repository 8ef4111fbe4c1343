# SPDX-License-Identifier: GPL-3.0-or-later
"""The atlas's outputs, rebuilt (each file atomically) from the finished
tasks of a sweep: OUT/atlas.csv (one row per cable knot or link found, plus
one row per failed task), OUT/atlas.parquet when pyarrow is installed,
OUT/summary.svg (matplotlib: families against Delta, one cell per arm and mode, coloured
by the companion knot type and Lk the branch reaches: cell_outcome) and
OUT/summary.md (counts and the picture)."""

__all__ = ['finished_results', 'table_rows', 'csv_text', 'read_csv',
           'cell_outcome', 'load_matplotlib', 'summary_svg', 'summary_md', 'write_outputs']

import csv
import importlib.util
import io
import json
import math
import os

from .atlas_task import ROW_FIELDS
from .atomic import replacing, write_text as write_atomic


def finished_results(sweep):
    """The results of the sweep's finished tasks, in the sweep's order."""
    out = []
    for t in sweep.tasks:
        p = os.path.join(sweep.output, 'tasks', t.name, 'result.json')
        if os.path.exists(p):
            with open(p) as fh:
                out.append((t, json.load(fh)))
    return out


def table_rows(results):
    rows = []
    for t, r in results:
        if r['status'] != 'ok' or not r['rows']:
            i = t.inputs
            rows.append({'family': '%s(%d,2)' % (i['kind'], i['p']), 'kind': i['kind'],
                         'p': i['p'],
                         'hand': i['hand'], 'Delta': i['Delta'], 'arm': i['arm'],
                         'mode': i['mode'],
                         'wall': r['wall'], 'status': r['status'], 'error': r['error'],
                         'task': t.name})
        else:
            rows.extend(r['rows'])
    return rows


def _cell(x):
    if x is None:
        return ''
    if isinstance(x, float):
        return '' if math.isnan(x) else repr(x)
    return str(x)


def csv_text(rows):
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator='\n')
    w.writerow(ROW_FIELDS)
    for r in rows:
        w.writerow([_cell(r.get(k)) for k in ROW_FIELDS])
    return buf.getvalue()


def read_csv(path):
    with open(path, newline='') as fh:
        return list(csv.DictReader(fh))


def _write_parquet(path, rows):
    import pyarrow
    import pyarrow.parquet
    cols = {k: [r.get(k) for r in rows] for k in ROW_FIELDS}
    with replacing(path, suffix='.parquet') as tmp:
        pyarrow.parquet.write_table(pyarrow.table(cols), tmp)


# ---- the picture ----------------------------------------------------------------------

_PALETTE = ['#4e79a7', '#f28e2b', '#e15759', '#76b7b2', '#59a14f', '#edc948', '#b07aa1', '#ff9da7',
            '#9c755f',
            '#bab0ac', '#86bcb6', '#d37295']


def cell_outcome(rows):
    """What a task's cell shows: the cable knot or link the branch reaches,
    the overlap-free stretch furthest from the flat braid (the most net
    self-passages of the axis; the first of equals): its companion and Lk
    ('no overlap-free stretch' when none is free of overlap, 'failed')."""
    if not rows or rows[0].get('status') != 'ok':
        return 'failed'
    free = [r for r in rows if r.get('overlap_free') == 1 and r.get('passages') is not None]
    if not free:
        return 'no overlap-free stretch'
    r = max(free, key=lambda x: (round(abs(x['passages'])), -x['segment']))
    return '%s (Lk %g)' % (r['companion'], round(2 * r['Lk']) / 2)


def load_matplotlib():
    """Imports what summary_svg draws with.  A sweep calls it before its first
    task: the first import of matplotlib takes a second or two, and a Ctrl-C
    that lands inside it leaves the module half-imported, so that the table
    written on the way out (the points computed so far) would fail."""
    try:
        import matplotlib  # noqa: F401
        from matplotlib.backends.backend_svg import FigureCanvasSVG  # noqa: F401
        from matplotlib.figure import Figure  # noqa: F401
        from matplotlib.patches import Patch, Rectangle  # noqa: F401
    except ImportError:
        pass   # summary_svg says what is missing


def summary_svg(results, tasks=None):
    """The picture (matplotlib, SVG text): a row per family, a group of
    cells per Delta, a cell per arm and mode, for every task of tasks
    (default: those of results), so that an empty cell is a task not
    computed yet."""
    import io
    try:
        import matplotlib
        from matplotlib.backends.backend_svg import FigureCanvasSVG
        from matplotlib.figure import Figure
        from matplotlib.patches import Patch, Rectangle
    except ImportError:
        from ._cable import CableError
        raise CableError("atlas: summary.svg is drawn with matplotlib (Debian's "
                         "python3-matplotlib, which scripts/install-deps.sh "
                         "installs)") from None
    fams, deltas, cols = [], [], []
    cell = {}

    def where(t):
        i = t.inputs
        fam = '%s(%d,2) %s' % (i['kind'], i['p'], 'R' if i['hand'] > 0 else 'L')
        return fam, i['Delta'], (i['arm'], i['mode'])

    for t in (tasks if tasks is not None else [t for t, _ in results]):
        for lst, x in zip((fams, deltas, cols), where(t)):
            if x not in lst:
                lst.append(x)
    for t, r in results:
        cell[where(t)] = cell_outcome(r['rows'] if r['status'] == 'ok' else [])
    deltas.sort()
    cols.sort(key=lambda c: (-c[0], c[1]))
    kinds = []
    for v in cell.values():
        if v not in kinds:
            kinds.append(v)
    colour = {}
    k = 0
    for v in kinds:
        if v == 'failed':
            colour[v] = '#000000'
        elif v == 'no overlap-free stretch':
            colour[v] = '#dddddd'
        else:
            colour[v] = _PALETTE[k % len(_PALETTE)]
            k += 1
    # cell (family i, Delta j, column m) at x = j (ncol + 1) + m, y = -i
    ncol, gap = len(cols), 1
    width = max(len(deltas) * (ncol + gap), 1)
    # the legend: up to 12 entries a column, each column about 2.4 inches
    nleg = len(kinds) + 1
    legcols = min(4, -(-nleg // 12))
    legrows = -(-nleg // legcols)
    legh = 0.1 + 0.19 * legrows
    rc = {'svg.fonttype': 'none', 'svg.hashsalt': 'cable-atlas',
          'font.family': 'sans-serif', 'font.size': 9}
    with matplotlib.rc_context(rc):
        fig = Figure(figsize=(max(7.5, 2.2 + 0.28 * width, 2.4 * legcols),
                              1.6 + 0.28 * len(fams) + legh))
        FigureCanvasSVG(fig)
        ax = fig.add_subplot()
        for i, f in enumerate(fams):
            for j, d in enumerate(deltas):
                for m, c in enumerate(cols):
                    v = cell.get((f, d, c))
                    x = j * (ncol + gap) + m
                    if v is None:
                        ax.add_patch(Rectangle((x, -i - 0.45), 0.9, 0.9,
                                               fill=False, edgecolor='#bbbbbb'))
                    else:
                        ax.add_patch(Rectangle((x, -i - 0.45), 0.9, 0.9,
                                               facecolor=colour[v]))
        ax.set_xlim(-0.2, width)
        ax.set_ylim(-len(fams) + 0.4, 0.6)
        ax.set_yticks([-i for i in range(len(fams))], fams)
        ax.set_xticks([j * (ncol + gap) + m + 0.45 for j in range(len(deltas))
                       for m in range(ncol)],
                      ['%s%d' % ('+' if c[0] > 0 else '-', c[1])
                       for _ in deltas for c in cols], fontsize=7)
        ax.tick_params(length=0)
        for j, d in enumerate(deltas):
            ax.text(j * (ncol + gap), 0.75, 'Delta = %.4g' % d)
        for side in ax.spines.values():
            side.set_visible(False)
        ax.set_title('cable atlas: the companion knot type and Lk each '
                     'branch reaches\n(its overlap-free stretch with the most '
                     'axis passages; a cell per arm and mode)', pad=18)
        handles = [Patch(facecolor=colour[v], edgecolor='#888888', label=v)
                   for v in kinds]
        handles.append(Patch(fill=False, edgecolor='#bbbbbb',
                             label='empty cell: not computed yet'))
        fig.legend(handles=handles, loc='lower left', ncol=legcols,
                   frameon=False, borderaxespad=0.2)
        fig.tight_layout(rect=(0, legh / fig.get_figheight(), 1, 1))
        buf = io.StringIO()
        fig.savefig(buf, format='svg', metadata={'Date': None})
    return buf.getvalue()


def summary_md(sweep, results, rows):
    n_ok = sum(1 for _, r in results if r['status'] == 'ok')
    n_fail = len(results) - n_ok
    count = {}
    for r in rows:
        if r.get('status') == 'ok' and r.get('overlap_free') == 1:
            count[r['companion']] = count.get(r['companion'], 0) + 1
    lines = ['# cable atlas: %s' % os.path.basename(sweep.path), '',
             '%d of %d tasks finished (%d ok, %d failed); %d rows in atlas.csv.'
             % (len(results), len(sweep.tasks), n_ok, n_fail, len(rows)), '',
             '![summary](summary.svg)', '',
             '| companion knot type (overlap-free stretches) | rows |', '|---|---|']
    lines += ['| %s | %d |' % (k, v) for k, v in sorted(count.items())]
    fails = [(t, r) for t, r in results if r['status'] != 'ok']
    if fails:
        lines += ['', 'Failed tasks:', '']
        lines += ['* %s: %s' % (t.name, r['error']) for t, r in fails]
    return '\n'.join(lines) + '\n'


def write_outputs(sweep, results=None):
    """Rewrites atlas.csv, atlas.parquet (pyarrow present), summary.svg and
    summary.md from the finished tasks: results, [(task, result)] in the
    sweep's order (None: read from OUT/tasks)."""
    if results is None:
        results = finished_results(sweep)
    rows = table_rows(results)
    write_atomic(os.path.join(sweep.output, 'atlas.csv'), csv_text(rows))
    if importlib.util.find_spec('pyarrow') is not None:
        _write_parquet(os.path.join(sweep.output, 'atlas.parquet'), rows)
    write_atomic(os.path.join(sweep.output, 'summary.svg'), summary_svg(results, sweep.tasks))
    write_atomic(os.path.join(sweep.output, 'summary.md'), summary_md(sweep, results, rows))
    return rows
