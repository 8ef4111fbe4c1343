# SPDX-License-Identifier: GPL-3.0-or-later
"""AUTO-07p's script commands on cable's engine (doc/scripts.md).

A Runner is AUTO's runner: it remembers the constants and problem of the last
run, and numbers a run's branch and labels as AUTO's NEWLAB does, after the
largest branch number and label of the run's restart data (the result or file
its start comes from; branch 1 and labels from 1 for a start from STPNT).
Its commands are AUTO's, with AUTO's short aliases:

  run/r/rn, load/ld, save/sv, loadbd/bd, merge/mb, relabel/rl, clean/cl,
  delete/dl, copy/cp, append/ap, cd, auto, wait, pr/printconstant/pc,
  plus cable's analyze,
  compare, overlap_free, branch_table, plot, render, known, clear_known.
"""

__all__ = ['constant_text', 'COMMANDS', 'command_names', 'Runner']

import functools
import os
import shutil
import sys
import tempfile

import numpy as np

from . import _cable, atomic, plotting, scenes
from ._cable import CableError
from .errors import CableFileNotFoundError, CableKeyError, CableTypeError, CableValueError
from .constants import Constants
from .results import Result, Solution

_NAME_KEYS = ('e', 'c', 's', 'sv', 'ap')


def constant_text(key, value):
    """KEY=VALUE in the constants-file syntax (doc/constants.md): Python's
    literal syntax, which the constants parser reads."""
    return '%s=%s' % (key, _value_text(key, value))


def _value_text(key, v):
    if isinstance(v, (bool, np.bool_)):
        return '1' if v else '0'
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        return repr(float(v))
    if isinstance(v, str):
        if "'" in v and '"' in v:
            raise CableValueError('%s: a value cannot contain both quote characters' % key)
        q = '"' if "'" in v else "'"
        return q + v + q
    if isinstance(v, np.ndarray):
        v = v.tolist()
    if isinstance(v, (list, tuple)):
        return '[' + ', '.join(_value_text(key, x) for x in v) + ']'
    if isinstance(v, dict):
        return '{' + ', '.join('%s: %s' % (_value_text(key, k), _value_text(key, x))
                               for k, x in v.items()) + '}'
    raise CableTypeError('%s: a %s is not a constants value' % (key, type(v).__name__))


def _command(name):
    """CableError messages of a command start with its name, as AUTO's CLI
    reports them (the script runner adds file and line)."""
    def wrap(fn):
        @functools.wraps(fn)
        def inner(*args, **kw):
            try:
                return fn(*args, **kw)
            except CableError as e:
                if getattr(e, 'command', None):
                    raise
                # the same class (CableKeyError stays a KeyError ...)
                err = type(e)('%s: %s' % (name, e))
                err.status = getattr(e, 'status', -2)
                err.command = name
                raise err from None
        return inner
    return wrap


def _columns(data):
    """Start data given as AUTO's columns, [[t0, ..., tn], [x0, ..., xn],
    ...] (a list or numpy array; AUTO's load(data)), as a float array of
    shape (NDIM + 1, n); None when data is not such a thing."""
    if isinstance(data, np.ndarray) or (isinstance(data, (list, tuple)) and data and
                                        not any(isinstance(x, (Solution, Result, str))
                                                for x in data)):
        try:
            a = np.array(data, dtype=float)
        except (TypeError, ValueError):
            raise CableValueError('start data: columns of numbers expected ([[t0, ..., tn], [x0, '
                                  '..., xn], ...])') from None
        if a.ndim != 2 or a.shape[0] < 2 or a.shape[1] < 2:
            raise CableValueError('start data: columns [[t0, ..., tn], [x0, ..., xn], ...] with '
                                  'at least two points '
                                  'expected, got an array of shape %s (a point solution [x, y, '
                                  '...] is for algebraic '
                                  'problems, which cable does not run)' % (a.shape,))
        if not np.all(np.isfinite(a)):
            raise CableValueError('start data: a value is not finite')
        if not np.all(np.diff(a[0]) > 0):
            raise CableValueError('start data: t (the first column) must increase')
        return a
    return None


