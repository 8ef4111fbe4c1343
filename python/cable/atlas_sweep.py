# SPDX-License-Identifier: GPL-3.0-or-later
"""The sweep file of cable.atlas (doc/atlas.md): a TOML file read with
Python's tomllib, checked whole before any task starts, and expanded into
tasks, each keyed by a hash of everything that determines its result.

    sweep = load('sweep.toml')        # SweepError naming file, line and key
    for t in sweep.tasks: t.key, t.name, t.inputs
"""

__all__ = ['TASK_VERSION', 'FLAT_VERSION', 'FLAT_DEFAULTS', 'BRANCH_DEFAULTS',
           'MESH_DEFAULTS', 'KNOT_LTOT', 'LINK_L', 'SweepError', 'Task',
           'FlatTask', 'flat_inputs', 'Sweep', 'knotting_arm', 'contact_limit',
           'auto_ntst', 'load']

import hashlib
import json
import math
import os
import re
import tomllib

# Bumped whenever what a task computes from its inputs changes, so that a
# resumed sweep recomputes the tasks of an older algorithm.  2: the branch
# starts from the shared flat branch's s-file (FlatTask), not from the
# task's own flat run in memory.
TASK_VERSION = 2
# The same for the shared flat branches (FlatTask).
FLAT_VERSION = 1

# The AUTO constants a sweep may set for the flat branch ([flat]) and the
# mode branches ([branch]), with their defaults (doc/atlas.md says why).
FLAT_DEFAULTS = {'DS': 2.0, 'DSMIN': 1e-6, 'DSMAX': 10.0, 'NMX': 200, 'NPR': 0, 'RL0': -200.0,
                 'RL1': 200.0,
                 'EPSL': 1e-7, 'EPSU': 1e-7, 'EPSS': 1e-7, 'ITNW': 5, 'NWTN': 3, 'ITMX': 8,
                 'IAD': 3}
BRANCH_DEFAULTS = {'DS': 0.05, 'DSMIN': 1e-6, 'DSMAX': 2.0, 'NMX': 400, 'NPR': 10, 'RL0': -200.0,
                   'RL1': 200.0,
                   'EPSL': 1e-7, 'EPSU': 1e-7, 'EPSS': 1e-7, 'ITNW': 5, 'NWTN': 3, 'ITMX': 8,
                   'IAD': 3}
_INT_CONSTANTS = ('NMX', 'NPR', 'ITNW', 'NWTN', 'ITMX', 'IAD')
MESH_DEFAULTS = {'NTST': 30, 'NCOL': 4}
KNOT_LTOT = 1.98889      # the knot72 scene's total length (both strands)
LINK_L = 1.0             # the link scenes' strand length

_TOP_KEYS = ('output', 'deltas', 'modes', 'arms', 'switch', 'family', 'mesh', 'flat', 'branch',
             'record')
# How a task switches at its branch point (cable.explorer.follow): 'sym' (the
# S0-symmetric formulation at a double point, the plain problem at a simple
# one: the atlas's rule before explore, and its default, so that the keys of
# stored tasks stay as they were), 'auto' (every direction the bifurcation
# equations give on the plain problem, the S0 formulation when they give
# none), 'plain'.  Only a value other than 'sym' enters the task's inputs.
SWITCHES = ('sym', 'auto', 'plain')
_FAMILY_KEYS = ('kind', 'p', 'hands', 'deltas', 'modes', 'arms', 'length')
_RECORD_KEYS = ('files',)


class SweepError(Exception):
    """A sweep file that cannot be run: the message names file, line and key."""


class Task:
    """One scene: a flat branch to its mode-th branch point on one arm and
    the branch from that point.  inputs is everything the result depends
    on; key its hash; name a readable directory name ending in the key."""

    def __init__(self, inputs):
        self.inputs = inputs
        text = json.dumps(inputs, sort_keys=True, separators=(',', ':'))
        self.key = hashlib.sha256(text.encode()).hexdigest()[:16]
        i = inputs
        self.name = '%s%d%s-D%s-arm%s-m%d-%s' % (i['kind'], i['p'], 'R' if i['hand'] > 0 else 'L',
                                                 _num(i['Delta']), '+' if i['arm'] > 0 else '-',
                                                 i['mode'],
                                                 self.key)
        # the flat branch it starts from (load() shares one between a family's modes)
        self.flat = FlatTask(flat_inputs(inputs, inputs['mode']))

    def __repr__(self):
        return '<atlas task %s>' % self.name


