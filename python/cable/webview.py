# SPDX-License-Identifier: GPL-3.0-or-later
"""cable view: one self-contained HTML page that links a bifurcation diagram
to the 3-D shapes of its solutions (doc/view.md).

    cable view DIR [o=FILE.html]        # a run directory's b./s. files, or an atlas
    python3 -m cable.webview DIR [o=FILE.html]
    cable.view(result)                  # in a notebook: shown inline (_repr_html_)
    cable.view(result, 'page.html')     # the same page, written to a file

Every number the page shows is computed here by the C library: the rows of
the b-files (cable_bfile_read), the strands and contact pressures of each
labelled solution (cable_solution_strands) and its analysis (Lk, the braid
axis's knot type, tube overlap: cable_braid_analysis_compute).  The page embeds
Debian's three.js (libjs-three) and works offline from the file.
"""

__all__ = ['THREE_DIR', 'THREE_FILES', 'ANALYSIS_KEYS', 'run_data',
           'result_data', 'ATLAS_COLUMNS', 'atlas_data', 'page',
           'directory_page', 'write_page', 'View', 'view', 'main']

import base64
import glob
import html
import json
import math
import os
import sys

import numpy as np

from . import _cable
from ._cable import CableError
from .atomic import write_text
from .errors import CableFileNotFoundError, CableTypeError
from .view_page import BODY, CSS, JS

THREE_DIR = '/usr/share/javascript/three'
THREE_FILES = ('three.min.js', 'examples/js/controls/OrbitControls.js')

# the analysis values the page shows (names of _cable.analyze's dict)
ANALYSIS_KEYS = ('Lk', 'Tw', 'Wr', 'knot', 'hand', 'crossings', 'dmin', 'noverlap',
                 'overlap_length', 'pmin',
                 'pmax1', 'pmax2')


def _scripts():
    out = []
    for f in THREE_FILES:
        path = os.path.join(THREE_DIR, f)
        try:
            with open(path, encoding='utf-8') as fh:
                out.append(fh.read())
        except OSError as e:
            raise CableFileNotFoundError('%s: %s (the page embeds Debian\'s three.js: apt-get '
                                         'install libjs-three)'
                                         % (path, e.strerror)) from None
    return out


def _b64(a):
    return base64.b64encode(np.ascontiguousarray(a, dtype='<f4').tobytes()).decode('ascii')


def _finite(x):
    return x if isinstance(x, (int, str)) or (isinstance(x, float) and math.isfinite(x)) else None


def _solution(branch, i, lab, ty, pt, row, geom, offset):
    """One labelled solution: its place in the b-file rows and, for a braid
    solution, its strands and analysis appended to geom."""
    s = {'lab': int(lab), 'ty': ty, 'pt': int(pt), 'row': int(row), 'n': 0}
    try:
        st = _cable.strands(branch, i)
        a = _cable.analyze(branch, i)
    except CableError as e:
        s['why'] = str(e)
        return s, offset
    n = st['n']
    parts = [np.frombuffer(st[k], dtype=np.float64) for k in ('r1', 'r2', 'p1', 'p2')]
    geom.extend(parts)
    s.update(n=n, off=offset, radius=st['radius'], closed=st['closed'],
             a={k: _finite(a[k]) for k in ANALYSIS_KEYS})
    return s, offset + 8 * n


def _section(name, columns, data, pt, ty, lab, sols):
    """One branch of the diagram: columns [ncol][npt] (named), the rows' PT,
    TY, LAB, and its labelled solutions [(branch, i, LAB, TY, BR, PT)]."""
    npt = len(pt)
    row_of = {int(l): k for k, l in enumerate(lab) if l}
    geom, entries, off = [], [], 0
    for (b, i, slab, sty, sbr, spt) in sols:
        if slab not in row_of:
            continue
        e, off = _solution(b, i, slab, sty, spt, row_of[slab], geom, off)
        entries.append(e)
    return {'name': name, 'npt': npt, 'colnames': list(columns), 'coldata': data,
            'pt': [int(x) for x in pt],
            'ty': [int(x) for x in ty], 'sols': entries,
            'geometry': _b64(np.concatenate(geom)) if geom else ''}