def _start(data):
    """(start, sol, mbr, mlab, name) for the session from run()'s first
    argument; mbr, mlab: a solution's bundle maxima (AUTO's _mbr, _mlab)."""
    if data is None:
        return None, -1, 0, 0, None
    if isinstance(data, Solution):
        br, i = data.branch
        return br, i, data._mbr, data._mlab, None
    if isinstance(data, Result):
        if len(data) == 0:
            raise CableValueError('the result is empty')
        return data.branches, -1, 0, 0, None
    if isinstance(data, str):
        return None, -1, 0, 0, data
    raise CableTypeError('the start must be a solution, a result or a name, got a %s'
                         % type(data).__name__)


def _args(data, kw):
    start, sol, mbr, mlab, name = _start(data)
    names = {}
    over = []
    for k, v in kw.items():
        # a keyword is one constants key: run(**{'NMX=50, NPR': 1}) would
        # otherwise be pasted into the override text as two statements
        if not (isinstance(k, str) and k.isidentifier() and k.isascii()):
            raise CableKeyError('%r: not a constants key (a key is a name such as NMX or DS)'
                                % (k,))
        if k in _NAME_KEYS:
            if not isinstance(v, str):
                raise CableTypeError('%s: must be a non-empty name, got a %s'
                                     % (k, type(v).__name__))
            names[k] = v
        else:
            over.append(constant_text(k, v))
    return (start, sol, mbr, mlab, name, names.get('e'), names.get('c'), names.get('s'),
            names.get('sv'),
            names.get('ap'), over)


class _data_start:
    """A start given as data columns becomes a dat= file (rows t U(1) ...
    U(NDIM), as AUTO's dat files) for the run, in a temporary directory
    removed afterwards, with IRS=0 (the run starts from the data, STPNT
    giving the parameters and PAR= the rest, as dat= does)."""

    def __init__(self, data, kw):
        self.data, self.kw, self.dir = data, kw, None

    def __enter__(self):
        cols = _columns(self.data)
        if cols is None:
            return self.data, self.kw
        if 'dat' in self.kw:
            raise CableValueError('start data and dat= both given')
        self.dir = tempfile.mkdtemp(prefix='cable-dat-')
        path = os.path.join(self.dir, 'start.dat')
        with open(path, 'w') as f:
            for row in cols.T:
                f.write(' '.join(repr(float(v)) for v in row) + '\n')
        kw = dict(self.kw)
        kw['dat'] = path
        kw.setdefault('IRS', 0)
        return None, kw

    def __exit__(self, *exc):
        if self.dir:
            shutil.rmtree(self.dir, ignore_errors=True)
        return False


def _picture_file(name):
    return os.path.splitext(name)[1].lower() in ('.png', '.svg')


def _branches(x, what):
    if isinstance(x, Result):
        return x.branches, -1
    if isinstance(x, Solution):
        br, i = x.branch
        return [br], i
    raise CableTypeError('%s needs a result or a solution, got a %s' % (what, type(x).__name__))


# the commands and their aliases (AUTO's names; cable's own last)
# (AUTO's commandXxx names are the same commands: AUTOclui exports both)
COMMANDS = {
    'run': ('r', 'rn', 'commandRun'),
    'load': ('ld', 'commandRunnerLoadName', 'commandRunnerConfig'),
    'loadbd': ('bd', 'commandParseOutputFiles'), 'save': ('sv',),
    'merge': ('mb', 'commandMergeBranches'),
    'relabel': ('rl', 'commandRelabel'), 'clean': ('cl', 'commandClean'),
    'delete': ('dl', 'commandDeleteDataFiles'), 'copy': ('cp', 'commandCopyDataFiles'),
    'append': ('ap', 'commandAppend'), 'cd': ('commandCd',), 'auto': (), 'wait': ('commandWait',),
    'pr': ('printconstant', 'pc', 'commandRunnerPrintFort2'), 'analyze': (),
    'plot': ('pl', 'p2', 'commandPlotter'),
    'sl': ('solutionget', 'commandParseSolutionFile'),
    'ch': ('changeconstant', 'cc', 'commandRunnerConfigFort2'),
    'render': (), 'compare': (),
    'overlap_free': (), 'branch_table': (), 'info': (), 'branches': (),
    'known': (), 'clear_known': (),
}


def command_names():
    """Every command name and alias a script's namespace has."""
    return [n for name, aliases in COMMANDS.items() for n in (name,) + tuple(aliases)]