class FlatTask:
    """The flat branch of one (family, hand, Delta, arm, mesh, [flat]
    constants), from T = 0 along the arm to its bps-th branch point, shared
    by the mode tasks 1..bps of a sweep: a keyed, resumable result of its
    own (OUT/flat/NAME, doc/atlas.md 2).  A mode task needs only the
    flat branch's prefix up to its own branch point, which is the same
    whatever later point the run stops at (the run is deterministic)."""

    def __init__(self, inputs):
        self.inputs = inputs
        text = json.dumps(inputs, sort_keys=True, separators=(',', ':'))
        self.key = hashlib.sha256(text.encode()).hexdigest()[:16]
        i = inputs
        self.name = 'flat-%s%d%s-D%s-arm%s-bp%d-%s' % (i['kind'], i['p'], 'R' if i['hand'] > 0
                                                       else 'L',
                                                      _num(i['Delta']), '+' if i['arm'] > 0
                                                      else '-', i['bps'],
                                                      self.key)

    def __repr__(self):
        return '<atlas flat branch %s>' % self.name


def flat_inputs(task_inputs, bps):
    """The inputs of the flat branch a mode task starts from, run to its
    bps-th branch point (bps >= the task's mode)."""
    i = task_inputs
    return {'version': FLAT_VERSION, 'kind': i['kind'], 'p': i['p'], 'hand': i['hand'],
            'Delta': i['Delta'],
            'length': i['length'], 'arm': i['arm'], 'mesh': i['mesh'], 'flat': i['flat'],
            'bps': bps}


def _num(x):
    return ('%.10g' % x).replace('+', '')


class Sweep:
    """A checked sweep: path, output directory, tasks, record options."""

    def __init__(self, path, output, tasks, record):
        self.path = path
        self.output = output
        self.tasks = tasks
        self.record = record


class _Where:
    """Line numbers of keys in the TOML text (tomllib gives none): the line
    of `key =` inside the table (or the n-th array-of-tables entry) named."""

    def __init__(self, path, text):
        self.path = path
        self.lines = text.splitlines()

    def line(self, key, table=None, index=None):
        cur, count = None, {}
        for n, raw in enumerate(self.lines, 1):
            s = raw.split('#', 1)[0].strip()
            m = re.match(r'^\[\[\s*([A-Za-z0-9_]+)\s*\]\]$', s)
            if m:
                count[m.group(1)] = count.get(m.group(1), -1) + 1
                cur = (m.group(1), count[m.group(1)])
                if key is None and table == m.group(1) and index == cur[1]:
                    return n
                continue
            m = re.match(r'^\[\s*([A-Za-z0-9_]+)\s*\]$', s)
            if m:
                cur = (m.group(1), None)
                if key is None and table == m.group(1):
                    return n
                continue
            m = re.match(r'^"?([A-Za-z0-9_]+)"?\s*=', s)
            if m and m.group(1) == key and (cur == (table, index) if table else cur is None):
                return n
        return 0

    def error(self, msg, key=None, table=None, index=None):
        n = self.line(key, table, index)
        where = '%s:%d' % (self.path, n) if n else self.path
        name = key if key is not None else table
        if table and key is not None:
            name = '%s%s.%s' % (table, '' if index is None else '[%d]' % (index + 1), key)
        return SweepError('%s: %s: %s' % (where, name, msg))


def _is_num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _list(w, v, key, table=None, index=None):
    if not isinstance(v, list) or not v:
        raise w.error('must be a non-empty list', key, table, index)
    return v


def _deltas(w, v, table=None, index=None):
    out = []
    for x in _list(w, v, 'deltas', table, index):
        if not _is_num(x) or x <= 0:
            raise w.error('Delta must be a positive number, got %r' % (x,), 'deltas', table, index)
        out.append(float(x))
    return out


def _modes(w, v, table=None, index=None):
    out = []
    for x in _list(w, v, 'modes', table, index):
        if not isinstance(x, int) or isinstance(x, bool) or x < 1:
            raise w.error('a mode is the n-th branch point of the arm, n >= 1; got %r' % (x,),
                          'modes', table,
                          index)
        out.append(x)
    return out


def _arms(w, v, table=None, index=None):
    out = []
    for x in _list(w, v, 'arms', table, index):
        if x not in ('knotting', '+', '-'):
            raise w.error('an arm is "knotting", "+" (T > 0) or "-" (T < 0); got %r' % (x,),
                          'arms', table,
                          index)
        out.append(x)
    return out


def knotting_arm(kind, hand):
    """The sign of T on the flat branch whose branches knot the axis in the
    paper's scenes: a knot's own handedness (runs/knot72: right-handed knot,
    T > 0), a link's opposite one (runs/link62, link43, link102: left-handed
    link, T > 0)."""
    return hand if kind == 'knot' else -hand


