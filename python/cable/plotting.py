# SPDX-License-Identifier: GPL-3.0-or-later
"""plot(name), plot(result), plot(sol) as matplotlib figures (AUTO's plot
opens its plotter window on the same data; cable returns a Figure, which a
notebook shows and fig.savefig writes).  A diagram: each branch's first
b-file column (ICP(1)) against its second (IPLT's measure, L2-NORM by
default), AUTO's default axes, or the columns x= and y= name; labelled
points marked with their type and label.  A solution: its first component
against t (or the components x=, y= name).  Figures are made without
pyplot, so no window or GUI backend is needed.
"""

__all__ = ['figure', 'save']

from ._cable import CableError
from .errors import CableTypeError, CableValueError
from .results import Result, Solution, branch_columns


def _matplotlib():
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError:
        raise CableError("plot: drawing a figure needs matplotlib (Debian's python3-matplotlib, "
                         "which "
                         "scripts/install-deps.sh installs); plot('fig.png', ['name', ...]) draws "
                         "without it") from None
    return Figure, FigureCanvasAgg


def _column(b, r, key, default):
    """A branch's column by name (a parameter, PAR(k), L2-NORM, MAX U(i)) or
    its default (0: the first b-file column, 1: the second)."""
    cols = branch_columns(b)
    if key is None:
        return cols[default]
    for h, c in cols:
        if h == key:
            return h, c
    return key, r[key]


def _diagram(ax, results, x, y, marks):
    from ._cable import type_name
    xl = yl = None
    for r in results:
        for b in r.branches:
            one = Result([b])
            xl, xs = _column(b, one, x, 0)
            yl, ys = _column(b, one, y, 1)
            line, = ax.plot(xs, ys, '-', lw=1)
            p = b.points()
            for i in range(b.npt):
                if p['LAB'][i] > 0 and p['TY'][i]:
                    ty = type_name(int(p['TY'][i]))
                    if ty in ('RG', ''):
                        continue
                    ax.plot([xs[i]], [ys[i]], 'o', ms=4, color=line.get_color())
                    ax.annotate('%s%d' % (ty, p['LAB'][i]), (xs[i], ys[i]),
                                textcoords='offset points',
                                xytext=(4, 4), fontsize=8)
    for sol, text in marks:
        if not isinstance(sol, Solution) or not isinstance(text, str):
            raise CableValueError("marks: marks are [solution, 'text'] pairs")
        xs, ys = sol[xl], sol[yl]
        ax.plot([xs], [ys], 'kx')
        ax.annotate(text, (xs, ys), textcoords='offset points', xytext=(4, -12), fontsize=9)
    ax.set_xlabel(xl or '')
    ax.set_ylabel(yl or '')


def _solution(ax, sol, x, y):
    names = sol.coordnames
    xk = x or 't'
    yk = y or names[0]
    ax.plot(sol[xk], sol[yk], '-', lw=1)
    ax.set_xlabel(xk)
    ax.set_ylabel(yk)
    ax.set_title('%s label %d' % (sol.TY or '-', sol.LAB))


def figure(data, x=None, y=None, title=None, marks=()):
    """A matplotlib Figure of a result, a list of results, or a solution."""
    Figure, FigureCanvasAgg = _matplotlib()
    fig = Figure(figsize=(6.4, 4.8))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1)
    if isinstance(data, Solution):
        _solution(ax, data, x, y)
    else:
        results = data if isinstance(data, (list, tuple)) else [data]
        for r in results:
            if not isinstance(r, Result):
                raise CableTypeError('plot: a result or a solution expected, got a %s'
                                     % type(r).__name__)
        _diagram(ax, results, x, y, marks)
    if title:
        ax.set_title(title)
    return fig


def save(fig, path):
    """The figure written to path (PNG or SVG by its extension), whole or not at all."""
    import os
    from .atomic import replacing
    ext = os.path.splitext(path)[1]
    with replacing(path, suffix=ext) as tmp:
        fig.savefig(tmp, format=ext[1:].lower() or 'png')
