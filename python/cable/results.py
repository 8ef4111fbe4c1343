# SPDX-License-Identifier: GPL-3.0-or-later
"""Results and solutions with AUTO-07p's behaviour (its bifDiag, parseB and
parseS objects): r('BP1'), r('BP'), r(3), r(), r + s, iteration over
branches, len, r[0], br['T'] as a numpy array; sol['T'], sol.PAR,
sol['PAR(1)'], the mesh and components as numpy arrays.

A Result holds branches computed by the engine (cable._cable.Branch, shared
and immutable); nothing here copies a solution until its mesh is asked for.
"""

__all__ = ['Parameters', 'Solution', 'SolutionList', 'Result', 'branch_columns']

import re

import numpy as np

from ._cable import Branch, CableError, curves as _curves
from .errors import CableKeyError, CableValueError
from .constants import Constants

_SPEC = re.compile(r'^([A-Z][A-Z])(\d*)$')
_TYPES = ('BP', 'LP', 'UZ', 'EP', 'MX', 'RG')


# a braid solution's geometry by name: sol['x2'] is strand 2's x, sol['xc'] the
# contact curve's, sol['p1'] the contact pressure (Solution.strand2, .contact, .pressure)
_GEOMETRY_KEYS = {'x2': ('strand2', 0), 'y2': ('strand2', 1), 'z2': ('strand2', 2),
                  'xc': ('contact', 0), 'yc': ('contact', 1), 'zc': ('contact', 2),
                  'p1': ('p1', None), 'p2': ('p2', None)}


class Parameters:
    """A solution's parameters: p['T'] or p['PAR(5)'] by name, p(5) by AUTO's
    1-based index, p[4] by 0-based index, len(p), iteration over values,
    p.toarray()."""

    def __init__(self, values, names):
        self._v = values
        self._names = names

    def _index(self, key):
        if isinstance(key, str):
            m = re.match(r'^PAR\((\d+)\)$', key)
            if m and 1 <= int(m.group(1)) <= len(self._v):
                return int(m.group(1)) - 1
            if key in self._names and self._names.index(key) < len(self._v):
                return self._names.index(key)
            raise CableKeyError('%s: no such parameter (names: %s, PAR(k))'
                                % (key, ', '.join(n for n in self._names if n)))
        k = int(key)
        if k < 0:
            k += len(self._v)
        if not 0 <= k < len(self._v):
            raise IndexError('parameter index %d out of range' % key)
        return k

    def __getitem__(self, key):
        return float(self._v[self._index(key)])

    def __call__(self, index):
        return float(self._v[int(index) - 1])

    def __contains__(self, key):
        try:
            self._index(key)
        except (CableError, IndexError, ValueError):
            return False
        return True

    def __len__(self):
        return len(self._v)

    def __iter__(self):
        return (float(x) for x in self._v)

    def keys(self):
        return [n if n else 'PAR(%d)' % (k + 1) for k, n in enumerate(self._names[:len(self._v)])]

    def toarray(self):
        return np.array(self._v)

    def __repr__(self):
        return '{%s}' % ', '.join('%r: %.10g' % (k, v) for k, v in zip(self.keys(), self._v))