def contact_limit(kind, length):
    """A necessary condition on Delta for a flat (p,2) torus braid to exist:
    the braid (the two strands, centrelines Delta/2 from the axis, tubes of
    radius Delta/2, so reaching Delta from the axis) fits inside the radius
    of curvature of its axis, a circle of length at most the strand length
    (length of a link's strand; half the knot's total length).  Returns the
    bound Delta < axis length / (2 pi)."""
    axis = length / 2 if kind == 'knot' else length
    return axis / (2 * math.pi)


def _constants(w, v, table, defaults):
    if v is None:
        return dict(defaults)
    if not isinstance(v, dict):
        raise w.error('must be a table', None, table)
    out = dict(defaults)
    for k, x in v.items():
        if k not in defaults:
            raise w.error('unknown key (the AUTO constants allowed here: %s)'
                          % ', '.join(sorted(defaults)), k,
                          table)
        if k in _INT_CONSTANTS:
            if not isinstance(x, int) or isinstance(x, bool) or x < 0:
                raise w.error('must be a non-negative integer', k, table)
        elif not _is_num(x):
            raise w.error('must be a number', k, table)
        if k in ('DSMIN', 'DSMAX', 'EPSL', 'EPSU', 'EPSS') and x <= 0:
            raise w.error('must be positive', k, table)
        out[k] = int(x) if k in _INT_CONSTANTS else float(x)
    if out['DSMIN'] > out['DSMAX']:
        raise w.error('DSMIN > DSMAX', 'DSMIN', table)
    if out['RL0'] >= out['RL1']:
        raise w.error('RL0 must be below RL1', 'RL0', table)
    return out


def _mesh(w, v):
    out = dict(MESH_DEFAULTS)
    if v is None:
        return out
    if not isinstance(v, dict):
        raise w.error('must be a table', None, 'mesh')
    for k, x in v.items():
        if k not in out:
            raise w.error('unknown key (NTST, NCOL)', k, 'mesh')
        if k == 'NTST' and x == 'auto':
            out[k] = x
            continue
        if not isinstance(x, int) or isinstance(x, bool):
            raise w.error('must be an integer%s' % (' or "auto"' if k == 'NTST' else ''), k,
                          'mesh')
        if (k == 'NCOL' and not 2 <= x <= 7) or (k == 'NTST' and x < 2):
            raise w.error('out of range (NTST >= 2, 2 <= NCOL <= 7)', k, 'mesh')
        out[k] = x
    return out


def auto_ntst(kind, p):
    """NTST = "auto": the flat braid turns p/2 times about its axis, and
    the torus scene's measurements (runs/torus/c.knot, c.link: |Lk - p/2|
    below 1e-6 at NCOL 4) ask for NTST = max(60, 4p) for knots and
    max(60, 6p) for links; the atlas takes 30 as the floor, the knot72
    scene's NTST (its NCOL 7 meets 1e-8 in F there, doc/benchmarks.md)."""
    return max(30, (4 if kind == 'knot' else 6) * p)


def _family(w, f, i, top):
    t = 'family'
    if not isinstance(f, dict):
        raise w.error('each [[family]] must be a table', None, t, i)
    for k in f:
        if k not in _FAMILY_KEYS:
            raise w.error('unknown key (a family has %s)' % ', '.join(_FAMILY_KEYS), k, t, i)
    kind = f.get('kind')
    if kind not in ('knot', 'link'):
        raise w.error('kind must be "knot" ((p,2) torus knots, p odd) or "link" ((p,2) torus '
                      'links, p even)',
                      'kind', t, i)
    if 'p' not in f:
        raise w.error('missing key p (a list of p of the (p,2) torus %ss)' % kind, 'kind', t, i)
    ps = f['p'] if isinstance(f['p'], list) else [f['p']]
    for p in ps:
        if not isinstance(p, int) or isinstance(p, bool):
            raise w.error('p must be an integer, got %r' % (p,), 'p', t, i)
        if kind == 'knot' and (p < 1 or p % 2 == 0):
            raise w.error('no (%d,2) torus knot: a knot needs p odd and >= 1 '
                          '(p even gives a link)' % p, 'p', t, i)
        if kind == 'link' and (p < 2 or p % 2 == 1):
            raise w.error('no (%d,2) torus link: a link needs p even and >= 2 '
                          '(p odd gives a knot)' % p, 'p', t, i)
    hands = f.get('hands', [1 if kind == 'knot' else -1])
    for h in _list(w, hands, 'hands', t, i):
        if h not in (1, -1) or isinstance(h, bool):
            raise w.error('a handedness is 1 (right) or -1 (left), got %r' % (h,), 'hands', t, i)
    length = f.get('length', KNOT_LTOT if kind == 'knot' else LINK_L)
    if not _is_num(length) or length <= 0:
        raise w.error('length must be a positive number', 'length', t, i)
    deltas = _deltas(w, f['deltas'], t, i) if 'deltas' in f else top['deltas']
    if deltas is None:
        raise w.error('no Delta values (deltas = [...] at the top or in the family)', 'kind', t, i)
    lim = contact_limit(kind, float(length))
    for d in deltas:
        if d >= lim:
            msg = ('Delta = %g is impossible for a %s of length %g: the braid does not fit inside '
                   'its axis '
                   '(Delta < %.4g needed)' % (d, kind, length, lim))
            raise w.error(msg, 'deltas', t, i) if 'deltas' in f else w.error(msg, 'deltas')
    modes = _modes(w, f['modes'], t, i) if 'modes' in f else top['modes']
    arms = _arms(w, f['arms'], t, i) if 'arms' in f else top['arms']
    return kind, ps, hands, float(length), deltas, modes, arms


