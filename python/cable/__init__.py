# SPDX-License-Identifier: GPL-3.0-or-later
"""cable: equilibria of elastic cable knots and links by numerical
continuation, with AUTO-07p's command-line interface.

    import cable
    flat = cable.run(e='braid_knot', c='knot72', sv='flat')
    m1 = cable.run(flat('BP1'), e='braid_knot_sym', c='knot72sym', UZR={'T': -2.10752})

Scripts (`cable replay X.auto`, `python3 -m cable X.auto`) get these commands
preloaded, as AUTO's `auto X.auto` does (cable.script).  doc/scripts.md lists
the commands and where they differ from AUTO's.
"""
import threading

from ._cable import CableError
from .errors import CableFileNotFoundError, CableKeyError, CableTypeError, CableValueError
from .commands import Runner, constant_text
from .constants import Constants
from .results import Parameters, Result, Solution, SolutionList
from . import scenes
from .script import run_script

_runner = None
_runner_lock = threading.Lock()


def runner():
    """The module's own runner (AUTO's interactive one), made on first use
    (once, also when threads ask at the same time: they share it, and its
    commands run one after the other)."""
    global _runner
    with _runner_lock:
        if _runner is None:
            _runner = Runner()
        return _runner


def _delegate(name):
    def fn(*args, **kw):
        return runner().namespace()[name](*args, **kw)
    fn.__name__ = name
    fn.__doc__ = getattr(Runner, name, None).__doc__ if hasattr(Runner, name) else None
    return fn


_COMMANDS = ('run', 'r', 'load', 'ld', 'loadbd', 'bd', 'save', 'sv', 'merge', 'mb', 'relabel',
             'rl', 'clean', 'cl',
             'delete', 'dl', 'copy', 'cp', 'append', 'ap', 'cd', 'wait', 'pr', 'printconstant',
             'pc', 'analyze', 'plot', 'render', 'compare',
             'overlap_free', 'branch_table', 'info', 'branches', 'known', 'clear_known')
for _n in _COMMANDS:
    globals()[_n] = _delegate(_n)
del _n



def view(x, file=None, title=None):
    """view(result | solution | 'DIR' [, 'page.html']): cable view's page (doc/view.md);
    a notebook shows it inline.  (cable.webview is imported on first use, so that
    `python3 -m cable.webview` runs it as a script without a second copy.)"""
    from .webview import view as _view
    return _view(x, file, title)


def explore(TORUS, HAND, Delta, **kw):
    """explore(TORUS=p, HAND=+-1, Delta=..., Ltot=..., modes=N, out='DIR', ...): the flat
    branch of a torus knot or link, its branch points and every branch from the
    first N of them, with the diagram, pictures and table (cable.explorer,
    doc/explore.md)."""
    from .explorer import explore as _explore
    return _explore(TORUS, HAND, Delta, **kw)


branch_points = scenes.branch_points
branch_point = scenes.branch_point
mirror_table = scenes.mirror_table

__all__ = ['CableError', 'CableFileNotFoundError', 'CableKeyError', 'CableTypeError',
           'CableValueError',
           'Runner', 'constant_text', 'Constants', 'Parameters', 'Result', 'Solution',
           'SolutionList',
           'scenes', 'run_script', 'runner', 'view', 'branch_points', 'branch_point',
           'mirror_table', 'explore'] + list(_COMMANDS)
