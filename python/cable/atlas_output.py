"""The atlas's outputs, rebuilt (each file atomically) from the finished
tasks of a sweep: OUT/atlas.csv (one row per cable knot or link found, plus
one row per failed task), OUT/atlas.parquet when pyarrow is installed,
OUT/summary.svg (families against Delta, one cell per arm and mode, coloured
by the companion knot type and Lk the branch reaches: cell_outcome) and
OUT/summary.md (counts and the picture)."""
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
            rows.append({'family': '%s(%d,2)' % (i['kind'], i['p']), 'kind': i['kind'], 'p': i['p'],
                         'hand': i['hand'], 'Delta': i['Delta'], 'arm': i['arm'], 'mode': i['mode'],
                         'wall': r['wall'], 'status': r['status'], 'error': r['error'], 'task': t.name})
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

_PALETTE = ['#4e79a7', '#f28e2b', '#e15759', '#76b7b2', '#59a14f', '#edc948', '#b07aa1', '#ff9da7', '#9c755f',
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


def _esc(s):
    return s.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')


def summary_svg(results, tasks=None):
    """The picture: a row per family, a group of cells per Delta, a cell per
    arm and mode, for every task of tasks (default: those of results), so
    that an empty cell is a task not computed yet."""
    fams, deltas, cols = [], [], []
    cell = {}

    def where(t):
        i = t.inputs
        return '%s(%d,2) %s' % (i['kind'], i['p'], 'R' if i['hand'] > 0 else 'L'), i['Delta'], (i['arm'], i['mode'])

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
    cw, ch, left, top = 18, 18, 130, 78
    title = ['cable atlas: the companion knot type and Lk each branch reaches',
             '(its overlap-free stretch with the most axis passages; a cell per arm and mode)']
    # text widths estimated at 0.62 em per character (sans-serif), so that nothing overlaps
    labels = ['Delta = %.4g' % d for d in deltas]
    gw = max([len(cols) * cw + 12, 110] + [int(0.62 * 11 * len(x)) + 14 for x in labels])
    width = max(left + len(deltas) * gw + 20, int(0.62 * 13 * max(len(x) for x in title)) + 16,
                int(0.62 * 11 * max([len(v) for v in kinds] + [0])) + 40)
    height = top + len(fams) * ch + 30 + 16 * len(kinds)
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
           'font-size="11">' % (width, height),
           '<rect width="100%" height="100%" fill="white"/>']
    out += ['<text x="8" y="%d" font-size="13">%s</text>' % (18 + 17 * k, _esc(x)) for k, x in enumerate(title)]
    for j, d in enumerate(deltas):
        x = left + j * gw
        out.append('<text x="%d" y="%d">%s</text>' % (x, top - 22, labels[j]))
        for m, c in enumerate(cols):
            out.append('<text x="%d" y="%d" font-size="9">%s%d</text>' % (x + m * cw + 3, top - 6,
                                                                          '+' if c[0] > 0 else '-', c[1]))
    for i, f in enumerate(fams):
        y = top + i * ch
        out.append('<text x="8" y="%d">%s</text>' % (y + 13, _esc(f)))
        for j, d in enumerate(deltas):
            for m, c in enumerate(cols):
                v = cell.get((f, d, c))
                x = left + j * gw + m * cw
                if v is None:
                    out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#bbbbbb"/>'
                               % (x, y, cw - 2, ch - 2))
                else:
                    out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="%s"><title>%s</title></rect>'
                               % (x, y, cw - 2, ch - 2, colour[v], _esc(v)))
    y = top + len(fams) * ch + 20
    for v in kinds:
        out.append('<rect x="8" y="%d" width="12" height="12" fill="%s" stroke="#888888"/>' % (y - 10, colour[v]))
        out.append('<text x="26" y="%d">%s</text>' % (y, _esc(v)))
        y += 16
    out.append('<text x="8" y="%d" fill="#888888">empty cell: not computed yet</text>' % y)
    out.append('</svg>')
    return '\n'.join(out) + '\n'


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