class Solution:
    """One labelled solution of a branch (AUTO's parseS.AUTOSolution)."""

    __slots__ = ('_br', '_i', '_lab', '_ty', '_ibr', '_pt', '_par', '_note', '_kind', '_data',
                 '_mbr', '_mlab',
                 '_curv')

    def __init__(self, branch, index, info, mbr=0, mlab=0):
        self._br = branch
        self._i = index
        self._lab, self._ty, self._ibr, self._pt, self._par, self._note, self._kind = info
        self._data = None
        self._curv = None
        # AUTO's _mbr, _mlab: the largest branch number and label of the
        # result this solution was taken from; a run from it numbers on after
        # them (AUTO's NEWLAB), as AUTO's r1('UZ2') does
        self._mbr, self._mlab = mbr, mlab

    @property
    def kind(self):
        """A branch point's kind as the detector found it: 'simple' (the
        determinant changed sign), 'double' (two singular values vanished) or
        'pair' (two simple ones in one step); '' when this is not a BP.  A
        solution read back from files (loadbd) has it from the d-file's BP
        record on its label (the s-file, AUTO's format, has no place for it);
        '' when the d-file or its record is missing."""
        return self._kind

    @property
    def c(self):
        """The constants the solution's run used (AUTO's s.c; print(s.c) shows them as a constants
        file)."""
        return Constants(self._br.constants())

    @property
    def note(self):
        """The engine's remark on this point (the d-file's), e.g. 'double branch point: ...'; None:
        none."""
        return self._note

    # --- what AUTO's solutions offer -------------------------------------------
    @property
    def PAR(self):
        return Parameters(self._par, self._br.parnames)

    @property
    def LAB(self):
        return self._lab

    @property
    def TY(self):
        return self._ty

    @property
    def BR(self):
        return self._ibr

    @property
    def PT(self):
        return self._pt

    def _full(self):
        if self._data is None:
            self._data = self._br.solution(self._i)
        return self._data

    @property
    def indepvararray(self):
        """The mesh t in [0, 1] (NTST*NCOL+1 points), a numpy array."""
        return self._full()['t']

    @property
    def coordarray(self):
        """The components, one row per U(i): shape (NDIM, NTST*NCOL+1)."""
        return self._full()['u'].T

    @property
    def coordnames(self):
        return [n if n else 'U(%d)' % (k + 1) for k, n in enumerate(self._br.unames)]

    # --- a braid solution's geometry, at the stored points (t = sol['t']) -----------
    def _geometry(self):
        if self._curv is None:
            self._curv = _curves(self._br, self._i)
        return self._curv

    @property
    def strand1(self):
        """Strand 1's centre line, shape (NTST*NCOL+1, 3): x1, y1, z1 at sol['t']."""
        return self._geometry()['strand1'].copy()

    @property
    def strand2(self):
        """Strand 2's centre line r2 = r1 + Delta d1, shape (NTST*NCOL+1, 3), at the same points
        (strand 2's own arclength there is sol.sigma)."""
        return self._geometry()['strand2'].copy()

    @property
    def contact(self):
        """The contact curve (the braid axis) c = (r1 + r2)/2, shape (NTST*NCOL+1, 3)."""
        return self._geometry()['contact'].copy()

    @property
    def pressure(self):
        """The contact pressure along the contact curve: the force on strand 1 per unit length of
        strand 1 (p1), one value per point of sol['t'] (doc/braid-equations.md)."""
        return self._geometry()['p1'].copy()

    @property
    def pressure2(self):
        """The contact force on strand 2 per unit length of strand 2 (p2 = p1 / sigma')."""
        return self._geometry()['p2'].copy()

    @property
    def sigma(self):
        """Strand 2's arclength at the points of sol['t'] (sigma(0) = 0, sigma(1) = L2)."""
        return self._geometry()['sigma'].copy()

    @property
    def data(self):
        """Everything stored: LAB, BR, PT, TY, par, t, u, NTST, NCOL, icp, err."""
        return dict(self._full())

    def __getitem__(self, key):
        # AUTO's parseS solutions also answer to 'Label', 'Type name', 'Branch number', 'Point
        # number'
        if key in ('LAB', 'Label'):
            return self._lab
        if key in ('TY', 'TY name', 'Type name'):
            return self._ty
        if key in ('BR', 'Branch number'):
            return self._ibr
        if key in ('PT', 'Point number'):
            return self._pt
        if key == 'kind':
            return self._kind
        if key == 'PAR':
            return self.PAR
        if key == 't':
            return self.indepvararray
        if key in ('NTST', 'NCOL'):
            return self._full()[key.lower()]
        if key == 'data':
            return self.data
        if key in _GEOMETRY_KEYS and key not in self._br.unames and key not in self._br.parnames:
            which, col = _GEOMETRY_KEYS[key]
            g = self._geometry()[which]
            return g[:, col].copy() if col is not None else g.copy()
        if isinstance(key, str):
            m = re.match(r'^U\((\d+)\)$', key)
            names = self._br.unames
            if m and 1 <= int(m.group(1)) <= len(names):
                return self._full()['u'][:, int(m.group(1)) - 1].copy()
            p = self.PAR
            if key in p:
                return p[key]
            if key in names:
                return self._full()['u'][:, names.index(key)].copy()
        raise CableKeyError('%s: no such parameter or component (names: the problem\'s '
                            'parameters, PAR(k), '
                            'U(k), t, LAB, BR, PT, TY; a braid solution also x2, y2, z2, xc, yc, '
                            'zc, p1, p2)' % (key,))

    def __contains__(self, key):
        try:
            self[key]
        except CableError:
            return False
        return True

    def __eq__(self, other):
        return isinstance(other, Solution) and self._br is other._br and self._i == other._i

    def __hash__(self):
        return hash((id(self._br), self._i))

    def __repr__(self):
        return '<solution %s label %d, branch %d, point %d>' % (self._ty or '-', self._lab,
                                                                self._ibr, self._pt)

    def __str__(self):
        return ('  BR    PT  TY  LAB\n%4d %5d  %-2s %4d\n'
                % (self._ibr, self._pt, self._ty, self._lab)
                + str(self.PAR))

    # --- cable's own ---------------------------------------------------------------
    def _repr_html_(self):
        """A notebook shows the solution in cable view's page (cable.view)."""
        from .webview import view
        return view(self)._repr_html_()

    @property
    def branch(self):
        """(the engine branch, the index of this solution in it)"""
        return self._br, self._i