def _finish(title, sections):
    """The page's run: every section's columns on the union of the names
    (NaN where a branch has no such column)."""
    names = []
    for s in sections:
        for c in s['colnames']:
            if c not in names:
                names.append(c)
    for s in sections:
        cols = np.full((len(names), s['npt']), np.nan)
        for k, c in enumerate(s.pop('colnames')):
            cols[names.index(c)] = s['coldata'][k]
        s.pop('coldata')
        s['data'] = _b64(cols)
    x = names[0] if names else 'PT'
    y = 'F' if 'F' in names else 'L2-NORM' if 'L2-NORM' in names else names[-1]
    return {'kind': 'run', 'title': title, 'columns': names, 'xdefault': x, 'ydefault': y,
            'branches': sections}


def _bnames(directory):
    """NAME of every b.NAME in directory (not the CSV copies b.NAME.k.csv)."""
    out = []
    for p in sorted(glob.glob(os.path.join(directory, 'b.*'))):
        name = os.path.basename(p)[2:]
        if name.endswith('.csv') or '.tmp' in name or not os.path.isfile(p):
            continue
        out.append(name)
    return out


def run_data(directory, title=None):
    """The page data of a run directory: every b.NAME and, where s.NAME is
    there, its labelled solutions."""
    from .commands import Runner
    directory = os.path.abspath(directory)
    names = _bnames(directory)
    if not names:
        raise CableFileNotFoundError('%s: no b-files (b.NAME) in this directory' % directory)
    runner = Runner()
    here = os.getcwd()
    runner.cd(directory)   # loadbd reads from the runner's directory
    try:
        return _run_data(runner, directory, names, title)
    finally:
        os.chdir(here)


def _run_data(runner, directory, names, title):
    sections = []
    for name in names:
        secs = _cable.bfile(os.path.join(directory, 'b.' + name))
        sols = {}
        if os.path.isfile(os.path.join(directory, 's.' + name)):
            for b in runner.loadbd(name).branches:
                for i, lab in enumerate(b.labels()):
                    sols.setdefault(abs(int(lab[2])),
                                    []).append((b, i, int(lab[0]), lab[1], int(lab[2]),
                                                int(lab[3])))
        for k, sec in enumerate(secs):
            npt = len(sec['pt'])
            data = np.frombuffer(sec['data'], dtype=np.float64).reshape(len(sec['columns']), npt)
            brs = {abs(x) for x in sec['br']}
            mine = [s for br in sorted(brs) for s in sols.get(br, [])]
            label = name if len(secs) == 1 else '%s (%d)' % (name, k + 1)
            sections.append(_section(label, sec['columns'], data, sec['pt'], sec['ty'],
                                     sec['lab'], mine))
    return _finish(title or os.path.basename(os.path.abspath(directory)), sections)


def result_data(result, title='cable result', select=None):
    """The page data of a Result's engine branches (a run in a script or a
    notebook): the rows of each branch and its labelled solutions."""
    sections = []
    for k, b in enumerate(result.branches):
        p = b.points()
        names = [n or 'PAR(%d)' % (j + 1) for j, n in enumerate(b.parnames[:p['par'].shape[1]])]
        cols = [names[j - 1] for j in b.icp if j - 1 < len(names)]
        if 'F' in names and 'F' not in cols:
            cols.append('F')
        data = [p['par'][:, names.index(c)] for c in cols] + [p['L2-NORM']]
        sols = [(b, i, int(lab[0]), lab[1], int(lab[2]), int(lab[3]))
                for i, lab in enumerate(b.labels())]
        sections.append(_section('branch %d' % b.ibr if len(result.branches) > 1 or not b.ibr
                                 else 'branch %d' % b.ibr,
                                 cols + ['L2-NORM'], np.array(data), p['PT'], p['TY'],
                                 p['LAB'], sols))
    d = _finish(title, sections)
    if select is not None:
        d['select'] = select
    return d


ATLAS_COLUMNS = ('family', 'Delta', 'mode', 'segment', 'companion', 'Lk', 'overlap_free', 'T_free',
                 'F_free',
                 'T_free_end', 'F_free_end', 'free_end', 'dmin', 'status')