class Runner:
    """AUTO's runner on one engine session; its methods are the commands."""

    def __init__(self):
        self.session = _cable.Session()
        self.script_runner = None   # set by cable.script to run auto('other.auto')
        # the last run's result: AUTO's fort.7/8/9, for sv('NAME'), ap('NAME')
        self.last = None

    # --- runs -------------------------------------------------------------------------
    def run(self, data=None, **kw):
        """run([start], KEY=value, ...): one continuation run (AUTO's run):
        c='NAME' reads c.NAME, e='NAME' the problem, s='NAME' the start
        file, sv='NAME' saves b./s./d.NAME, ap='NAME' appends; every other
        keyword overrides a constant (NMX=200, DS='-', UZR={'T': -2.1}).
        The start may also be data columns [[t...], [u1...], ...] (a list or
        numpy array, AUTO's form), as a dat= file gives them."""
        sys.stdout.flush()
        with _data_start(data, kw) as (data, kw):
            try:
                self.last = Result([self.session.run(*_args(data, kw))])
            except KeyboardInterrupt as e:
                # the run stopped after its last point: the partial branch stays
                # with the exception (e.result) and as the runner's last result
                if getattr(e, 'branch', None) is not None:
                    e.result = self.last = Result([e.branch])
                raise
        return self.last

    def branches(self, data, **kw):
        """branches(bp, KEY=value, ...): the branch directions at a double branch
        point bp (doc/engine.md, "Multiple branch points" and "Symmetry: the
        restriction to Fix(S)"), as run(bp, ISW=-1, BRANCH=k) would follow them:
        a list of dicts, BRANCH (the k), phi (degrees from e1 towards e2), a
        (the coefficients of the known tangent, e1, e2), mu, L, N, dg (|g'|),
        multiplicity (equivalent directions under the problem's declared
        symmetries that the entry stands for), symmetric (it lies in a declared
        Fix(S)), sym (which symmetry, 1-based; 0 none), restricted (followed in
        the problem restricted to Fix(S)), order (2, 3: quadratic or cubic
        bifurcation equations).  [] when the equations have no real solution or
        are degenerate without a declared symmetry (the d-file note says why).
        It makes the switch's first step (one run of NMX=2, saved nowhere, that
        leaves the runner's state as it was): the keywords are those of that
        run (e=, c=, ...).  A point with no list: CableValueError."""
        for k in ('ISW', 'BRANCH', 'BPANGLE', 'BPDIR', 'NMX', 'sv', 'ap'):
            if k in kw:
                raise CableValueError('branches: %s= is set by branches itself' % k)
        kw = dict(kw, ISW=-1, NMX=2)
        sys.stdout.flush()
        with _data_start(data, kw) as (data, kw):
            # keep_state: the probe leaves the runner's constants and solution
            # (and the last result) as they were
            r = Result([self.session.run(*_args(data, kw), True)])
        br = r.branches[0] if r.branches else None
        dirs = br.directions() if br is not None else None
        if dirs is None:
            note = ''
            for s in r():
                note = s.note or note
            raise CableValueError('branches: no branch directions at this point (not a double '
                                  'branch point, or a switch that could not reduce it)%s'
                                  % (': ' + note if note else ''))
        return dirs

    def load(self, data=None, **kw):
        """load([start], KEY=value, ...): the solution a run with the same
        arguments would start from; sets the runner's constants.  None when
        that run would start from STPNT (ld(e='x', c='x') only sets the
        constants, which pr() shows)."""
        if _columns(data) is not None:
            # AUTO's load(u) makes a solution of the table itself; cable's
            # table is read by the run (as dat=), there is no solution before
            raise CableValueError('data columns are a start for run(u, ...), not for load (cable '
                                  'reads them as '
                                  'dat= when the run starts)')
        b = self.session.load(*_args(data, kw))
        return None if b is None else Result([b])(None)[0]

    def loadbd(self, name):
        """loadbd('NAME'): the labelled solutions of s.NAME (b.NAME's norms) as a result."""
        if not isinstance(name, str):
            raise CableTypeError('loadbd needs a name (files b.NAME, s.NAME)')
        return Result(self.session.loadbd(name))

    def _last_run(self, what):
        if self.last is None:
            if what in ('merge', 'relabel'):
                raise CableError("%s() works on the last run's output (AUTO's fort.7, fort.8, "
                                 "fort.9), "
                                 "but there was no run yet" % what)
            raise CableError("%s('NAME') saves the last run's output (AUTO's fort.7, fort.8, "
                             "fort.9), "
                             "but there was no run yet" % what)
        return self.last

    def save(self, data, name=None):
        """save(x, 'NAME'): b./s./d.NAME from a result or one solution;
        save('NAME'): from the last run's result (AUTO: its fort.7/8/9)."""
        if name is None and isinstance(data, str):
            data, name = self._last_run('save'), data
        br, i = _branches(data, 'save')
        if not isinstance(name, str) or not name:
            raise CableTypeError('the second argument must be a non-empty name, got a %s'
                                 % type(name).__name__)
        sys.stdout.flush()
        self.session.save(br, i, name, False)

    def append(self, x, name=None):
        """append(x, 'NAME'): x's branches appended to b./s./d.NAME;
        append('NAME1', 'NAME2'): the files NAME1 appended to NAME2."""
        if isinstance(x, str) and isinstance(name, Result):   # append('xxx', x): x after the files
            return self.loadbd(x) + name
        if isinstance(x,
                      # append('NAME'): the last run's output (AUTO: fort.*)
                      str) and name is None:
            x, name = self._last_run('append'), x
        elif isinstance(x, str):
            x = self.loadbd(x)
        if not isinstance(name, str) or not name:
            raise CableValueError('the second argument must be a non-empty name')
        br, i = _branches(x, 'append')
        sys.stdout.flush()
        self.session.save(br, i, name, True)

    def _transform(self, what, relabel, name1, name2):
        """AUTO's merge and relabel: an object gives a new one; 'A' rewrites
        the files A; 'A', 'B' writes the files A's transformed into B (A
        unchanged); no argument: the last run's result (AUTO: fort.*)."""
        if name1 is None:
            name1 = self._last_run(what)
            self.last = Result(self.session.transform(name1.branches, relabel))
            return self.last
        if isinstance(name1, str):
            if name2 is not None and not (isinstance(name2, str) and name2):
                raise CableTypeError("%s('A', 'B'): B must be a name, got a %s"
                                     % (what, type(name2).__name__))
            target = name1
            if name2 is not None and name2 != name1:
                self._copy_files(name1, name2)
                target = name2
            self.session.transform_files(target, relabel)
            print('%s done' % ('Relabeling' if relabel else 'Merging'))
            return None
        br, _ = _branches(name1, what)
        return Result(self.session.transform(br, relabel))

    def merge(self, name1=None, name2=None):
        """merge(r): the two directions from one start joined (labels
        renumbered, as AUTO's); merge('A') rewrites the files A;
        merge('A', 'B') writes A's merged into B; merge(): the last run's."""
        return self._transform('merge', False, name1, name2)

    def sl(self, name):
        """sl('NAME'): the labelled solutions of s.NAME, as a list (AUTO's sl: loadbd('NAME')()).
        """
        return self.loadbd(name)()

    def ch(self, entry=None, value=None, **kw):
        """ch('KEY', value): change one of the runner's constants (AUTO's ch / cc); ch(KEY=value,
        ...)
        likewise; the next run without a start uses them (ch('IRS', 4): label 4 of the runner's
        solutions)."""
        if entry is not None:
            if not isinstance(entry, str):
                raise CableTypeError("ch('KEY', value) takes a constant's name, got a %s"
                                     % type(entry).__name__)
            kw = dict(kw)
            kw[entry] = value
        self.load(None, **kw)
        print('  %s changed' % ', '.join('%s = %r' % kv for kv in kw.items()))

    def relabel(self, name1=None, name2=None):
        """relabel(r): labels 1, 2, ...; relabel('A') rewrites the files A;
        relabel('A', 'B') writes A's relabelled into B; relabel(): the last run's."""
        return self._transform('relabel', True, name1, name2)

    def info(self, e):
        """A problem's parameters, components, keys with their defaults and the
        constants it recommends (`cable info e=NAME`); printed, and returned as
        text.  An equation file NAME.f90, .f or .c in the run directory counts,
        as for run(e=NAME)."""
        text = self.session.info(e)
        print(text, end='')
        return text

    def pr(self, parameter=None):
        """pr(): print the runner's constants (what the next run without a
        start and without c= uses) as a constants file; pr('NTST'): return
        one of them (a number, list or dict; None when not set)."""
        c = Constants(self.session.constants())
        if parameter is None:
            sys.stdout.write(str(c))
            return None
        if not isinstance(parameter, str):
            raise CableTypeError("pr('KEY') takes a constant's name, got a %s"
                                 % type(parameter).__name__)
        return c[parameter]

    # --- files and directories ----------------------------------------------------------
    def clean(self):
        """clean(): AUTO deletes fort.* and compiled files; cable writes none."""
        print('  clean: nothing to delete (cable writes no fort.* or object files)')

    def delete(self, name):
        """delete('NAME'): removes b.NAME, s.NAME, d.NAME."""
        for t in 'bsd':
            path = '%s.%s' % (t, name)
            if os.path.exists(path):
                print('Deleting %s ...' % path)
                os.remove(path)

    def copy(self, name1, name2):
        """copy('A', 'B'): b./s./d.A copied to b./s./d.B (each file whole or not at all)."""
        self._copy_files(name1, name2, verbose=True)

    def _copy_files(self, name1, name2, verbose=False):
        found = False
        for t in 'bsd':
            src, dst = '%s.%s' % (t, name1), '%s.%s' % (t, name2)
            if not os.path.exists(src):
                continue
            found = True
            atomic.copy_file(src, dst)
            if verbose:
                print('Copying %s to %s ...' % (src, dst))
        if not found:
            raise CableFileNotFoundError('%s: no files b./s./d.%s' % (name1, name1))

    def cd(self, dir=None):
        """cd('DIR'): change directory (~ and $VARS expanded); cd(): home."""
        os.chdir(os.path.expanduser(os.path.expandvars(dir)) if dir else os.path.expanduser('~'))

    def auto(self, script=None):
        """auto('x.auto'): run another script in this runner."""
        if script is None or self.script_runner is None:
            raise CableTypeError('auto needs a script name')
        return self.script_runner(script)

    def wait(self):
        """wait(): wait for <return> (only when the input is a terminal)."""
        if sys.stdin is not None and sys.stdin.isatty():
            input('Hit <return> to continue')

    # --- branch identity ------------------------------------------------------------------
    def known(self, x):
        """known(result | solution): the branch points of the result's branches
        (or the one BP solution) become known points of every later run: a
        branch that reaches one ends there (end status CABLE_END_LOOP, end
        note "joins a known branch ... BP label L of branch B"), so an
        exploration does not compute a branch twice (doc/engine.md, Branch
        identity).  Returns the number of points added."""
        if isinstance(x, Result):
            return sum(self.session.add_known(b, -1) for b in x.branches)
        if isinstance(x, Solution):
            br, i = x.branch
            return self.session.add_known(br, i)
        raise CableTypeError('known(result | solution), got a %s' % type(x).__name__)

    def clear_known(self):
        """clear_known(): forget the known points (known())."""
        self.session.clear_known()

    # --- cable's scene functions ---------------------------------------------------------
    def analyze(self, sol, STAB=0):
        """analyze(sol) -> dict: Lk, Tw, Wr, knot type, pressure, tube distance ...
        (doc/scripts.md); analyze(sol, STAB=1) adds the Morse index: 'index',
        'nzero', 'sigma' (doc/stability.md S7)"""
        if not isinstance(sol, Solution):
            raise CableTypeError('analyze(sol) takes one solution')
        if STAB not in (0, 1):
            raise CableValueError('analyze: STAB=0 or STAB=1, got %r' % (STAB,))
        br, i = sol.branch
        return _cable.analyze(br, i, STAB) if STAB else _cable.analyze(br, i)

    def plot(self, file=None, names=None, marks=(), x=None, y=None, title=None):
        """plot('fig.png', ['name', ...], marks=[[sol, 'text'], ...], x='T', y='F', title=...):
        a diagram file; plot('name'), plot(result), plot(sol): a matplotlib
        figure (the diagram of b.name or the result; a solution's first
        component against t), as AUTO's plot(name) opens its plotter."""
        if names is None and (isinstance(file, (Result, Solution)) or
                              (isinstance(file, str) and not _picture_file(file))):
            return plotting.figure(self._plot_data(file), x=x, y=y, title=title, marks=marks)
        if file is None:
            raise CableTypeError("plot('name'), plot(result) or plot('fig.png', ['name', ...], "
                                 "marks=[[sol, 'text'], ...])")
        if isinstance(names, (Result, str)):
            names = [names]
        if (isinstance(file, str) and isinstance(names, (list, tuple)) and names and
                any(isinstance(n, Result) for n in names)):
            # results in memory: drawn by matplotlib into the file
            fig = plotting.figure([self._plot_data(n) for n in names], x=x, y=y, title=title,
                                  marks=marks)
            plotting.save(fig, file)
            print('  diagram written to %s' % file)
            return fig
        if not isinstance(file, str) or not isinstance(names, (list, tuple)) or not names or \
                not all(isinstance(n, str) for n in names):
            raise CableTypeError("plot('fig.png', ['name', ...] (saved results or results), "
                                 "marks=[[sol, 'text'], ...])")
        if marks and ((x and x != 'T') or (y and y != 'F')):
            raise CableValueError('marks: marks are drawn on the default (T, F) axes only')
        m = []
        for mk in marks:
            if len(mk) != 2 or not isinstance(mk[0], Solution) or not isinstance(mk[1], str):
                raise CableValueError('marks: marks are [solution, \'text\'] pairs')
            # a branch point is marked as one (a filled circle: the paper's
            # numbering of branch points, marks=[[bp, '1'], ...]); others open
            m.append((mk[0]['T'], mk[0]['F'], mk[1], mk[0].TY == 'BP'))
        _cable.plot(file, ['b.%s' % n for n in names], x, y, m, title)
        print('  diagram written to %s' % file)

    def _plot_data(self, x):
        if isinstance(x, str):
            return self.loadbd(x)
        if isinstance(x, (Result, Solution)):
            return x
        raise CableTypeError('plot: a name, a result or a solution expected, got a %s'
                             % type(x).__name__)

    def render(self, sol, file, view=None, size=0, thicken=0.0, color=None, vtp=None, ply=None):
        """render(sol, 'fig.png', view=[x, y, z], size=600, thicken=0, color='pressure', vtp=...,
        ply=...)"""
        if not isinstance(sol, Solution) or not isinstance(file, str):
            raise CableTypeError("render(sol, 'fig.png', view=[x, y, z], ...)")
        if color not in (None, 'pressure'):
            raise CableValueError("color: color='pressure' is the only colour map")
        if view is not None and len(view) != 3:
            raise CableValueError('view: view=[x, y, z]')
        br, i = sol.branch
        _cable.render(br, i, file, None if view is None else tuple(float(v) for v in view),
                      int(size),
                      float(thicken), color == 'pressure', vtp, ply)
        print('  label %d rendered to %s' % (sol.LAB, file))

    def compare(self, file, rows, ref=None, notes=(), stab=False):
        """compare('table.txt', [[name, x, T, F, Lk(, ref)], ...], ref=sol, notes=[...],
        stab=True) (scenes.compare; stab: the Morse index of every point)"""
        return scenes.compare(self, file, rows, ref=ref, notes=notes, stab=stab)

    def overlap_free(self, result):
        """overlap_free(result): the stretches where the tubes do not overlap (scenes.overlap_free)
        """
        return scenes.overlap_free(result)

    def branch_table(self, file, result, paper=None, title=None, stab=False):
        """branch_table('table.txt', result, paper={...}, title='...', stab=True)
        (scenes.branch_table; stab: the Morse index of every labelled point)"""
        return scenes.branch_table(self, file, result, paper=paper, title=title, stab=stab)

    # --- the namespace of a script ---------------------------------------------------------
    def namespace(self):
        """The commands under AUTO's names and aliases, for a script's globals."""
        ns = {}
        for name, aliases in COMMANDS.items():
            fn = _command(name)(getattr(self, name))
            ns[name] = fn
            for a in aliases:
                ns[a] = fn
        ns.update({'CableError': CableError, 'branch_points': scenes.branch_points,
                   'bp_kind': scenes.bp_kind,
                   'branch_point': _command('branch_point')(scenes.branch_point),
                   'mirror_table': scenes.mirror_table, 'fail': _command('fail')(scenes.fail)})
        return ns