class SolutionList(list):
    """Solutions picked from a result: a list that can be selected from again."""

    def __call__(self, label=None):
        return _select(self, label, 'the selection')


def _solutions(branches):
    out = SolutionList()
    labels = [b.labels() for b in branches]
    mbr = max((b.ibr for b in branches), default=0)
    mlab = max((info[0] for ls in labels for info in ls), default=0)
    for b, ls in zip(branches, labels):
        out.extend(Solution(b, i, info, mbr, mlab) for i, info in enumerate(ls))
    return out


def _select(sols, label, where):
    if label is None:
        return SolutionList(sols)
    if isinstance(label, (list, tuple)):
        out = SolutionList()
        for x in label:
            y = _select(sols, x, where)
            out.extend(y if isinstance(y, list) else [y])
        return out
    if isinstance(label, (int, np.integer)) and not isinstance(label, bool):
        for s in sols:
            if s.LAB == label:
                return s
        raise CableKeyError('%d: no such label in %s' % (label, where))
    if isinstance(label, str):
        m = _SPEC.match(label)
        if m and m.group(1) in _TYPES:
            same = [s for s in sols if s.TY == m.group(1)]
            if not m.group(2):
                return SolutionList(same)
            n = int(m.group(2))
            if 1 <= n <= len(same):
                return same[n - 1]
            raise CableKeyError('%s: no such label in %s' % (label, where))
    raise CableValueError('%r: not a label: use a number, a type (BP, LP, UZ, EP, MX, RG) or a '
                          'type and '
                          'count (BP1)' % (label,))


class Result:
    """Branches computed or loaded (AUTO's bifDiag): r('BP1'), r(3), r(),
    r + s, for b in r, len(r), r[0], r['T'] (a column over all branches)."""

    def __init__(self, branches=()):
        self._br = list(branches)
        for b in self._br:
            if not isinstance(b, Branch):
                raise TypeError('a Result holds engine branches')

    @property
    def branches(self):
        return list(self._br)

    def __call__(self, label=None):
        return _select(_solutions(self._br), label, 'the result')

    def __add__(self, other):
        if isinstance(other, Result):
            return Result(self._br + other._br)
        return NotImplemented

    def __iter__(self):
        return (Result([b]) for b in self._br)

    def __len__(self):
        return len(self._br)

    def __bool__(self):
        return True

    def __getitem__(self, key):
        if isinstance(key, slice):
            return Result(self._br[key])
        if isinstance(key, str):
            cols = [_column(b, key) for b in self._br]
            return np.concatenate(cols) if cols else np.array([])
        return Result([self._br[key]])

    def getLabel(self, label):
        return self(label)

    @property
    def c(self):
        """The constants of the first branch (AUTO's branch.c: for a loaded
        file, what its b-file section's header records; r[k].c for branch k)."""
        if not self._br:
            raise CableError('the result has no branch')
        return Constants(self._br[0].constants())

    def _repr_html_(self):
        """A notebook shows the result in cable view's page (cable.view)."""
        from .webview import view
        return view(self)._repr_html_()

    def getLabels(self):
        """The labels of the labelled solutions, in order (AUTO's getLabels)."""
        return [s.LAB for s in _solutions(self._br)]

    def toArray(self):
        """Every computed point as a row of the b-file's value columns (AUTO's
        toArray: the rows without BR, PT, TY, LAB), a list of lists."""
        rows = []
        for b in self._br:
            cols = [c for _, c in branch_columns(b)]
            rows.extend([float(c[i]) for c in cols] for i in range(b.npt))
        return rows

    def summary(self):
        """AUTO's summary (what print(r) shows): per branch, the labelled
        rows under the b-file's column headings."""
        return '\n'.join(t for t in (_branch_summary(b) for b in self._br) if t) + '\n'

    @property
    def coordnames(self):
        if not self._br:
            return []
        b = self._br[0]
        return ['PAR(%d)' % k if not b.parnames[k - 1] else b.parnames[k - 1]
                for k in b.icp] + ['L2-NORM']

    def __repr__(self):
        n = sum(b.nsol for b in self._br)
        return '<result: %d branch%s, %d labelled solution%s>' % (len(self._br), ''
                                                                  if len(self._br) == 1 else 'es',
                                                                   n, '' if n == 1 else 's')

    def __str__(self):
        return self.summary()