def atlas_data(directory):
    """The page data of an atlas output directory (doc/atlas.md): every task
    with its rows (result.json) and, where its b./s. files are there, its
    run (the flat branch and the branch from its branch point)."""
    tasks = []
    for tdir in sorted(glob.glob(os.path.join(directory, 'tasks', '*'))):
        if not os.path.isdir(tdir):
            continue
        name = os.path.basename(tdir)
        try:
            with open(os.path.join(tdir, 'result.json'), encoding='utf-8') as fh:
                res = json.load(fh)
        except (OSError, ValueError):
            continue   # a task not finished yet
        rows = [{k: _finite(r.get(k)) for k in ATLAS_COLUMNS} for r in res.get('rows', [])] or \
            [{'status': res.get('status'), 'family': name}]
        task = {'name': name, 'rows': rows, 'run': None}
        if _bnames(tdir):
            task['run'] = run_data(tdir, title=name)
        else:
            task['why'] = ('no b./s. files in tasks/%s: the repository keeps each task\'s '
                           'result.json; '
                           'the files are there where the atlas ran ([record] files = true)'
                           % name)
        tasks.append(task)
    if not tasks:
        raise CableFileNotFoundError('%s: no finished atlas task (tasks/NAME/result.json)'
                                     % directory)
    nrun = sum(1 for t in tasks if t['run'])
    return {'kind': 'atlas', 'title': 'atlas %s: %d tasks, %d with b./s. files'
            % (os.path.basename(os.path.abspath(directory)), len(tasks), nrun),
            'columns': list(ATLAS_COLUMNS), 'tasks': tasks}


def page(data):
    """The HTML page of data (run_data, result_data or atlas_data)."""
    three, orbit = _scripts()
    js = json.dumps(data, separators=(',', ':'), allow_nan=False).replace('</', '<\\/')
    return ''.join(['<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">\n<title>cable '
                    'view</title>',
                    '\n<style>', CSS, '</style></head>\n<body>', BODY,
                    '\n<script>/* three.js r111 (Debian libjs-three, MIT licence) */\n', three,
                    '\n</script>\n<script>/* OrbitControls (three.js examples, MIT licence) */\n',
                    orbit,
                    '\n</script>\n<script>var DATA = ', js, ';\n</script>\n<script>', JS,
                    '</script>\n</body></html>\n'])


def directory_page(directory):
    """The page of a run directory or an atlas (a directory with tasks/)."""
    if not os.path.isdir(directory):
        raise CableFileNotFoundError('%s: no such directory' % directory)
    if os.path.isdir(os.path.join(directory, 'tasks')):
        return page(atlas_data(directory))
    return page(run_data(directory))


def write_page(text, path):
    """Write text to path atomically (a temporary file renamed over it)."""
    return write_text(path, text)


class View:
    """The page of a result or solution: shown inline in a notebook
    (_repr_html_: the page in an iframe), save(path) writes it."""

    def __init__(self, text):
        self.html = text

    def _repr_html_(self):
        return ('<iframe style="width:100%%;height:1020px;border:1px solid #ccc" '
                'sandbox="allow-scripts" '
                'srcdoc="%s"></iframe>' % html.escape(self.html, quote=True))

    def save(self, path):
        return write_page(self.html, path)


def view(x, file=None, title=None):
    """view(result | solution | 'DIR' [, 'page.html']): the interactive page.
    Without a file name: a View (a notebook shows it); with one: the page
    written there (its path returned)."""
    from .results import Result, Solution
    if isinstance(x, str):
        text = directory_page(x)
    elif isinstance(x, Solution):
        r = Result([x.branch[0]])
        d = result_data(r, title or 'label %d' % x.LAB, select=x.LAB)
        text = page(d)
    elif isinstance(x, Result):
        text = page(result_data(x, title or 'cable result'))
    else:
        raise CableTypeError('view() takes a result, a solution or a directory name, not %s'
                             % type(x).__name__)
    v = View(text)
    return v.save(file) if file else v


def main(argv):
    out, dirs = None, []
    for a in argv:
        if a.startswith('o='):
            out = a[2:]
        elif '=' in a:
            print('cable: view: %s: unknown option (o=FILE.html)' % a, file=sys.stderr)
            return 2
        else:
            dirs.append(a)
    if len(dirs) != 1:
        print('cable: usage: cable view DIR [o=FILE.html]', file=sys.stderr)
        return 2
    if out is None:
        out = os.path.join(dirs[0], 'view.html')
    if not out.endswith('.html'):
        print('cable: %s: o: the file name must end in .html' % out, file=sys.stderr)
        return 2
    try:
        text = directory_page(dirs[0])
        write_page(text, out)
    except (CableError, OSError) as e:
        print('cable: view: %s' % e, file=sys.stderr)
        return 1
    print('cable: page written to %s (%.1f MB)' % (out, len(text.encode('utf-8')) / 1e6))
    return 0


if __name__ == '__main__':
    _cable.blas_single_thread()
    sys.exit(main(sys.argv[1:]))