def load(path):
    """Reads and checks a sweep file; returns a Sweep or raises SweepError."""
    try:
        with open(path, 'rb') as fh:
            raw = fh.read()
    except OSError as e:
        raise SweepError('%s: cannot read: %s' % (path, e.strerror)) from None
    text = raw.decode('utf-8', errors='replace')
    w = _Where(path, text)
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise SweepError('%s: not a TOML file: %s' % (path, e)) from None
    for k in doc:
        if k not in _TOP_KEYS:
            raise w.error('unknown key (a sweep has %s)' % ', '.join(_TOP_KEYS), k,
                          k if isinstance(doc[k], dict) else None)
    top = {'deltas': _deltas(w, doc['deltas']) if 'deltas' in doc else None,
           'modes': _modes(w, doc['modes']) if 'modes' in doc else [1],
           'arms': _arms(w, doc['arms']) if 'arms' in doc else ['knotting']}
    switch = doc.get('switch', 'sym')
    if switch not in SWITCHES:
        raise w.error('must be one of %s' % ', '.join('"%s"' % x for x in SWITCHES), 'switch')
    fams = doc.get('family')
    if not isinstance(fams, list) or not fams:
        raise SweepError('%s: family: no [[family]] table (each names a kind and its p)' % path)
    mesh = _mesh(w, doc.get('mesh'))
    flat = _constants(w, doc.get('flat'), 'flat', FLAT_DEFAULTS)
    branch = _constants(w, doc.get('branch'), 'branch', BRANCH_DEFAULTS)
    rec = doc.get('record', {})
    if not isinstance(rec, dict):
        raise w.error('must be a table', None, 'record')
    for k, v in rec.items():
        if k not in _RECORD_KEYS:
            raise w.error('unknown key (record has %s)' % ', '.join(_RECORD_KEYS), k, 'record')
        if not isinstance(v, bool):
            raise w.error('must be true or false', k, 'record')
    record = {'files': rec.get('files', True)}
    out = doc.get('output', os.path.splitext(os.path.basename(path))[0])
    if not isinstance(out, str) or not out:
        raise w.error('must be a directory name', 'output')
    output = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(path)), out))
    tasks, seen = [], set()
    for i, f in enumerate(fams):
        kind, ps, hands, length, deltas, modes, arms = _family(w, f, i, top)
        for p in ps:
            for h in hands:
                for d in deltas:
                    for a in arms:
                        sign = knotting_arm(kind, h) if a == 'knotting' else (1 if a == '+'
                                                                              else -1)
                        me = dict(mesh, NTST=auto_ntst(kind, p) if mesh['NTST'] == 'auto'
                                  else mesh['NTST'])
                        group = []
                        for m in modes:
                            ti = {'version': TASK_VERSION, 'kind': kind, 'p': p, 'hand': h,
                                  'Delta': d,
                                  'length': length, 'arm': sign, 'mode': m, 'mesh': me,
                                  'flat': flat,
                                  'branch': branch, 'files': record['files']}
                            if switch != 'sym':
                                ti['switch'] = switch
                            t = Task(ti)
                            if t.key not in seen:
                                seen.add(t.key)
                                tasks.append(t)
                                group.append(t)
                        # one flat branch for the group's modes, to its highest branch point
                        if group:
                            shared = FlatTask(flat_inputs(group[0].inputs, max(modes)))
                            for t in group:
                                t.flat = shared
    return Sweep(os.path.abspath(path), output, tasks, record)