def _column(b, key):
    """A column of branch b's points by name: a parameter, PAR(k), L2-NORM, PT, LAB, TY, BR."""
    p = b.points()
    if key in ('L2-NORM', 'PT', 'LAB', 'BR'):
        return p[key]
    if key == 'TY':
        from ._cable import type_name
        return np.array([type_name(int(x)) for x in p['TY']])
    m = re.match(r'^PAR\((\d+)\)$', key)
    names = b.parnames
    if m and 1 <= int(m.group(1)) <= p['par'].shape[1]:
        return p['par'][:, int(m.group(1)) - 1].copy()
    if key in names and names.index(key) < p['par'].shape[1]:
        return p['par'][:, names.index(key)].copy()
    raise CableKeyError("%s: no such column (the problem's parameters, PAR(k), L2-NORM, PT, LAB, "
                        "TY, BR)" % key)


# AUTO prints at most 7 parameter and MAX U columns (its WRLINE; aufile_write.c)
_SCREEN_MAX = 7


def _par_heading(b, k):
    """The heading of PAR(k+1) (0-based k): its name, or PAR(k+1)."""
    names = b.parnames
    return names[k] if k < len(names) and names[k] else 'PAR(%d)' % (k + 1)


def _u_heading(b, what, i):
    names = b.unames
    return '%s %s' % (what, names[i] if i < len(names) and names[i] else 'U(%d)' % (i + 1))


def branch_columns(b):
    """The b-file's value columns of branch b, as AUTO writes them:
    [(heading, numpy array over every point)]: ICP(1), IPLT's measure
    (L2-NORM by default), MAX U(i) (as many as fit AUTO's 7 columns), the
    other ICP parameters."""
    p = b.points()
    icp = b.icp or [1]
    ndim = p['MAX U'].shape[1]
    nicp = len(icp)
    n2 = 0 if nicp > _SCREEN_MAX else (_SCREEN_MAX - nicp if nicp + ndim > _SCREEN_MAX else ndim)
    iplt = b.constants().get('IPLT') or 0
    if iplt == 0 or ndim == 0:
        mname = 'L2-NORM'
    elif iplt < 0:
        mname = _u_heading(b, 'MIN', -iplt - 1)
    elif iplt <= ndim:
        mname = _u_heading(b, 'MAX', iplt - 1)
    elif iplt <= 2 * ndim:
        mname = _u_heading(b, 'INTEGRAL', iplt - ndim - 1)
    else:
        mname = _u_heading(b, 'L2-NORM', iplt - 2 * ndim - 1)
    par = p['par']

    def pcol(k):
        return par[:, k].copy() if k < par.shape[1] else np.full(len(par), np.nan)

    cols = [(_par_heading(b, icp[0] - 1), pcol(icp[0] - 1)), (mname, p['measure'].copy())]
    cols += [(_u_heading(b, 'MAX', i), p['MAX U'][:, i].copy()) for i in range(n2)]
    cols += [(_par_heading(b, k - 1), pcol(k - 1)) for k in icp[1:]]
    return cols


def _branch_summary(b):
    """AUTO's parseB summary of one branch: its labelled rows, headed."""
    from ._cable import type_name
    p = b.points()
    cols = branch_columns(b)
    lines = []
    for i in range(b.npt):
        ty = type_name(int(p['TY'][i])) if p['TY'][i] else ''
        if not ty or p['LAB'][i] == 0:
            continue
        if not lines:
            lines.append('\n  BR    PT  TY  LAB '
                         + ''.join('%-14s' % ('   ' + h) for h, _ in cols))
        lines.append('%4d%6d%4s%5d' % (abs(int(p['BR'][i])), abs(int(p['PT'][i])) % 10000,
                                        '  ' if ty == 'RG' else ty, int(p['LAB'][i]))
                     + ''.join('%14.5E' % c[i] for _, c in cols))
    return '\n'.join(lines)
